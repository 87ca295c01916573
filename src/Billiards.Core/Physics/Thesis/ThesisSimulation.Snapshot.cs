namespace Billiards.Core.Physics.Thesis;

public sealed partial class ThesisSimulation
{
    /// <inheritdoc />
    protected override SimulationSnapshot NewSnapshot() => new Snapshot(this);

    /// <inheritdoc />
    protected override void CaptureState(SimulationSnapshot snapshot) => Engine.Save(((Snapshot)snapshot).Engine);

    /// <inheritdoc />
    protected override void RestoreState(SimulationSnapshot snapshot)
    {
        Engine.Load(((Snapshot)snapshot).Engine);
        _statesStale = true;
    }

    private sealed class Snapshot(ThesisSimulation simulation) : SimulationSnapshot(simulation)
    {
        public PhysicsEngine.State Engine { get; } = simulation.Engine.CreateState();
    }
}
