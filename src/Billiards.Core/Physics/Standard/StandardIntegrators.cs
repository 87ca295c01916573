using Billiards.Core.Balls;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// What the standard simulation asks of its integrator while it runs: one step, an advance to a
/// time where the integrator can go there directly, restarts, outside changes and snapshots.
/// One implementation per integrator, so the simulation never asks which one it runs.
/// </summary>
internal interface IStepper
{
    /// <summary>True when no ball moves or spins.</summary>
    bool IsAtRest { get; }

    /// <summary>How often the per-instant event cap was hit.</summary>
    int EventCapHits { get; }

    /// <summary>True when the integrator never lets balls overlap (contacts found at their times, not by overlap).</summary>
    bool KeepsBallsApart { get; }

    /// <summary>One step from <paramref name="time"/> (s) with the fixed step <paramref name="dt"/> (s); returns the time after it.</summary>
    double Step(double time, double dt, bool trackOrientation);

    /// <summary>
    /// Advances straight to <paramref name="time"/> (s), or to the instant everything rests, when
    /// the integrator can; returns false (and does nothing) when it only takes steps.
    /// </summary>
    bool TryAdvanceTo(double time, bool trackOrientation, ref double now, ref long steps);

    /// <summary>
    /// Resolves the next event at or before <paramref name="time"/> (s) as <see cref="TryAdvanceTo"/>
    /// would on its way there, without ending at a time of its own; true when one was resolved,
    /// false when none is left, null when the integrator only takes steps.
    /// </summary>
    bool? AdvanceOneEvent(double time, bool trackOrientation, ref double now, ref long steps);

    /// <summary>Starts over at t = 0 from the balls' current (restored) state.</summary>
    void Restart();

    /// <summary>A ball's velocity or spin was changed from outside (a cue strike, a placement).</summary>
    void BallChanged(int index);

    /// <summary>A holder of the integrator's own state beyond the balls, for snapshots, or null when it keeps none.</summary>
    EventEngine? NewStateHolder(BallState[] snapshotBalls, IReadOnlyList<BallId> ids, StandardTableModel model);

    /// <summary>Copies the integrator's own state into a holder of <see cref="NewStateHolder"/>.</summary>
    void CaptureInto(EventEngine? holder);

    /// <summary>Takes the integrator's own state back from a holder of <see cref="NewStateHolder"/>.</summary>
    void RestoreFrom(EventEngine? holder);
}

/// <summary>An integrator of the standard model: a type that starts its stepper over a simulation's balls.</summary>
internal abstract class StandardIntegrator : IIntegrator
{
    /// <inheritdoc />
    public abstract string Name { get; }

    /// <inheritdoc />
    public virtual bool IsReference => false;

    /// <inheritdoc />
    public virtual bool ExactContacts => true;

    /// <inheritdoc />
    public virtual int Order => 0;

    /// <summary>The stepper over the balls (changed in place), logging to <paramref name="log"/>.</summary>
    public abstract IStepper Start(BallState[] balls, IReadOnlyList<BallId> ids, StandardTableModel model, EventLog log);

    /// <inheritdoc />
    public override string ToString() => Name;
}

/// <summary>"exact": fixed steps, each advanced by the event engine, so motion and contact times are exact inside the step.</summary>
internal sealed class ExactIntegrator : StandardIntegrator
{
    /// <inheritdoc />
    public override string Name => Scenes.Integrators.Exact;

    /// <inheritdoc />
    public override IStepper Start(BallState[] balls, IReadOnlyList<BallId> ids, StandardTableModel model, EventLog log) =>
        new FixedGridStepper(new EventEngine(balls, ids, model, log));

    private sealed class FixedGridStepper(EventEngine engine) : EngineStepper(engine)
    {
        public override double Step(double time, double dt, bool trackOrientation)
        {
            // Steps stay on the fixed grid, also while the table waits for the player.
            double end = time + dt;
            if (Engine.IsAtRest)
            {
                Engine.IdleTo(end);
                return end;
            }
            Engine.TrackOrientation = trackOrientation;
            Engine.AdvanceTo(end, stopAtRest: false);
            return end;
        }

        public override bool TryAdvanceTo(double time, bool trackOrientation, ref double now, ref long steps) => false;
    }
}

/// <summary>"event": the reference solver; each step jumps to the next event.</summary>
internal sealed class EventIntegrator : StandardIntegrator
{
    /// <inheritdoc />
    public override string Name => Scenes.Integrators.Event;

