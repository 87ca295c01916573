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
/// <example>
/// A scene's simulation stepped by hand, as the game does one fixed step a frame
/// (<see cref="Scenes.SimulationRunner.Run"/> does the same to rest, bounded):
/// <code language="csharp">
/// Scene scene = SceneLoader.Load("assets/scenes/eight-ball-break.json");
/// Simulation sim = SimulationFactory.Create(scene);
/// sim.Strike(scene.Shot!);
/// while (!sim.IsAtRest &amp;&amp; sim.Time &lt; 60)
/// {
///     sim.Step();
/// }
/// for (int i = 0; i &lt; sim.Ids.Count; i++)
/// {
///     Console.WriteLine($"{sim.Ids[i]}: {sim.Balls[i].State} at {sim.Balls[i].Position}");
/// }
/// </code>
/// </example>
public abstract partial class Simulation
{
    /// <summary>Creates the common part of a simulation.</summary>
    /// <param name="model">The model's name as results write it (<see cref="PhysicsModel.Name"/>).</param>
    /// <param name="integrator">The integrator (one of the model's <see cref="PhysicsModel.Integrators"/>).</param>
    /// <param name="dt">Fixed step (s).</param>
    /// <param name="table">The table.</param>
    /// <param name="ids">Ids of the balls, in the order of <see cref="Balls"/>.</param>
    /// <param name="ballSet">The set the balls belong to; pool's when null.</param>
    protected Simulation(string model, IIntegrator integrator, double dt, TableSpec table, IReadOnlyList<BallId> ids, BallSet? ballSet = null)
    {
        BallSet = ballSet ?? BallSet.Pool;
        Model = model;
        Integrator = integrator;
        Dt = dt;
        Table = table;
        Ids = ids;
    }

    /// <summary>The model's name as results write it (<see cref="PhysicsModel.Name"/>).</summary>
    public string Model { get; }

    /// <summary>The integrator (one of the model's <see cref="PhysicsModel.Integrators"/>).</summary>
    public IIntegrator Integrator { get; }

    /// <summary>The resolver of each interaction, for the models that take them (the standard model), else null.</summary>
    public virtual Collisions.InteractionModels? Models => null;

    /// <summary>The fixed step (s).</summary>
    public double Dt { get; }

    /// <summary>The table being played on.</summary>
    public TableSpec Table { get; }

    /// <summary>Ball ids, index-aligned with <see cref="Balls"/>.</summary>
    public IReadOnlyList<BallId> Ids { get; }

    /// <summary>The set the balls belong to: which are cue balls, their names in files and their looks.</summary>
    public BallSet BallSet { get; }

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
    /// How many impacts an impulse-integrated model (the Mathavan models) cut short at its step
    /// limit; written to the result so that it is never silent (0 in every ordinary shot).
    /// </summary>
    public int TruncatedImpacts { get; protected set; }

    /// <summary>
    /// When true, ball orientations are integrated (for drawing). Off by default: a headless run
    /// computes nothing for rendering.
    /// </summary>
    public bool TrackOrientation { get; set; }

    /// <summary>
    /// True when a game's referee rules on this simulation's shots: a model with end-of-shot rules
    /// of its own (the thesis model respots a scratched cue ball and resets the rack after the 8)
    /// then leaves every ball where the shot left it. Models without such rules ignore it.
    /// </summary>
    public virtual bool RefereeRules { get; set; }

    /// <summary>The balls' state in SI units, index-aligned with <see cref="Ids"/>.</summary>
    public abstract ReadOnlySpan<BallState> Balls { get; }

    private BallState[] _atStrike = [];

    /// <summary>Every ball as it stood when the last shot was struck (index-aligned with <see cref="Ids"/>), empty before the first strike.</summary>
    public ReadOnlySpan<BallState> BallsAtStrike => _atStrike;

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
    /// Resolves the next event at or before <paramref name="time"/> (s) as one
    /// <see cref="AdvanceTo"/> to that time would on its way, and stops there without bringing the
    /// other balls to a time of their own: events taken one by one (a snapshot may be taken between
    /// them) and then <c>AdvanceTo(time)</c> end bit for bit as that one call alone would. True when
    /// an event was resolved, false when none is left before the time (or all rests), null for
    /// an integrator that takes fixed steps (its <see cref="AdvanceTo"/> is those steps anyway).
    /// </summary>
    public virtual bool? AdvanceOneEvent(double time) => null;

    /// <summary>
    /// Restores the scene's initial state (t = 0, before any shot): balls, time, step count and
    /// events. Allocates nothing, so a benchmark or a replay can rerun a shot.
    /// </summary>
    public abstract void Reset();

    /// <summary>Strikes the set's first cue ball (<see cref="Strike(ShotSpec, BallId)"/>): the one cue ball of pool or snooker.</summary>
    public void Strike(ShotSpec shot) => Strike(shot, BallSet.CueBalls[0]);

    /// <summary>
    /// Strikes <paramref name="cueBall"/> with the cue at the current time and opens a shot: logs a
    /// <see cref="EventKind.CueStrike"/> event (speed = the cue's speed), then applies the model's
    /// strike. Does nothing when that ball is not in play.
    /// </summary>
    public void Strike(ShotSpec shot, BallId cueBall)
    {
        ArgumentNullException.ThrowIfNull(shot);
        int cue = IndexOf(cueBall);
        if (cue < 0 || Balls[cue].IsOutOfPlay)
        {
            return;
        }
        // Kept for the referee (was the striker snookered?): one buffer, filled again each strike.
        if (_atStrike.Length != Balls.Length)
        {
            _atStrike = new BallState[Balls.Length];
        }
        Balls.CopyTo(_atStrike);
        Events.Add(new SimEvent(Time, EventKind.CueStrike, cueBall, cueBall, -1, shot.Speed));
        ApplyStrike(cue, shot);
    }

