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
        s.Engine?.CopyStateFrom(_engine!);
    }

    /// <inheritdoc />
    protected override void RestoreState(SimulationSnapshot snapshot)
    {
        var s = (Snapshot)snapshot;
        s.Balls.CopyTo(_balls, 0);
        _engine?.CopyStateFrom(s.Engine!);
    }

    // The balls, and for the exact and event integrators an engine that only holds state (it is
    // never stepped): the Euler stepper keeps nothing but the balls.
    private sealed class Snapshot : SimulationSnapshot
    {
        public Snapshot(StandardSimulation simulation)
            : base(simulation)
        {
            Balls = (BallState[])simulation._balls.Clone();
            if (simulation._engine is not null)
            {
                Engine = new EventEngine(Balls, simulation.Ids, simulation._model, new EventLog());
            }
        }

        public BallState[] Balls { get; }

        public EventEngine? Engine { get; }
    }
}
