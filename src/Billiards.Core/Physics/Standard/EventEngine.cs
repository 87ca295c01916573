// Design of the standard model's engine (shared by the "exact" and "event" integrators).
//
// Between collisions every ball's centre is an exact quadratic in time within its motion state
// (BallMotion), so every future contact is a root of a polynomial. The engine keeps, in absolute
// time, the next event of every kind: per ball the end of its motion state and its first contact
// with a cushion face, jaw nose or pocket; per pair its first contact. AdvanceTo(t) repeatedly
// takes the earliest prediction not after t, advances the balls it involves exactly to it,
// resolves it, and re-predicts only what involves the balls that changed; finally it advances the
// moving balls to t. The "event" integrator jumps from event to event; the "exact" integrator
// calls AdvanceTo(t + dt) once per fixed step. Both run the same predictions in the same order,
// and they differ only in that "exact" re-bases the quadratics at step boundaries, so they agree to
// round-off at every dt, and no contact can be stepped over whatever dt is.
//
// The pipeline's parts, one job each (Events/):
//   - EventQueue: each ball's earliest prediction in an indexed binary min-heap; the total key
//     order (time, rank transition < rail < pair < refresh, ball indices) is the deterministic
//     tie order both integrators share;
//   - BroadPhase: a uniform grid of the balls' pair windows; only balls sharing a cell are solved;
//   - PairCache: the finite pair predictions, stored sparsely with both balls;
//   - ContactMemory: the TC model's last contact of each ball, for repeat contacts;
//   - Predictor: state ends, cushion contacts, pair windows and pair contacts, as polynomial roots;
//   - Resolver: the collision models applied to one contact, and its log entry.
// Balls are advanced lazily: each keeps the time its state refers to and is brought forward in
// closed form only when an event involves it, a prediction needs it, or a step ends (only the
// active balls then: resting and pocketed balls are never touched). A pair window ends at the
// state's end, and on large tables also after about one grid cell of travel, when a "refresh"
// (not an event, no state change) predicts that ball's pairs one window further.
using Billiards.Core.Balls;
using Billiards.Core.Physics.Standard.Events;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// The event engine of the standard model: exact closed-form motion, exact contact times,
/// contacts resolved in time order. See the design comment at the top of the file.
/// </summary>
public sealed class EventEngine
{
    /// <summary>Most events resolved at one instant before the engine gives up on that contact (frozen balls).</summary>
    public const int MaxEventsPerInstant = 64;

    /// <summary>
    /// Contact duration of the TC model (s). A ballistic contact cannot represent balls pushing
    /// each other (a sliding cue ball driving its object ball, a ball driven along a rail by its
    /// spin): resolved as inelastic collisions they chatter with ever smaller gaps and speeds
    /// (inelastic collapse, a Zeno point), and a contact met with no approach speed at all would
    /// be missed and the balls would overlap. Following McNamara and Luding (1998), a contact of the
    /// same two bodies again within this time is a repeat: it is resolved elastically (e = 1) in
    /// the normal direction and leaves at no less than <see cref="RepeatSeparationSpeed"/>.
    /// First contacts keep e_b and e_c exactly.
    /// </summary>
    public const double ContactDuration = 1e-3;

    /// <summary>
    /// Smallest normal separation speed after a repeat contact (m/s): pushing contacts then
    /// re-touch at most every few milliseconds. The energy this may add is at most m (5 mm/s)^2 / 4
    /// = 1.1e-6 J per repeat, and only ever in a pushing contact.
    /// </summary>
    public const double RepeatSeparationSpeed = 0.005;

    private readonly BallState[] _balls;
    private readonly int _n;
    private readonly MotionConstants _k;

    private readonly EventQueue _queue;
    private readonly BroadPhase _grid;
    private readonly PairCache _pairs;
    private readonly ContactMemory _contacts;
    private readonly Predictor _predictor;
    private readonly Resolver _resolver;

    // Per ball: the time its state refers to (balls are advanced lazily, when something needs them).
    private readonly double[] _baseTime;

    // Balls sliding, rolling or spinning, in no particular order.
    private readonly int[] _active;
    private readonly int[] _activePos;

    private double _lastEventTime = double.NaN;
    private int _eventsThisInstant;