    private SimulationSnapshot? _probe;

    /// <summary>
    /// Every ball's position at <paramref name="time"/> (s), from <see cref="Time"/> up to one step
    /// beyond it, into <paramref name="into"/> (index-aligned with <see cref="Ids"/>); the
    /// simulation is left as it was. A model that can split a step (<see cref="StepBy"/>) advances a
    /// copy of its state exactly there; one that cannot interpolates between its own steps.
    /// </summary>
    public void PositionsAt(double time, Mathematics.Vec3[] into)
    {
        ArgumentNullException.ThrowIfNull(into);
        var balls = Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            into[i] = balls[i].Position;
        }
        if (time <= Time + 1e-12 || IsAtRest || !KeepsSnapshots)
        {
            return;
        }
        _probe ??= CreateSnapshot();
        Capture(_probe);
        double start = Time;
        if (!StepBy(time - Time))
        {
            Step();
            double f = Time > start ? Math.Clamp((time - start) / (Time - start), 0, 1) : 1;
            var after = Balls;
            for (int i = 0; i < after.Length; i++)
            {
                into[i] += (after[i].Position - into[i]) * f;
            }
            Restore(_probe);
            return;
        }
        var moved = Balls;
        for (int i = 0; i < moved.Length; i++)
        {
            into[i] = moved[i].Position;
        }
        Restore(_probe);
    }

    /// <summary>Advances by <paramref name="dt"/> exactly (a split step); false when the model cannot.</summary>
    protected virtual bool StepBy(double dt) => false;

    /// <summary>The model's cue strike on the ball at index <paramref name="cue"/>, which is in play.</summary>
    protected abstract void ApplyStrike(int cue, ShotSpec shot);

    /// <summary>Name of a cushion (or jaw) or pocket feature of an event, as results write it.</summary>
    public abstract string FeatureName(EventKind kind, int feature);

    /// <summary>
    /// The shared, immutable part of this simulation (table geometry, parameters, collision
    /// models): more simulations made from it run side by side and take each other's snapshots.
    /// Simulations that do not support snapshots (test doubles) throw <see cref="NotSupportedException"/>.
    /// </summary>
    public virtual TableModel TableModel => throw new NotSupportedException(Unsupported);

    /// <summary>True when the simulation keeps snapshots (<see cref="CreateSnapshot"/>, <see cref="Restore"/>): every model's does, test doubles may not.</summary>
    public virtual bool KeepsSnapshots => false;

    /// <summary>A new snapshot holding this simulation's current state (allocates; reuse it with <see cref="Capture"/>).</summary>
    public SimulationSnapshot CreateSnapshot()
    {
        var snapshot = NewSnapshot();
        Capture(snapshot);
        return snapshot;
    }

    /// <summary>Copies this simulation's whole dynamic state into <paramref name="snapshot"/>. Allocates nothing after the first capture into it.</summary>
    /// <exception cref="ArgumentException">The snapshot is of another table model or other balls.</exception>
    public void Capture(SimulationSnapshot snapshot)
    {
        Check(snapshot);
        snapshot.Time = Time;
        snapshot.StepCount = StepCount;
        snapshot.EventCapHits = EventCapHits;
        snapshot.TruncatedImpacts = TruncatedImpacts;
        snapshot.Events.CopyFrom(Events);
        CaptureState(snapshot);
    }

    /// <summary>
    /// Puts this simulation back in the state captured in <paramref name="snapshot"/>; it then runs
    /// on bit for bit as from the capture. Allocates nothing when the snapshot came from this
    /// simulation.
    /// </summary>
    /// <exception cref="ArgumentException">The snapshot is of another table model or other balls.</exception>
    public void Restore(SimulationSnapshot snapshot)
    {
        Check(snapshot);
        Time = snapshot.Time;
        StepCount = snapshot.StepCount;
        EventCapHits = snapshot.EventCapHits;
        TruncatedImpacts = snapshot.TruncatedImpacts;
        Events.CopyFrom(snapshot.Events);
        RestoreState(snapshot);
    }

    /// <summary>An empty snapshot of the model's own type, sized for this simulation.</summary>
    protected virtual SimulationSnapshot NewSnapshot() => throw new NotSupportedException(Unsupported);

    /// <summary>Copies the model's own state (balls included) into the snapshot.</summary>
    protected virtual void CaptureState(SimulationSnapshot snapshot) => throw new NotSupportedException(Unsupported);

    /// <summary>Restores the model's own state (balls included) from the snapshot.</summary>
    protected virtual void RestoreState(SimulationSnapshot snapshot) => throw new NotSupportedException(Unsupported);

    private const string Unsupported = "this simulation keeps no snapshots";

    private void Check(SimulationSnapshot snapshot)
    {
        if (!snapshot.Fits(this))
        {
            throw new ArgumentException("the snapshot was taken from a simulation of another table model or other balls", nameof(snapshot));
        }
    }

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
