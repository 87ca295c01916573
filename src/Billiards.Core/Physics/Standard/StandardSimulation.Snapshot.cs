using Billiards.Core.Balls;

namespace Billiards.Core.Physics.Standard;

public sealed partial class StandardSimulation
{
    /// <inheritdoc />
    protected override SimulationSnapshot NewSnapshot() => new Snapshot(this);

    /// <inheritdoc />
    protected override void CaptureState(SimulationSnapshot snapshot)
    {
        var s = (Snapshot)snapshot;
        _balls.CopyTo(s.Balls, 0);
        _stepper.CaptureInto(s.Engine);
    }

    /// <inheritdoc />
    protected override void RestoreState(SimulationSnapshot snapshot)
    {
        var s = (Snapshot)snapshot;
        s.Balls.CopyTo(_balls, 0);
        _stepper.RestoreFrom(s.Engine);
    }

    // The balls, and what the integrator keeps beyond them (for the exact and event integrators an
    // engine that only holds state and is never stepped; nothing for Euler).
    private sealed class Snapshot : SimulationSnapshot
    {
        public Snapshot(StandardSimulation simulation)
            : base(simulation)
        {
            Balls = (BallState[])simulation._balls.Clone();
            Engine = simulation._stepper.NewStateHolder(Balls, simulation.Ids, simulation._model);
        }

        public BallState[] Balls { get; }

        public EventEngine? Engine { get; }
    }
}