    /// <summary>Creates an engine over the balls (shared, not copied: the engine changes them in place).</summary>
    /// <param name="balls">The balls' state, which the engine owns from now on.</param>
    /// <param name="ids">The balls' ids, for the event log.</param>
    /// <param name="model">The table, parameters and collision models (shared, immutable).</param>
    /// <param name="log">Where events are logged.</param>
    public EventEngine(BallState[] balls, IReadOnlyList<BallId> ids, StandardTableModel model, EventLog log)
    {
        _balls = balls;
        _n = balls.Length;
        Parameters = model.Parameters;
        _k = model.Constants;
        _queue = new EventQueue(_n);
        _grid = new BroadPhase(_n, model.Table, Parameters.R);
        _pairs = new PairCache(_n);
        _contacts = new ContactMemory(_n);
        _predictor = new Predictor(balls, model, _grid);
        _resolver = new Resolver(balls, [.. ids], model, _contacts, log);
        _baseTime = new double[_n];
        _active = new int[_n];
        _activePos = new int[_n];
        PredictAll();
    }

    /// <summary>Simulated time (s).</summary>
    public double Time { get; private set; }

    /// <summary>When true, orientations are integrated as the balls move.</summary>
    public bool TrackOrientation { get; set; }

    /// <summary>How often the per-instant event cap was hit.</summary>
    public int EventCapHits { get; private set; }

    /// <summary>Number of events resolved (transitions included).</summary>
    public long EventCount { get; private set; }

    /// <summary>Number of balls sliding, rolling or spinning.</summary>
    public int ActiveCount { get; private set; }

    /// <summary>True when no ball moves or spins.</summary>
    public bool IsAtRest => ActiveCount == 0;

    /// <summary>The model parameters.</summary>
    public PhysicsParams Parameters { get; }

    /// <summary>
    /// Starts over from the balls' current state (the caller has restored it) at t = 0: clears the
    /// clock, the counters and every prediction, and predicts anew. Allocates nothing.
    /// </summary>
    public void Restart()
    {
        Time = 0;
        EventCount = 0;
        EventCapHits = 0;
        _lastEventTime = double.NaN;
        _eventsThisInstant = 0;
        _contacts.Forget();
        PredictAll();
    }

    /// <summary>
    /// Takes over another engine's whole per-run state (clock, counters, predictions, queue, grid,
    /// pair cache, contact memory), not its balls: the caller copies those into this engine's
    /// array. Both engines must be over the same number of balls on the same table model.
    /// Allocates nothing once this engine's rows are as long as the other's.
    /// </summary>
    internal void CopyStateFrom(EventEngine other)
    {
        Time = other.Time;
        EventCount = other.EventCount;
        EventCapHits = other.EventCapHits;
        ActiveCount = other.ActiveCount;
        _lastEventTime = other._lastEventTime;
        _eventsThisInstant = other._eventsThisInstant;
        other._baseTime.CopyTo(_baseTime, 0);
        other._active.CopyTo(_active, 0);
        other._activePos.CopyTo(_activePos, 0);
        _queue.CopyFrom(other._queue);
        _grid.CopyFrom(other._grid);
        _pairs.CopyFrom(other._pairs);
        _contacts.CopyFrom(other._contacts);
        _predictor.CopyFrom(other._predictor);
    }

    /// <summary>
    /// Call after changing a ball's velocity or spin from outside (a cue strike): re-classifies
    /// its state and re-predicts everything that involves it.
    /// </summary>
    public void BallChanged(int index)
    {
        _baseTime[index] = Time;
        BallMotion.Classify(ref _balls[index], _k);
        Repredict(index);
        UpdateActive(index);
    }

    /// <summary>
    /// Advances to <paramref name="time"/>, resolving every event before or at it in time order.
    /// Stops early when everything comes to rest (at the time the last ball stops) unless
    /// <paramref name="stopAtRest"/> is false.
    /// </summary>
    public void AdvanceTo(double time, bool stopAtRest)
    {
        while (ActiveCount > 0)
        {
            int top = _queue.Top;
            if (_queue.TimeOf(top) > time)
            {
                break;
            }
            Process(top);
        }
        if (ActiveCount > 0 || !stopAtRest)
        {
            Time = time;
            SyncActive();
        }
    }

    /// <summary>
    /// One turn of <see cref="AdvanceTo"/>'s loop: resolves the earliest prediction when it falls at
    /// or before <paramref name="time"/> (s), and nothing more (no ball is brought to a time of its
    /// own), so that turns taken one by one and then <c>AdvanceTo(time, true)</c> end bit for bit as
    /// that one call alone. False when nothing moves or the next prediction is later.
    /// </summary>
    public bool ResolveNextBy(double time)
    {
        if (ActiveCount == 0)
        {
            return false;
        }
        int top = _queue.Top;
        if (_queue.TimeOf(top) > time)
        {
            return false;
        }
        Process(top);
        return true;
    }

