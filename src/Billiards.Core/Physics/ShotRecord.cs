using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Table;

namespace Billiards.Core.Physics;

/// <summary>
/// One shot as rules, sound, the HUD and replays read it: the strike, the shot's events in time
/// order (from its <see cref="EventKind.CueStrike"/> on), and every ball as it rests afterwards.
/// Reusable: <see cref="Capture"/> refills the same buffers, so a search that judges thousands of
/// shots allocates only while the buffers grow.
/// </summary>
public sealed class ShotRecord
{
    private SimEvent[] _events = new SimEvent[64];
    private BallId[] _ids = [];
    private BallState[] _balls = [];
    private BallState[] _before = [];
    private PocketSet _pockets = PocketSet.None;

    /// <summary>The strike that opened the shot, or null for a shot without one (balls set moving by the scene).</summary>
    public ShotSpec? Shot { get; private set; }

    /// <summary>Simulated time of the strike (s).</summary>
    public double StartTime { get; private set; }

    /// <summary>Simulated time when the record was taken, normally when every ball rests (s).</summary>
    public double EndTime { get; private set; }

    /// <summary>The ball the shot's cue strike struck; without a strike, the set's first cue ball.</summary>
    public BallId CueBall { get; private set; }

    /// <summary>Number of events of the shot.</summary>
    public int EventCount { get; private set; }

    /// <summary>The shot's events in time order, starting with its cue strike when there is one.</summary>
    public ReadOnlySpan<SimEvent> Events => _events.AsSpan(0, EventCount);

    /// <summary>Ball ids, index-aligned with <see cref="BallsAfter"/>.</summary>
    public ReadOnlySpan<BallId> Ids => _ids;

    /// <summary>Every ball as it is after the shot (at <see cref="EndTime"/>), in SI.</summary>
    public ReadOnlySpan<BallState> BallsAfter => _balls;

    /// <summary>
    /// Every ball as it stood when the shot was struck, index-aligned with <see cref="Ids"/>; empty
    /// when the record does not know (a shot without a strike, a hand-made record without them).
    /// Snooker's referee reads from it whether the striker was snookered.
    /// </summary>
    public ReadOnlySpan<BallState> BallsBefore => _before;

    /// <summary>The balls in play after the shot as a layout (<see cref="BallLayout.InPlay"/>); with <paramref name="z"/>, every centre at that height.</summary>
    public BallLayout InPlayAfter(double? z = null) => BallLayout.InPlay(_balls, _ids, z);

    /// <summary>The balls in play when the shot was struck as a layout (empty when <see cref="BallsBefore"/> is); with <paramref name="z"/>, every centre at that height.</summary>
    public BallLayout InPlayBefore(double? z = null) => _before.Length == _ids.Length ? BallLayout.InPlay(_before, _ids, z) : BallLayout.Empty;

