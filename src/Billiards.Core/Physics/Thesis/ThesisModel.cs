using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Thesis;

/// <summary>The thesis model as a plug-in of <see cref="ModelRegistry"/>.</summary>
public sealed class ThesisModel : PhysicsModel
{
    /// <summary>The model's name in scene and result files.</summary>
    public const string ModelName = "thesis";

    /// <inheritdoc />
    public override string Name => ModelName;

    /// <inheritdoc />
    public override IReadOnlyList<IIntegrator> Integrators { get; } = [new FixedIntegrator()];

    /// <summary>The seed's table.</summary>
    public override string DefaultTablePreset => "thesis";

    /// <summary>The seed's 2.86 cm whatever the scene's R: the model keeps its own constants.</summary>
    public override double BallRadius(PhysicsParams parameters) => ThesisConstants.RadiusMetres;

    /// <inheritdoc />
    public override Simulation Create(Scene scene) => new ThesisSimulation(scene);

    /// <summary>
    /// The collision triangles of <see cref="Initializer.InitRails"/>, offset a ball radius from
    /// the cushion faces as the seed's debug draw shows them, in SI.
    /// </summary>
    public override IReadOnlyList<CollisionFace> CollisionFaces(TableSpec table, PhysicsParams parameters) =>
        [.. Initializer.InitRails(table).Select(t => new CollisionFace(
            SeedFrame.ToSi(t.P1), SeedFrame.ToSi(t.P2), SeedFrame.ToSi(t.P3), SeedFrame.ToSi(t.Normal).Normalized()))];
}

/// <summary>"fixed": the thesis model's own fixed step with overlap detection (its only integrator).</summary>
internal sealed class FixedIntegrator : IIntegrator
{
    /// <inheritdoc />
    public string Name => Scenes.Integrators.Fixed;

    /// <inheritdoc />
    public bool IsReference => false;

    /// <inheritdoc />
    public bool ExactContacts => false;

    /// <summary>0: the thesis model's error is model error, which does not vanish with the step.</summary>
    public int Order => 0;

    /// <inheritdoc />
    public override string ToString() => Name;
}
