using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Table;

namespace Billiards.Core.Physics;

/// <summary>
/// A running simulation of one table: a model (<see cref="ModelRegistry"/>) with one integrator.
/// The caller owns the clock: it takes fixed steps (<see cref="Step"/>) or advances to a time
/// (<see cref="AdvanceTo"/>, which the event integrator reaches exactly). State is exposed in SI through
/// <see cref="Balls"/>, whatever units the model keeps inside.
/// </summary>
public abstract partial class Simulation
{
    /// <summary>Creates the common part of a simulation.</summary>
    /// <param name="model">The model's name as results write it (<see cref="PhysicsModel.Name"/>).</param>
    /// <param name="integrator">The integrator's name as results write it.</param>
    /// <param name="dt">Fixed step (s).</param>
    /// <param name="table">The table.</param>
    /// <param name="ids">Ids of the balls, in the order of <see cref="Balls"/>.</param>
    protected Simulation(string model, string integrator, double dt, TableSpec table, IReadOnlyList<BallId> ids)
    {
        Model = model;
        Integrator = integrator;
        Dt = dt;
        Table = table;
        Ids = ids;
    }

    /// <summary>The model's name as results write it (<see cref="PhysicsModel.Name"/>).</summary>
    public string Model { get; }

    /// <summary>The integrator: "fixed" (thesis), "exact", "euler" or "event".</summary>
    public string Integrator { get; }

    /// <summary>The fixed step (s).</summary>
    public double Dt { get; }

    /// <summary>The table being played on.</summary>
    public TableSpec Table { get; }

    /// <summary>Ball ids, index-aligned with <see cref="Balls"/>.</summary>
    public IReadOnlyList<BallId> Ids { get; }

    /// <summary>Simulated time since the start (s).</summary>
    public double Time { get; protected set; }

    /// <summary>Number of steps (or, for the event solver, of advances) taken.</summary>
    public long StepCount { get; protected set; }

    /// <summary>The events of the simulation so far.</summary>
    public EventLog Events { get; } = new();

    /// <summary>
    /// How often the cap on events at one instant stopped a pathological loop (frozen balls);
    /// written to the result so that it is never silent.
    /// </summary>
    public int EventCapHits { get; protected set; }

    /// <summary>
    /// When true, ball orientations are integrated (for drawing). Off by default: a headless run
    /// computes nothing for rendering.
    /// </summary>
    public bool TrackOrientation { get; set; }

    /// <summary>The balls' state in SI units, index-aligned with <see cref="Ids"/>.</summary>
    public abstract ReadOnlySpan<BallState> Balls { get; }

    /// <summary>True when no ball moves or spins (pocketed balls count as at rest).</summary>
    public abstract bool IsAtRest { get; }

    /// <summary>Advances by one fixed step of <see cref="Dt"/>.</summary>
    public abstract void Step();

    /// <summary>
    /// Advances until <see cref="Time"/> reaches <paramref name="time"/> or everything rests.
    /// Stepping integrators stop at the first step boundary at or after it.
    /// </summary>
    public virtual void AdvanceTo(double time)
    {
        while (Time < time - 1e-12 && !IsAtRest)
        {
            Step();
        }
    }

    /// <summary>
    /// Restores the scene's initial state (t = 0, before any shot): balls, time, step count and
    /// events. Allocates nothing, so a benchmark or a replay can rerun a shot.
    /// </summary>
    public abstract void Reset();

    /// <summary>
    /// Strikes the cue ball with the cue at the current time and opens a shot: logs a
    /// <see cref="EventKind.CueStrike"/> event (speed = the cue's speed), then applies the model's
    /// strike. Does nothing without a cue ball in play.
    /// </summary>
    public void Strike(ShotSpec shot)
    {
        int cue = IndexOf(BallId.Cue);
        if (cue < 0 || Balls[cue].IsPocketed)
        {
            return;
        }
        Events.Add(new SimEvent(Time, EventKind.CueStrike, BallId.Cue, BallId.Cue, -1, shot.Speed));
        ApplyStrike(cue, shot);
    }

    /// <summary>The model's cue strike on the ball at index <paramref name="cue"/>, which is in play.</summary>
    protected abstract void ApplyStrike(int cue, ShotSpec shot);

    /// <summary>Name of a cushion (or jaw) or pocket feature of an event, as results write it.</summary>
    public abstract string FeatureName(EventKind kind, int feature);

    /// <summary>Index of a ball in <see cref="Balls"/>, or -1.</summary>
    public int IndexOf(BallId id)
    {
        for (int i = 0; i < Ids.Count; i++)
        {
            if (Ids[i] == id)
            {
                return i;
            }
        }
        return -1;
    }
}