    /// <summary>
    /// Takes the shot from a simulation: its events from index <paramref name="firstEvent"/> (the
    /// shot's cue strike, when it has one) and its balls as they are now.
    /// </summary>
    /// <param name="simulation">The simulation, normally at rest after the shot.</param>
    /// <param name="firstEvent">Index in <see cref="Simulation.Events"/> of the shot's first event.</param>
    /// <param name="shot">The strike, or null.</param>
    public void Capture(Simulation simulation, int firstEvent, ShotSpec? shot)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        var events = simulation.Events.AsSpan();
        ArgumentOutOfRangeException.ThrowIfNegative(firstEvent);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(firstEvent, events.Length);
        var slice = events[firstEvent..];
        if (_events.Length < slice.Length)
        {
            _events = new SimEvent[Math.Max(slice.Length, _events.Length * 2)];
        }
        slice.CopyTo(_events);
        EventCount = slice.Length;
        var balls = simulation.Balls;
        if (_balls.Length != balls.Length)
        {
            _balls = new BallState[balls.Length];
            _ids = new BallId[balls.Length];
        }
        balls.CopyTo(_balls);
        var before = shot is null ? [] : simulation.BallsAtStrike;
        if (_before.Length != before.Length)
        {
            _before = new BallState[before.Length];
        }
        before.CopyTo(_before);
        for (int i = 0; i < _ids.Length; i++)
        {
            _ids[i] = simulation.Ids[i];
        }
        _pockets = simulation.Table.Pockets;
        // The struck ball is the shot's cue ball (carom's players strike different ones).
        CueBall = slice.Length > 0 && slice[0].Kind == EventKind.CueStrike ? slice[0].A : simulation.BallSet.CueBalls[0];
        Shot = shot;
        StartTime = slice.Length > 0 && slice[0].Kind == EventKind.CueStrike ? slice[0].Time : simulation.Time;
        EndTime = simulation.Time;
    }

    /// <summary>
    /// A record made from given events and balls rather than a simulation: for shots logged
    /// elsewhere and for hand-made cases.
    /// </summary>
    /// <param name="events">The shot's events in time order.</param>
    /// <param name="ids">Ball ids, index-aligned with <paramref name="ballsAfter"/>.</param>
    /// <param name="ballsAfter">Every ball after the shot, in SI.</param>
    /// <param name="shot">The strike, or null.</param>
    /// <param name="ballsBefore">Every ball when the shot was struck, index-aligned with <paramref name="ids"/>, or empty.</param>
    public static ShotRecord Of(ReadOnlySpan<SimEvent> events, IReadOnlyList<BallId> ids, ReadOnlySpan<BallState> ballsAfter, ShotSpec? shot = null, ReadOnlySpan<BallState> ballsBefore = default)
    {
        if (ballsBefore.Length != 0 && ballsBefore.Length != ids.Count)
        {
            throw new ArgumentException($"{ids.Count} ids for {ballsBefore.Length} balls before the shot", nameof(ballsBefore));
        }
        ArgumentNullException.ThrowIfNull(ids);
        if (ids.Count != ballsAfter.Length)
        {
            throw new ArgumentException($"{ids.Count} ids for {ballsAfter.Length} balls", nameof(ids));
        }
        var record = new ShotRecord { _events = events.ToArray(), _ids = [.. ids], _balls = ballsAfter.ToArray(), _before = ballsBefore.ToArray() };
        record.EventCount = events.Length;
        record.Shot = shot;
        record.StartTime = events.Length > 0 ? events[0].Time : 0;
        record.EndTime = events.Length > 0 ? events[^1].Time : 0;
        return record;
    }

    /// <summary>A new record of the shot that the simulation's last <see cref="EventKind.CueStrike"/> opened (or of all its events without one).</summary>
    public static ShotRecord LastShot(Simulation simulation, ShotSpec? shot)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        var events = simulation.Events.AsSpan();
        int first = 0;
        for (int i = events.Length - 1; i >= 0; i--)
        {
            if (events[i].Kind == EventKind.CueStrike)
            {
                first = i;
                break;
            }
        }
        var record = new ShotRecord();
        record.Capture(simulation, first, shot);
        return record;
    }

    /// <summary>Index of a ball in <see cref="BallsAfter"/>, or -1.</summary>
    public int IndexOf(BallId id) => Array.IndexOf(_ids, id);

    /// <summary>The ball's state after the shot; throws if the ball is not on this table.</summary>
    public ref readonly BallState After(BallId id)
    {
        int i = IndexOf(id);
        if (i < 0)
        {
            throw new ArgumentException($"ball {id} is not on this table", nameof(id));
        }
        return ref _balls[i];
    }

    /// <summary>True when the ball is on this table and in a pocket after the shot.</summary>
    public bool IsPocketedAfter(BallId id)
    {
        int i = IndexOf(id);
        return i >= 0 && _balls[i].IsPocketed;
    }

    /// <summary>The pocket of the table the ball fell into on this shot, or <see cref="PocketId.None"/>.</summary>
    public PocketId PocketedOnShot(BallId id)
    {
        foreach (ref readonly var e in Events)
        {
            if (e.Kind == EventKind.BallPocket && e.A == id)
            {
                return _pockets.Id(e.Feature);
            }
        }
        return PocketId.None;
    }

    /// <summary>
    /// The first ball the cue ball touched (the first ball-ball event involving it), or null when it
    /// touched none.
    /// </summary>
    public BallId? FirstContact
    {
        get
        {
            foreach (ref readonly var e in Events)
            {
                if (e.Kind == EventKind.BallBall && (e.A == CueBall || e.B == CueBall))
                {
                    return e.A == CueBall ? e.B : e.A;
                }
            }
            return null;
        }
    }

    /// <summary>Index in <see cref="Events"/> of the first contact's event, or -1.</summary>
    public int FirstContactIndex
    {
        get
        {
            var events = Events;
            for (int i = 0; i < events.Length; i++)
            {
                if (events[i].Kind == EventKind.BallBall && (events[i].A == CueBall || events[i].B == CueBall))
                {
                    return i;
                }
            }
            return -1;
        }
    }
}
