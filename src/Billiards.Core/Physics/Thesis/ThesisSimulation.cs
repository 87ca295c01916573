using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Scenes;

namespace Billiards.Core.Physics.Thesis;

/// <summary>The thesis model (to be implemented).</summary>
public sealed class ThesisSimulation(Scene scene)
    : Simulation(Models.Thesis, Integrators.Fixed, scene.Physics.Dt, scene.Table, scene.Balls.Select(b => b.Id).ToList())
{
    /// <inheritdoc />
    public override ReadOnlySpan<BallState> Balls => throw new NotImplementedException();

    /// <inheritdoc />
    public override bool IsAtRest => throw new NotImplementedException();

    /// <inheritdoc />
    public override void Step() => throw new NotImplementedException();

    /// <inheritdoc />
    public override void Reset() => throw new NotImplementedException();

    /// <inheritdoc />
    public override void Strike(ShotSpec shot) => throw new NotImplementedException();

    /// <inheritdoc />
    public override string FeatureName(EventKind kind, int feature) => throw new NotImplementedException();
}