    /// <inheritdoc />
    public override bool IsReference => true;

    /// <inheritdoc />
    public override IStepper Start(BallState[] balls, IReadOnlyList<BallId> ids, StandardTableModel model, EventLog log) =>
        new NextEventStepper(new EventEngine(balls, ids, model, log));

    private sealed class NextEventStepper(EventEngine engine) : EngineStepper(engine)
    {
        public override double Step(double time, double dt, bool trackOrientation)
        {
            // At rest there is nothing to step to: the clock stays.
            if (Engine.IsAtRest)
            {
                return time;
            }
            Engine.TrackOrientation = trackOrientation;
            Engine.StepToNextEvent();
            return Engine.Time;
        }

        public override bool TryAdvanceTo(double time, bool trackOrientation, ref double now, ref long steps)
        {
            Engine.TrackOrientation = trackOrientation;
            long before = Engine.EventCount;
            Engine.AdvanceTo(Math.Max(time, now), stopAtRest: true);
            now = Engine.Time;
            steps += Engine.EventCount - before;
            return true;
        }

        public override bool? AdvanceOneEvent(double time, bool trackOrientation, ref double now, ref long steps)
        {
            Engine.TrackOrientation = trackOrientation;
            long before = Engine.EventCount;
            bool resolved = Engine.ResolveNextBy(Math.Max(time, now));
            now = Math.Max(now, Engine.Time);
            steps += Engine.EventCount - before;
            return resolved;
        }
    }
}

/// <summary>"euler": naive explicit stepping with overlap detection, the accuracy report's baseline.</summary>
internal sealed class EulerIntegrator : StandardIntegrator
{
    /// <inheritdoc />
    public override string Name => Scenes.Integrators.Euler;

    /// <inheritdoc />
    public override bool ExactContacts => false;

    /// <inheritdoc />
    public override int Order => 1;

    /// <inheritdoc />
    public override IStepper Start(BallState[] balls, IReadOnlyList<BallId> ids, StandardTableModel model, EventLog log) =>
        new Stepper(new EulerStepper(balls, ids, model, log));

    private sealed class Stepper(EulerStepper euler) : IStepper
    {
        public bool IsAtRest => euler.IsAtRest;

        public int EventCapHits => 0;

        public bool KeepsBallsApart => false;

        public double Step(double time, double dt, bool trackOrientation)
        {
            double end = time + dt;
            if (!euler.IsAtRest)
            {
                euler.TrackOrientation = trackOrientation;
                euler.Step(dt, end);
            }
            return end;
        }

        public bool TryAdvanceTo(double time, bool trackOrientation, ref double now, ref long steps) => false;

        public bool? AdvanceOneEvent(double time, bool trackOrientation, ref double now, ref long steps) => null;

        public void Restart() => euler.Restart();

        public void BallChanged(int index) => euler.BallChanged(index);

        // The Euler stepper keeps nothing but the balls.
        public EventEngine? NewStateHolder(BallState[] snapshotBalls, IReadOnlyList<BallId> ids, StandardTableModel model) => null;

        public void CaptureInto(EventEngine? holder)
        {
        }

        public void RestoreFrom(EventEngine? holder)
        {
        }
    }
}

/// <summary>The part of the exact and event steppers they share: one event engine.</summary>
internal abstract class EngineStepper(EventEngine engine) : IStepper
{
    protected EventEngine Engine { get; } = engine;

    public bool IsAtRest => Engine.IsAtRest;

    public int EventCapHits => Engine.EventCapHits;

    public bool KeepsBallsApart => true;

    public abstract double Step(double time, double dt, bool trackOrientation);

    public abstract bool TryAdvanceTo(double time, bool trackOrientation, ref double now, ref long steps);

    public virtual bool? AdvanceOneEvent(double time, bool trackOrientation, ref double now, ref long steps) => null;

    public void Restart() => Engine.Restart();

    public void BallChanged(int index) => Engine.BallChanged(index);

    // An engine over the snapshot's balls that only holds state (it is never stepped).
    public EventEngine? NewStateHolder(BallState[] snapshotBalls, IReadOnlyList<BallId> ids, StandardTableModel model) =>
        new(snapshotBalls, ids, model, new EventLog());

    public void CaptureInto(EventEngine? holder) => holder!.CopyStateFrom(Engine);

    public void RestoreFrom(EventEngine? holder) => Engine.CopyStateFrom(holder!);
}