    /// <summary>Moves the clock of a table at rest to <paramref name="time"/> (s); nothing else changes.</summary>
    public void IdleTo(double time)
    {
        if (ActiveCount == 0)
        {
            Time = time;
        }
    }

    /// <summary>
    /// Advances to the next event and resolves it (the event integrator's step). Does nothing at rest.
    /// </summary>
    public void StepToNextEvent()
    {
        if (ActiveCount == 0)
        {
            return;
        }
        while (double.IsFinite(_queue.TimeOf(_queue.Top)))
        {
            int top = _queue.Top;
            bool refresh = _queue.RankOf(top) == EventQueue.RankRefresh;
            Process(top);
            if (!refresh)
            {
                break;
            }
        }
        SyncActive();
    }

    // Resolves ball `top`'s earliest prediction, the earliest of all.
    private void Process(int top)
    {
        double t = _queue.TimeOf(top);
        if (t < Time)
        {
            t = Time; // a contact found "now" after round-off
        }
        Time = t;
        byte rank = _queue.RankOf(top);
        int a = _queue.AOf(top);
        int b = _queue.BOf(top);
        if (rank == EventQueue.RankRefresh)
        {
            // Not an event: the ball's pair look-ahead ran out; look further.
            RefreshPairs(a);
            return;
        }
        EventCount++;

        if (t == _lastEventTime)
        {
            if (++_eventsThisInstant > MaxEventsPerInstant)
            {
                // Frozen balls that keep re-colliding at one instant: drop this prediction; it
                // comes back when either ball next changes. Counted, so it is never silent.
                EventCapHits++;
                _eventsThisInstant = 0;
                Suppress(rank, a, b);
                return;
            }
        }
        else
        {
            _lastEventTime = t;
            _eventsThisInstant = 0;
        }

        switch (rank)
        {
            case EventQueue.RankTransition:
                Sync(a);
                if (_balls[a].State == MotionState.Airborne)
                {
                    _resolver.Land(a, Time);
                }
                else
                {
                    BallMotion.EndState(ref _balls[a], _k);
                }
                Repredict(a);
                UpdateActive(a);
                break;
            case EventQueue.RankPair:
                Sync(a);
                Sync(b);
                _resolver.Pair(a, b, Time);
                // Ball b's side is not predicted yet, so the pair itself waits for b's turn; ball a
                // is listed as active first, so that b, if it stopped, still finds it.
                Repredict(a, skip: b);
                UpdateActive(a);
                Repredict(b);
                UpdateActive(b);
                break;
            default:
                Sync(a);
                _resolver.Rail(a, _predictor.RailKindOf(a), _predictor.RailIndex(a), Time);
                Repredict(a);
                UpdateActive(a);
                break;
        }
    }

    private void Suppress(byte rank, int a, int b)
    {
        switch (rank)
        {
            case EventQueue.RankPair:
                _pairs.Remove(a, b);
                _pairs.Remove(b, a);
                UpdateKey(a);
                UpdateKey(b);
                break;
            case EventQueue.RankTransition:
                _predictor.DropTransition(a);
                RefreshPairs(a); // its pair window ended here
                break;
            default:
                _predictor.DropRail(a);
                RefreshPairs(a);
                break;
        }
    }

    // Brings a ball's state to the engine's time, in closed form.
    private void Sync(int i)
    {
        double dt = Time - _baseTime[i];
        if (dt > 0 && BallMotion.IsActive(_balls[i].State))
        {
            BallMotion.Advance(ref _balls[i], dt, _k, TrackOrientation, _predictor.Acceleration(i));
        }
        _baseTime[i] = Time;
    }

    // Brings every moving ball to the engine's time (resting balls need nothing).
    private void SyncActive()
    {
        for (int k = 0; k < ActiveCount; k++)
        {
            Sync(_active[k]);
        }
    }

    private void UpdateActive(int i)
    {
        bool active = BallMotion.IsActive(_balls[i].State);
        int pos = _activePos[i];
        if (active && pos < 0)
        {
            _activePos[i] = ActiveCount;
            _active[ActiveCount++] = i;
        }
        else if (!active && pos >= 0)
        {
            int last = _active[--ActiveCount];
            _active[pos] = last;
            _activePos[last] = pos;
            _activePos[i] = -1;
        }
    }

