using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Physics;

/// <summary>A point of a ball's path: where the ball was (m) at a time of the shot (s after the strike).</summary>
/// <param name="Time">Seconds after the strike.</param>
/// <param name="Position">The ball's centre (m).</param>
public readonly record struct PathPoint(double Time, Vec3 Position);

/// <summary>Where a collision of the shot happened, to mark on its tracking lines.</summary>
/// <param name="Time">Seconds after the strike.</param>
/// <param name="Kind">A ball-ball or ball-cushion collision, or a pocket drop.</param>
/// <param name="Ball">The (first) ball.</param>
/// <param name="Position">The contact (m): the point between the two centres for two balls, the ball's centre otherwise.</param>
public readonly record struct PathMark(double Time, EventKind Kind, BallId Ball, Vec3 Position);

/// <summary>How the shot being replayed was run, which the replay must repeat to pass through the same states.</summary>
public enum ShotStepping
{
    /// <summary>One <see cref="Simulation.AdvanceTo"/> of one fixed step per tick: the game window's way.</summary>
    Ticks,

    /// <summary>Straight to rest (<c>Match.RunToRest</c>): a game record's and self-play's way.</summary>
    ToRest,
}

/// <summary>
/// A shot played again from its snapshot at the strike: not frames recorded while it ran, but the
/// shot itself, re-simulated the way it was run (<see cref="ShotStepping"/>), so it passes through
/// the same states bit for bit and ends where the shot ended. It can be shown at any time of the
/// shot, forwards and backwards. Run by ticks, it steps as the game does and going back restores
/// the nearest checkpoint (one every <see cref="CheckpointSeconds"/> of the shot) and steps on. Run
/// to rest with the event integrator, whose state would change if the run stopped on the way, the
/// first run takes its events one by one (<see cref="Simulation.AdvanceOneEvent"/>, the same turns
/// as the one call) and keeps checkpoints between them; a time is shown on a second simulation
/// restored from the checkpoint before it and advanced to it, which never feeds back into the run.
/// The first run gives the shot's length, its events and every ball's path (the tracking lines).
/// </summary>
public sealed class ShotReplay
{
    /// <summary>Seconds of the shot between two checkpoints (s): showing an earlier time re-simulates at most this much.</summary>
    public const double CheckpointSeconds = 0.25;

    /// <summary>Seconds between checkpoints of a shot run to rest (s): every time shown re-simulates at most this much.</summary>
    public const double EventCheckpointSeconds = 0.1;

    /// <summary>A shot run to rest is sampled this often for its paths (s).</summary>
    public const double PathSampleSeconds = 1.0 / 120;

    /// <summary>A path keeps a point where the ball turns by more than this (deg) since its last kept point.</summary>
    public const double PathTurnDegrees = 2;

    /// <summary>A path keeps a point at least this often (s), so a path drawn up to a time ends near the ball.</summary>
    public const double PathMaxGapSeconds = 0.1;

    private readonly Simulation _sim;
    private readonly Simulation _view;
    private readonly bool _byEvents;
    private readonly List<SimulationSnapshot> _checkpoints = [];
    private readonly BallState[] _previous;
    private readonly double _start;
    private double _previousTime;
    private readonly PathPoint[][] _paths;
    private readonly PathMark[] _marks;
    private readonly SimEvent[] _events;

    /// <summary>
    /// Makes the replay of the shot whose state at the strike is <paramref name="atStrike"/>, taken
    /// from <paramref name="shot"/> (or any simulation of the same table model and balls, which is
    /// not changed), and runs it once to rest (at most <paramref name="maxSeconds"/>) for its length,
    /// events and paths.
    /// </summary>
    /// <exception cref="ArgumentException">The snapshot is of another table model or other balls.</exception>
    /// <exception cref="NotSupportedException">The simulation keeps no snapshots.</exception>
    public ShotReplay(Simulation shot, SimulationSnapshot atStrike, double maxSeconds = 600, ShotStepping stepping = ShotStepping.Ticks)
        : this(Checked(shot).TableModel, shot.Ids, Positions(shot), shot.RefereeRules, atStrike, maxSeconds, stepping)
    {
    }

