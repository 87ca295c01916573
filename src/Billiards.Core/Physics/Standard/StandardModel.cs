using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard;

/// <summary>The standard model as a plug-in of <see cref="ModelRegistry"/>.</summary>
public sealed class StandardModel : PhysicsModel
{
    /// <summary>The model's name in scene and result files.</summary>
    public const string ModelName = "standard";

    /// <inheritdoc />
    public override string Name => ModelName;

    /// <inheritdoc />
    public override IReadOnlyList<IIntegrator> Integrators { get; } = [new ExactIntegrator(), new EulerIntegrator(), new EventIntegrator()];

    /// <summary>The cushion and ball-ball resolvers of <see cref="ModelRegistry"/>.</summary>
    public override bool TakesInteractionModels => true;

    /// <inheritdoc />
    public override bool HasFlight => true;

    /// <inheritdoc />
    public override string DefaultTablePreset => "pool-9ft";

    /// <summary>The scene's R.</summary>
    public override double BallRadius(PhysicsParams parameters)
    {
        ArgumentNullException.ThrowIfNull(parameters);
        return parameters.R;
    }

    /// <summary>The limits of <see cref="RadiusLimits"/>: cushion contact height, pocket mouths and capture circles.</summary>
    public override string? RadiusProblem(TableSpec table, double radius) => RadiusLimits.Problem(table, radius);

    /// <inheritdoc />
    public override Simulation Create(Scene scene) => new StandardSimulation(scene);

    /// <summary>
    /// The cushion segments and jaw noses of <see cref="TableGeometry"/> as vertical faces from the
    /// bed up to the contact height; a nose as eight faces around its cylinder.
    /// </summary>
    public override IReadOnlyList<CollisionFace> CollisionFaces(TableSpec table, PhysicsParams parameters)
    {
        ArgumentNullException.ThrowIfNull(table);
        var geometry = TableGeometry.Build(table, BallRadius(parameters));
        var up = new Vec3(0, 0, table.CushionHeight);
        var list = new List<CollisionFace>();
        void Quad(Vec3 a, Vec3 b, Vec3 normal)
        {
            list.Add(new CollisionFace(a, b, b + up, normal));
            list.Add(new CollisionFace(a, b + up, a + up, normal));
        }
        foreach (var s in geometry.Segments)
        {
            Quad(s.Start, s.End, s.Normal);
        }
        const int Sides = 8;
        foreach (var nose in geometry.Noses)
        {
            for (int k = 0; k < Sides; k++)
            {
                double a0 = 2 * Math.PI * k / Sides, a1 = 2 * Math.PI * (k + 1) / Sides, mid = (a0 + a1) / 2;
                var p0 = nose.Centre + new Vec3(DeterministicMath.Cos(a0), DeterministicMath.Sin(a0), 0) * nose.Radius;
                var p1 = nose.Centre + new Vec3(DeterministicMath.Cos(a1), DeterministicMath.Sin(a1), 0) * nose.Radius;
                Quad(p0, p1, new Vec3(DeterministicMath.Cos(mid), DeterministicMath.Sin(mid), 0));
            }
        }
        return list;
    }
}