    private void PredictAll()
    {
        _grid.Clear();
        ActiveCount = 0;
        for (int i = 0; i < _n; i++)
        {
            _pairs.ClearRow(i);
            _baseTime[i] = Time;
            _activePos[i] = -1;
            BallMotion.Classify(ref _balls[i], _k);
            UpdateActive(i);
            _predictor.PredictBall(i, Time);
        }
        for (int i = 0; i < _n; i++)
        {
            foreach (int j in _grid.Candidates(i))
            {
                if (j > i) // Candidates may list i itself
                {
                    double t = PredictPair(i, j);
                    if (t < double.PositiveInfinity)
                    {
                        _pairs.Add(i, j, t);
                        _pairs.Add(j, i, t);
                    }
                }
            }
        }
        for (int i = 0; i < _n; i++)
        {
            ComputeKey(i);
        }
        _queue.Build();
    }

    // Everything that involves ball i, after its state changed (at the engine's time); the pair
    // with ball `skip` (if any) is left to that ball's own Repredict, which follows.
    private void Repredict(int i, int skip = -1)
    {
        Sync(i);
        ClearPairs(i);
        _predictor.PredictBall(i, Time);
        PredictPairsOf(i, skip);
        UpdateKey(i);
    }

    // The pair look-ahead of ball i ran out: predict its pairs a window further (state unchanged).
    private void RefreshPairs(int i)
    {
        Sync(i);
        ClearPairs(i);
        _predictor.PredictWindow(i, Math.Min(_predictor.TransitionTime(i), _predictor.RailTime(i)) - Time, Time);
        PredictPairsOf(i);
        UpdateKey(i);
    }

    private void PredictPairsOf(int i, int skip = -1)
    {
        // On a one-cell grid every ball is a candidate, but a ball that does not move can only be
        // met by one that does: then only the active balls need a look (every ball that moves is
        // active, the others would fail MayMeet anyway, and which balls are looked at in what
        // order changes no prediction).
        var partners = _grid.IsSingleCell && !BallMotion.Translates(_balls[i].State)
            ? _active.AsSpan(0, ActiveCount)
            : _grid.Candidates(i);
        foreach (int j in partners)
        {
            if (j == i || j == skip)
            {
                continue;
            }
            double t = i < j ? PredictPair(i, j) : PredictPair(j, i);
            if (t < double.PositiveInfinity)
            {
                _pairs.Add(i, j, t);
                _pairs.Add(j, i, t);
                int lo = Math.Min(i, j), hi = Math.Max(i, j);
                if (_queue.Precedes(t, EventQueue.RankPair, lo, hi, j))
                {
                    _queue.Set(j, t, EventQueue.RankPair, lo, hi);
                    _queue.Lowered(j);
                }
            }
        }
    }

    // Time of the first contact of balls i < j, or +infinity; syncs them only when they may meet.
    private double PredictPair(int i, int j)
    {
        if (!_predictor.MayMeet(i, j))
        {
            return double.PositiveInfinity;
        }
        Sync(i);
        Sync(j);
        return _predictor.PairContact(i, j, Time);
    }

    // Drops every pair prediction of ball i, re-keying the partners whose earliest event it was.
    private void ClearPairs(int i)
    {
        for (int p = 0; p < _pairs.Count(i); p++)
        {
            int j = _pairs.Partner(i, p);
            _pairs.Remove(j, i);
            if (_queue.RankOf(j) == EventQueue.RankPair && (_queue.AOf(j) == i || _queue.BOf(j) == i))
            {
                UpdateKey(j);
            }
        }
        _pairs.ClearRow(i);
    }

    // Ball i's earliest prediction, from scratch.
    private void ComputeKey(int i)
    {
        double t = _predictor.TransitionTime(i);
        byte rank = EventQueue.RankTransition;
        int a = i, b = 0;
        double rail = _predictor.RailTime(i);
        if (rail < t)
        {
            t = rail;
            rank = EventQueue.RankRail;
        }
        for (int p = 0; p < _pairs.Count(i); p++)
        {
            int j = _pairs.Partner(i, p);
            double at = _pairs.At(i, p);
            int lo = Math.Min(i, j), hi = Math.Max(i, j);
            if (EventQueue.Less(at, EventQueue.RankPair, lo, hi, t, rank, a, b))
            {
                t = at;
                rank = EventQueue.RankPair;
                a = lo;
                b = hi;
            }
        }
        double refresh = _predictor.RefreshTime(i);
        if (refresh < t)
        {
            t = refresh;
            rank = EventQueue.RankRefresh;
            a = i;
            b = 0;
        }
        _queue.Set(i, t, rank, a, b);
    }

    private void UpdateKey(int i)
    {
        ComputeKey(i);
        _queue.Update(i);
    }
}