    /// <summary>
    /// Makes the replay from what a simulation of the shot is made of (its table model, balls and
    /// their places now, whether a referee rules), so that it can be made on another thread while
    /// that simulation goes on: the first run to rest takes as long as the shot's simulation did.
    /// </summary>
    /// <exception cref="ArgumentException">The snapshot is of another table model or other balls.</exception>
    public ShotReplay(TableModel model, IReadOnlyList<BallId> ids, IReadOnlyList<Vec3> positions, bool refereeRules, SimulationSnapshot atStrike, double maxSeconds = 600, ShotStepping stepping = ShotStepping.Ticks)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(ids);
        ArgumentNullException.ThrowIfNull(positions);
        ArgumentNullException.ThrowIfNull(atStrike);
        _sim = Clone(model, ids, positions, refereeRules);
        // The balls turn as they are drawn (orientation never feeds back into the motion).
        _sim.TrackOrientation = true;
        _sim.Restore(atStrike);
        _start = _sim.Time;
        _previous = _sim.Balls.ToArray();
        _previousTime = _start;
        double end = _start + maxSeconds;
        // The strike's own event is in the log already; the collisions after it are the shot's.
        int firstEvent = _sim.Events.Count;
        StrikeEvent = firstEvent > 0 && _sim.Events[firstEvent - 1] is { Kind: EventKind.CueStrike } strike ? strike : null;
        var paths = new List<PathPoint>[_sim.Ids.Count];
        for (int i = 0; i < paths.Length; i++)
        {
            paths[i] = [new PathPoint(0, _sim.Balls[i].Position)];
        }
        var marks = new List<PathMark>();
        int seen = firstEvent;
        _checkpoints.Add(_sim.CreateSnapshot());
        // A stepping integrator runs to rest by the same steps as by ticks: only events differ.
        bool? first = stepping == ShotStepping.ToRest ? _sim.AdvanceOneEvent(end) : null;
        _byEvents = first is not null;
        if (_byEvents)
        {
            double nextCheckpoint = _start + EventCheckpointSeconds;
            for (bool resolved = first == true; resolved; resolved = _sim.AdvanceOneEvent(end) == true)
            {
                // Resolved at its time: the event's balls are where it happened.
                for (; seen < _sim.Events.Count; seen++)
                {
                    Mark(_sim.Events[seen], marks, paths, exact: true);
                }
                if (_sim.Time >= nextCheckpoint)
                {
                    _checkpoints.Add(_sim.CreateSnapshot());
                    nextCheckpoint = _sim.Time + EventCheckpointSeconds;
                }
            }
            // The one call's end, as Match.RunToRest ends.
            _sim.AdvanceTo(end);
            for (; seen < _sim.Events.Count; seen++)
            {
                Mark(_sim.Events[seen], marks, paths, exact: true);
            }
            Duration = _sim.Time - _start;
            _view = Clone(model, ids, positions, refereeRules);
            _view.TrackOrientation = true;
            SamplePaths(paths);
        }
        else
        {
            _view = _sim;
            double nextCheckpoint = _start + CheckpointSeconds;
            while (!_sim.IsAtRest && _sim.Time < end)
            {
                _sim.Balls.CopyTo(_previous);
                _previousTime = _sim.Time;
                StepOnce();
                for (; seen < _sim.Events.Count; seen++)
                {
                    Mark(_sim.Events[seen], marks, paths, exact: false);
                }
                for (int i = 0; i < paths.Length; i++)
                {
                    Extend(paths[i], _previousTime - _start, _sim.Time - _start, _sim.Balls[i], _previous[i]);
                }
                if (_sim.Time >= nextCheckpoint)
                {
                    _checkpoints.Add(_sim.CreateSnapshot());
                    nextCheckpoint = _sim.Time + CheckpointSeconds;
                }
            }
            Duration = _sim.Time - _start;
        }
        for (int i = 0; i < paths.Length; i++)
        {
            var last = _sim.Balls[i];
            if (!last.IsOutOfPlay && paths[i][^1].Position != last.Position)
            {
                paths[i].Add(new PathPoint(Duration, last.Position));
            }
        }
        _paths = [.. paths.Select(p => p.ToArray())];
        _marks = [.. marks];
        _events = _sim.Events.AsSpan()[firstEvent..].ToArray();
        Final = _sim.Balls.ToArray();
        Seek(0);
    }

    private static Simulation Clone(TableModel model, IReadOnlyList<BallId> ids, IReadOnlyList<Vec3> positions, bool refereeRules)
    {
        var balls = new List<BallSetup>(ids.Count);
        for (int i = 0; i < ids.Count; i++)
        {
            // Any places do: the snapshot sets every ball.
            balls.Add(new BallSetup(ids[i], positions[i], Vec3.Zero, Vec3.Zero));
        }
        var sim = model.CreateSimulation(new Scene("replay", null, model.Table, model.Physics, null, balls, null, null));
        sim.RefereeRules = refereeRules;
        return sim;
    }

    /// <summary>The shot's length: from the strike until every ball rests (s).</summary>
    public double Duration { get; }

    /// <summary>The time of the shot shown now (s after the strike).</summary>
    public double Time { get; private set; }

    /// <summary>How the shot is re-simulated: by ticks, or (the event integrator run to rest) by its events.</summary>
    public ShotStepping Stepping => _byEvents ? ShotStepping.ToRest : ShotStepping.Ticks;

    /// <summary>The balls' ids, index-aligned with <see cref="Current"/>, <see cref="Previous"/> and <see cref="Paths"/>.</summary>
    public IReadOnlyList<BallId> Ids => _sim.Ids;

    /// <summary>Index of a ball in <see cref="Ids"/> (and <see cref="Current"/>), or -1.</summary>
    public int IndexOf(BallId id) => _sim.IndexOf(id);

    /// <summary>The ball radius (m).</summary>
    public double BallRadius => _sim.BallRadius;

    /// <summary>The balls at <see cref="Time"/> (run by ticks: at the first step at or after it).</summary>
    public ReadOnlySpan<BallState> Current => _view.Balls;

    /// <summary>The balls at the step before <see cref="Current"/>'s (the same when the time is a step's, and for a shot run by its events).</summary>
    public ReadOnlySpan<BallState> Previous => _previous;

    /// <summary>Where <see cref="Time"/> lies between <see cref="Previous"/> (0) and <see cref="Current"/> (1), for drawing.</summary>
    public double Alpha { get; private set; }

    /// <summary>The balls when the shot ended (the shot's own end, bit for bit).</summary>
    public IReadOnlyList<BallState> Final { get; }

    /// <summary>The shot's events after the strike, with their simulated times (s; <see cref="EventTime"/> gives them from the strike).</summary>
    public IReadOnlyList<SimEvent> Events => _events;

    /// <summary>Each ball's path over the whole shot (index-aligned with <see cref="Ids"/>), simplified where it runs straight.</summary>
    public IReadOnlyList<IReadOnlyList<PathPoint>> Paths => _paths;

    /// <summary>The shot's collisions and pocket drops, in order.</summary>
    public IReadOnlyList<PathMark> Marks => _marks;

    /// <summary>The strike's own event (the cue meeting the ball, at time 0 of the replay), or null when the snapshot's log holds none.</summary>
    public SimEvent? StrikeEvent { get; }

    /// <summary>The name of a cushion, jaw or pocket of the shot's table, as <see cref="Simulation.FeatureName"/> gives it.</summary>
    public string FeatureName(EventKind kind, int feature) => _sim.FeatureName(kind, feature);

    /// <summary>Seconds after the strike of <paramref name="e"/>.</summary>
    public double EventTime(SimEvent e) => e.Time - _start;

    /// <summary>
    /// Shows the shot at <paramref name="time"/> (s after the strike, clamped to the shot). By
    /// ticks, later times step on and earlier ones restore the checkpoint before them; by events,
    /// the view is restored from the checkpoint before the time and advanced to it.
    /// </summary>
    public void Seek(double time)
    {
        double t = Math.Clamp(time, 0, Duration);
        double at = _start + t;
        if (_byEvents)
        {
            _view.Restore(_checkpoints[CheckpointBefore(at)]);
            _view.AdvanceTo(at);
            _view.Balls.CopyTo(_previous);
            _previousTime = at;
            Alpha = 1;
            Time = t;
            return;
        }
        if (at < _previousTime)
        {
            _sim.Restore(_checkpoints[CheckpointBefore(at)]);
            _sim.Balls.CopyTo(_previous);
            _previousTime = _sim.Time;
        }
        while (_sim.Time < at && !_sim.IsAtRest)
        {
            _sim.Balls.CopyTo(_previous);
            _previousTime = _sim.Time;
            StepOnce();
        }
        if (_sim.Time <= at || _sim.Time <= _previousTime)
        {
            _sim.Balls.CopyTo(_previous);
            _previousTime = _sim.Time;
            Alpha = 1;
        }
        else
        {
            Alpha = Math.Clamp((at - _previousTime) / (_sim.Time - _previousTime), 0, 1);
        }
        Time = t;
    }

    /// <summary>The time (s after the strike) of the first collision or pocket drop after <paramref name="time"/>, or null when none is left.</summary>
    public double? NextEvent(double time)
    {
        foreach (var mark in _marks)
        {
            if (mark.Time > time + 1e-9)
            {
                return mark.Time;
            }
        }
        return null;
    }

    /// <summary>The time (s after the strike) of the last collision or pocket drop before <paramref name="time"/>, or null when none is.</summary>
    public double? PreviousEvent(double time)
    {
        double? found = null;
        foreach (var mark in _marks)
        {
            if (mark.Time < time - 1e-9)
            {
                found = mark.Time;
            }
        }
        return found;
    }

    /// <summary>The balls' places in <paramref name="simulation"/> now (m), in its order.</summary>
    public static Vec3[] Positions(Simulation simulation)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        var balls = simulation.Balls;
        var positions = new Vec3[balls.Length];
        for (int i = 0; i < balls.Length; i++)
        {
            positions[i] = balls[i].Position;
        }
        return positions;
    }

    private static Simulation Checked(Simulation shot)
    {
        ArgumentNullException.ThrowIfNull(shot);
        return shot;
    }

    // The game's own step: the window advances its shot one fixed step per tick just so.
    private void StepOnce() => _sim.AdvanceTo(_sim.Time + _sim.Dt);

    private int CheckpointBefore(double at)
    {
        int k = 0;
        for (int i = 0; i < _checkpoints.Count; i++)
        {
            if (_checkpoints[i].Time <= at)
            {
                k = i;
            }
        }
        return k;
    }

    // Where a ball was at an event inside the last step: on the line between the step's ends.
    private Vec3 At(int index, double eventTime)
    {
        double span = _sim.Time - _previousTime;
        double f = span > 0 ? Math.Clamp((eventTime - _previousTime) / span, 0, 1) : 1;
        var a = _previous[index].Position;
        return a + ((_sim.Balls[index].Position - a) * f);
    }

    private void Mark(in SimEvent e, List<PathMark> marks, List<PathPoint>[] paths, bool exact)
    {
        if (e.Kind is not (EventKind.BallBall or EventKind.BallCushion or EventKind.BallPocket))
        {
            return;
        }
        int a = _sim.IndexOf(e.A);
        if (a < 0)
        {
            return;
        }
        double t = e.Time - _start;
        var pa = exact ? _sim.Balls[a].Position : At(a, e.Time);
        var where = pa;
        // A path bends where its ball was struck: the collision is a point of it.
        paths[a].Add(new PathPoint(t, pa));
        if (e.Kind == EventKind.BallBall && _sim.IndexOf(e.B) is >= 0 and var b)
        {
            var pb = exact ? _sim.Balls[b].Position : At(b, e.Time);
            paths[b].Add(new PathPoint(t, pb));
            where = (pa + pb) * 0.5;
        }
        marks.Add(new PathMark(t, e.Kind, e.A, where));
    }

    // A shot run by its events has no steps to follow: its paths are sampled from the view, the
    // events' own points (already in the paths) merged in by time.
    private void SamplePaths(List<PathPoint>[] paths)
    {
        var sampled = new List<PathPoint>[paths.Length];
        for (int i = 0; i < paths.Length; i++)
        {
            sampled[i] = [paths[i][0]];
        }
        var before = new BallState[paths.Length];
        _view.Restore(_checkpoints[0]);
        _view.Balls.CopyTo(before);
        double beforeTime = 0;
        int steps = (int)Math.Ceiling(Duration / PathSampleSeconds);
        for (int k = 1; k <= steps; k++)
        {
            double t = Math.Min(Duration, k * PathSampleSeconds);
            _view.Restore(_checkpoints[CheckpointBefore(_start + t)]);
            _view.AdvanceTo(_start + t);
            var now = _view.Balls;
            for (int i = 0; i < paths.Length; i++)
            {
                Extend(sampled[i], beforeTime, t, now[i], before[i]);
            }
            now.CopyTo(before);
            beforeTime = t;
        }
        for (int i = 0; i < paths.Length; i++)
        {
            var merged = sampled[i].Concat(paths[i].Skip(1)).OrderBy(p => p.Time).ToList();
            paths[i].Clear();
            paths[i].AddRange(merged);
        }
    }

    // Keeps the step's point when the ball turned since the last kept point, or after a while.
    private static void Extend(List<PathPoint> path, double beforeTime, double time, in BallState now, in BallState before)
    {
        if (now.Position == before.Position || before.IsPocketed)
        {
            return;
        }
        var last = path[^1];
        var step = now.Position - before.Position;
        var run = before.Position - last.Position;
        bool turned = false;
        // A collision's point may lie inside the step: the turn is judged from points before it only.
        if (last.Time < beforeTime && run.Length > 1e-9 && step.Length > 1e-12)
        {
            double cos = Vec3.Dot(run, step) / (run.Length * step.Length);
            turned = cos < DeterministicMath.Cos(PathTurnDegrees * Math.PI / 180);
        }
        if (turned)
        {
            path.Add(new PathPoint(beforeTime, before.Position));
        }
        if (time - path[^1].Time >= PathMaxGapSeconds || now.IsPocketed)
        {
            path.Add(new PathPoint(time, now.Position));
        }
    }
}
