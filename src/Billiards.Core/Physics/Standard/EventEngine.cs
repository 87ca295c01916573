// Design of the standard model's engine (shared by the "exact" and "event" integrators).
//
// Between collisions every ball's centre is an exact quadratic in time within its motion state
// (BallMotion), so every future contact is a root of a polynomial: ball-ball a quartic in t
// (|d(t)|^2 = 4R^2 with d quadratic), ball-rail and ball-jaw face a quadratic (signed distance =
// R), ball-nose and ball-pocket a quartic (distance to a circle's centre). The engine therefore
// keeps, in absolute time, the next event of every kind:
//   - per ball: the end of its motion state (sliding -> rolling -> spinning -> stationary);
//   - per ball: its first contact with a cushion face, a jaw nose or a pocket's capture circle;
//   - per pair: its first contact.
// Each prediction only looks as far as the end of the current states of the balls involved (after
// that the polynomials change, and the transition re-predicts). AdvanceTo(t) repeatedly takes the
// earliest prediction not after t, advances all balls exactly to it, resolves it, and re-predicts
// only what involves the balls that changed; finally it advances everything to t.
//
// The "event" integrator calls this to jump from event to event; the "exact" integrator calls
// AdvanceTo(t + dt) once per fixed step. Both run the same predictions in the same order, and the
// only difference is that "exact" re-bases the quadratics at step boundaries, so they agree to
// round-off at every dt, and no contact can be stepped over whatever dt is.
//
// Cost (what keeps a step at what the scene needs):
//   - Balls are advanced lazily: each keeps the time its state refers to, and is brought forward
//     in closed form only when an event involves it, a prediction needs it, or a step ends (only
//     the active balls then: resting and pocketed balls are never touched).
//   - Each ball keeps its earliest prediction (time, then rank transition < rail < pair, then ball
//     indices: the deterministic tie order both integrators share) in an indexed binary min-heap,
//     so finding the next event is O(1) and a change costs O(log n). Finite pair predictions are
//     stored sparsely with both balls (no n x n matrix); when a ball changes, its pairs are dropped
//     and only the partners whose earliest event that was are re-keyed.
//   - Broad phase: a uniform grid in which each ball is listed under the cells of its pair window
//     box, the box around its path until the window ends; only balls sharing a cell are solved.
//     The window ends at the state's end, and on large tables (more than SmallTable balls) also
//     after about one cell of travel, when a "refresh" (rank after pairs, not an event, no state
//     change) predicts that ball's pairs one window further. Small tables use one cell.
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Physics.Roots;
using Billiards.Core.Table;

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

    // Longest look-ahead (s) when no friction would ever end a state.
    private const double MaxHorizon = 1e4;

    // How far a gap may already be below zero and still count as a new contact (m, or m^2 / (2R)
    // for squared gaps): a few ulps of table coordinates, far less than anything physical.
    private const double OverlapTolerance = 1e-9;

    // Up to this many balls the grid is one cell and pairs look ahead to the end of the states:
    // every pair is a candidate anyway, and refreshes would only add work.
    private const int SmallTable = 32;

    // Balls per grid cell aimed at on larger tables (the cell is also the look-ahead distance).
    private const double BallsPerCell = 2;

    // Shortest pair look-ahead (s), so that a refresh always moves the clock on.
    private const double MinWindow = 1e-6;

    // Tie order of simultaneous predictions: transitions, rails, pairs, then look-ahead refreshes
    // (which change no state), each in ball index order.
    private const byte RankTransition = 0;
    private const byte RankRail = 1;
    private const byte RankPair = 2;
    private const byte RankRefresh = 3;

    private enum Kind : byte { None, Transition, Segment, Nose, Pocket, Pair }

    private readonly BallState[] _balls;
    private readonly BallId[] _ids;
    private readonly int _n;
    private readonly PhysicsParams _params;
    private readonly MotionConstants _k;
    private readonly TableGeometry _geometry;
    private readonly IBallBallModel _ballBall;
    private readonly IBallCushionModel _ballCushion;
    private readonly EventLog _log;

    // Feature boxes (xmin, ymin, xmax, ymax) grown by R, for the broad phase.
    private readonly (double X0, double Y0, double X1, double Y1)[] _segmentBoxes;
    private readonly (double X0, double Y0, double X1, double Y1)[] _noseBoxes;
    private readonly (double X0, double Y0, double X1, double Y1)[] _pocketBoxes;

    // Per ball: the time its state refers to (balls are advanced lazily, when something needs them).
    private readonly double[] _baseTime;

    // Per ball predictions, in absolute time.
    private readonly double[] _transitionTime;
    private readonly double[] _railTime;
    private readonly Kind[] _railKind;
    private readonly int[] _railIndex;
    private readonly Vec3[] _accel;

    // The TC model's memory: each ball's last contact partner (a ball index, or _n + cushion
    // feature) and its time; and the parameters with elastic restitution for repeat contacts.
    private readonly int[] _lastPartner;
    private readonly double[] _lastContactTime;
    private readonly PhysicsParams _elastic;

    // Per ball pair look-ahead: pairs are predicted until _windowEnd (the state's end, or the
    // refresh time _refreshTime when the path is cut to about one grid cell); _windowBox bounds
    // the path until then.
    private readonly double[] _windowEnd;
    private readonly double[] _refreshTime;
    private readonly (double X0, double Y0, double X1, double Y1)[] _windowBox;

    // Finite pair predictions, stored with both balls: partner and absolute time.
    private readonly int[][] _pairPartner;
    private readonly double[][] _pairAt;
    private readonly int[] _pairCount;

    // Each ball's earliest prediction (time, rank, a, b), and a binary min-heap of the balls on it.
    private readonly double[] _keyTime;
    private readonly byte[] _keyRank;
    private readonly int[] _keyA;
    private readonly int[] _keyB;
    private readonly int[] _heap;
    private readonly int[] _heapPos;

    // Balls sliding, rolling or spinning, in no particular order.
    private readonly int[] _active;
    private readonly int[] _activePos;

    // Uniform grid over the table: each ball is listed in the cells its pair window box (grown by
    // R) touches; two balls can only meet if they share a cell.
    private readonly double _gridX0;
    private readonly double _gridY0;
    private readonly double _invCell;
    private readonly int _nx;
    private readonly int _ny;
    private readonly double _lookAhead;
    private readonly int[][] _cells;
    private readonly int[] _cellCount;
    private readonly (int X0, int Y0, int X1, int Y1)[] _cellRect;
    private readonly int[] _stamp;
    private readonly int[] _candidates;
    private int _stampValue;

    private double _lastEventTime = double.NaN;
    private int _eventsThisInstant;

    /// <summary>Creates an engine over the balls (shared, not copied: the engine changes them in place).</summary>
    /// <param name="balls">The balls' state, which the engine owns from now on.</param>
    /// <param name="ids">The balls' ids, for the event log.</param>
    /// <param name="parameters">Model parameters.</param>
    /// <param name="geometry">The table's collision geometry.</param>
    /// <param name="ballBall">Ball-ball collision model.</param>
    /// <param name="ballCushion">Ball-cushion collision model.</param>
    /// <param name="log">Where events are logged.</param>
    public EventEngine(BallState[] balls, IReadOnlyList<BallId> ids, PhysicsParams parameters, TableGeometry geometry,
        IBallBallModel ballBall, IBallCushionModel ballCushion, EventLog log)
    {
        _balls = balls;
        _n = balls.Length;
        _ids = [.. ids];
        _params = parameters;
        _k = new MotionConstants(parameters);
        _geometry = geometry;
        _ballBall = ballBall;
        _ballCushion = ballCushion;
        _log = log;

        double r = parameters.R;
        var segments = geometry.Segments;
        _segmentBoxes = new (double, double, double, double)[segments.Length];
        for (int s = 0; s < segments.Length; s++)
        {
            var g = segments[s];
            _segmentBoxes[s] = (Math.Min(g.Start.X, g.End.X) - r, Math.Min(g.Start.Y, g.End.Y) - r,
                Math.Max(g.Start.X, g.End.X) + r, Math.Max(g.Start.Y, g.End.Y) + r);
        }
        var noses = geometry.Noses;
        _noseBoxes = new (double, double, double, double)[noses.Length];
        for (int s = 0; s < noses.Length; s++)
        {
            double e = noses[s].Radius + r;
            _noseBoxes[s] = (noses[s].Centre.X - e, noses[s].Centre.Y - e, noses[s].Centre.X + e, noses[s].Centre.Y + e);
        }
        var pockets = geometry.Pockets;
        _pocketBoxes = new (double, double, double, double)[pockets.Length];
        for (int s = 0; s < pockets.Length; s++)
        {
            double e = pockets[s].Radius;
            _pocketBoxes[s] = (pockets[s].Centre.X - e, pockets[s].Centre.Y - e, pockets[s].Centre.X + e, pockets[s].Centre.Y + e);
        }

        _baseTime = new double[_n];
        _transitionTime = new double[_n];
        _railTime = new double[_n];
        _railKind = new Kind[_n];
        _railIndex = new int[_n];
        _accel = new Vec3[_n];
        _lastPartner = new int[_n];
        _lastContactTime = new double[_n];
        _elastic = parameters with { EB = 1, EC = 1 };
        ForgetContacts();
        _windowEnd = new double[_n];
        _refreshTime = new double[_n];
        _windowBox = new (double, double, double, double)[_n];
        _pairPartner = new int[_n][];
        _pairAt = new double[_n][];
        _pairCount = new int[_n];
        for (int i = 0; i < _n; i++)
        {
            _pairPartner[i] = new int[4];
            _pairAt[i] = new double[4];
        }
        _keyTime = new double[_n];
        _keyRank = new byte[_n];
        _keyA = new int[_n];
        _keyB = new int[_n];
        _heap = new int[_n];
        _heapPos = new int[_n];
        _active = new int[_n];
        _activePos = new int[_n];

        // The grid covers the bed and a margin for the pockets; anything outside lands in the
        // border cells (clamping keeps overlapping boxes in shared cells).
        double halfX = geometry.Spec.HalfLength + 0.25;
        double halfY = geometry.Spec.HalfWidth + 0.25;
        if (_n > SmallTable)
        {
            double cell = Math.Max(Math.Sqrt(4 * halfX * halfY * BallsPerCell / _n), 8 * r);
            _nx = Math.Max(1, (int)Math.Ceiling(2 * halfX / cell));
            _ny = Math.Max(1, (int)Math.Ceiling(2 * halfY / cell));
            _invCell = 1 / cell;
            _lookAhead = cell - 2 * r;
        }
        else
        {
            _nx = 1;
            _ny = 1;
            _invCell = 0;
            _lookAhead = double.PositiveInfinity;
        }
        _gridX0 = -halfX;
        _gridY0 = -halfY;
        _cells = new int[_nx * _ny][];
        for (int c = 0; c < _cells.Length; c++)
        {
            _cells[c] = new int[_n > SmallTable ? 8 : _n];
        }
        _cellCount = new int[_cells.Length];
        _cellRect = new (int, int, int, int)[_n];
        _stamp = new int[_n];
        _candidates = new int[_n];
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

    /// <summary>
    /// Time of the next event (s) among the current predictions, or +infinity when nothing will
    /// happen. On large tables pairs are only predicted a short way ahead, so a contact beyond that
    /// shows up later.
    /// </summary>
    public double NextEventTime
    {
        get
        {
            double best = double.PositiveInfinity;
            for (int i = 0; i < _n; i++)
            {
                best = Math.Min(best, Math.Min(_transitionTime[i], _railTime[i]));
                for (int p = 0; p < _pairCount[i]; p++)
                {
                    best = Math.Min(best, _pairAt[i][p]);
                }
            }
            return best;
        }
    }

    /// <summary>The model parameters.</summary>
    public PhysicsParams Parameters => _params;

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
        ForgetContacts();
        PredictAll();
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
            int top = _heap[0];
            if (_keyTime[top] > time)
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
        while (double.IsFinite(_keyTime[_heap[0]]))
        {
            int top = _heap[0];
            bool refresh = _keyRank[top] == RankRefresh;
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
        double t = _keyTime[top];
        if (t < Time)
        {
            t = Time; // a contact found "now" after round-off
        }
        Time = t;
        byte rank = _keyRank[top];
        int a = _keyA[top];
        int b = _keyB[top];
        if (rank == RankRefresh)
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
            case RankTransition:
                Sync(a);
                BallMotion.EndState(ref _balls[a], _k);
                Repredict(a);
                UpdateActive(a);
                break;
            case RankPair:
                ResolvePair(a, b);
                break;
            default:
                {
                    Sync(a);
                    int feature = _railIndex[a];
                    switch (_railKind[a])
                    {
                        case Kind.Segment:
                            {
                                var s = _geometry.Segments[feature];
                                ResolveCushion(a, s.Normal, s.Feature);
                                break;
                            }
                        case Kind.Nose:
                            {
                                var nose = _geometry.Noses[feature];
                                var normal = (_balls[a].Position - nose.Centre).XY.Normalized();
                                ResolveCushion(a, normal, nose.Feature);
                                break;
                            }
                        case Kind.Pocket:
                            Pocket(a, _geometry.Pockets[feature].Pocket);
                            break;
                    }
                    break;
                }
        }
    }

    private void Suppress(byte rank, int a, int b)
    {
        switch (rank)
        {
            case RankPair:
                RemovePair(a, b);
                RemovePair(b, a);
                UpdateKey(a);
                UpdateKey(b);
                break;
            case RankTransition:
                _transitionTime[a] = double.PositiveInfinity;
                RefreshPairs(a); // its pair window ended here
                break;
            default:
                _railTime[a] = double.PositiveInfinity;
                RefreshPairs(a);
                break;
        }
    }

    private void ResolvePair(int i, int j)
    {
        Sync(i);
        Sync(j);
        ref var a = ref _balls[i];
        ref var b = ref _balls[j];
        var n = (b.Position - a.Position).XY.Normalized();
        double approach = Vec3.Dot(a.Velocity - b.Velocity, n);
        bool repeat = IsRepeat(i, j) || IsRepeat(j, i);
        _ballBall.Resolve(ref a, ref b, repeat ? _elastic : _params);
        double separation = Vec3.Dot(b.Velocity - a.Velocity, n);
        if (repeat && separation < RepeatSeparationSpeed)
        {
            var push = n * (0.5 * (RepeatSeparationSpeed - separation));
            a.Velocity -= push;
            b.Velocity += push;
        }
        Remember(i, j);
        Remember(j, i);
        BallMotion.Classify(ref a, _k);
        BallMotion.Classify(ref b, _k);
        _log.Add(new SimEvent(Time, EventKind.BallBall, _ids[i], _ids[j], -1, approach));
        Repredict(i);
        Repredict(j);
        UpdateActive(i);
        UpdateActive(j);
    }

    private void ResolveCushion(int i, Vec3 normal, int feature)
    {
        ref var ball = ref _balls[i];
        double approach = -Vec3.Dot(ball.Velocity, normal);
        bool repeat = IsRepeat(i, _n + feature);
        _ballCushion.Resolve(ref ball, normal, _geometry.CushionHeight, repeat ? _elastic : _params);
        double separation = Vec3.Dot(ball.Velocity, normal);
        if (repeat && separation < RepeatSeparationSpeed)
        {
            ball.Velocity += normal * (RepeatSeparationSpeed - separation);
        }
        Remember(i, _n + feature);
        BallMotion.Classify(ref ball, _k);
        _log.Add(new SimEvent(Time, EventKind.BallCushion, _ids[i], _ids[i], feature, approach));
        Repredict(i);
        UpdateActive(i);
    }

    private bool IsRepeat(int ball, int partner) =>
        _lastPartner[ball] == partner && Time - _lastContactTime[ball] < ContactDuration;

    private void Remember(int ball, int partner)
    {
        _lastPartner[ball] = partner;
        _lastContactTime[ball] = Time;
    }

    private void ForgetContacts()
    {
        _lastPartner.AsSpan().Fill(-1);
        _lastContactTime.AsSpan().Fill(double.NegativeInfinity);
    }

    private void Pocket(int i, int pocket)
    {
        ref var ball = ref _balls[i];
        double dropSpeed = ball.Velocity.Length;
        ball.Velocity = Vec3.Zero;
        ball.Spin = Vec3.Zero;
        ball.State = MotionState.Pocketed;
        ball.Pocket = pocket;
        _log.Add(new SimEvent(Time, EventKind.BallPocket, _ids[i], _ids[i], pocket, dropSpeed));
        Repredict(i);
        UpdateActive(i);
    }

    // Brings a ball's state to the engine's time, in closed form.
    private void Sync(int i)
    {
        double dt = Time - _baseTime[i];
        if (dt > 0 && BallMotion.IsActive(_balls[i].State))
        {
            BallMotion.Advance(ref _balls[i], dt, _k, TrackOrientation, _accel[i]);
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
        Array.Clear(_cellCount);
        ActiveCount = 0;
        for (int i = 0; i < _n; i++)
        {
            _cellRect[i] = (-1, -1, -1, -1);
            _pairCount[i] = 0;
            _baseTime[i] = Time;
            _activePos[i] = -1;
            BallMotion.Classify(ref _balls[i], _k);
            UpdateActive(i);
            PredictBall(i);
        }
        for (int i = 0; i < _n; i++)
        {
            int count = Candidates(i);
            for (int c = 0; c < count; c++)
            {
                int j = _candidates[c];
                if (j > i)
                {
                    double t = PredictPair(i, j);
                    if (t < double.PositiveInfinity)
                    {
                        AddPair(i, j, t);
                        AddPair(j, i, t);
                    }
                }
            }
        }
        for (int i = 0; i < _n; i++)
        {
            ComputeKey(i);
            _heap[i] = i;
            _heapPos[i] = i;
        }
        for (int k = _n / 2 - 1; k >= 0; k--)
        {
            SiftDown(k);
        }
    }

    // Everything that involves ball i, after its state changed (at the engine's time).
    private void Repredict(int i)
    {
        Sync(i);
        ClearPairs(i);
        PredictBall(i);
        PredictPairsOf(i);
        UpdateKey(i);
    }

    // The pair look-ahead of ball i ran out: predict its pairs a window further (state unchanged).
    private void RefreshPairs(int i)
    {
        Sync(i);
        ClearPairs(i);
        PredictWindow(i, Math.Min(_transitionTime[i], _railTime[i]) - Time);
        PredictPairsOf(i);
        UpdateKey(i);
    }

    private void PredictPairsOf(int i)
    {
        int count = Candidates(i);
        for (int c = 0; c < count; c++)
        {
            int j = _candidates[c];
            double t = i < j ? PredictPair(i, j) : PredictPair(j, i);
            if (t < double.PositiveInfinity)
            {
                AddPair(i, j, t);
                AddPair(j, i, t);
                int lo = Math.Min(i, j), hi = Math.Max(i, j);
                if (Less(t, RankPair, lo, hi, _keyTime[j], _keyRank[j], _keyA[j], _keyB[j]))
                {
                    SetKey(j, t, RankPair, lo, hi);
                    SiftUp(_heapPos[j]);
                }
            }
        }
    }

    // State end, first rail / jaw / pocket contact and pair window of one ball (synced to Time).
    private void PredictBall(int i)
    {
        ref readonly var b = ref _balls[i];
        _railTime[i] = double.PositiveInfinity;
        _railKind[i] = Kind.None;
        if (!BallMotion.IsActive(b.State))
        {
            _transitionTime[i] = double.PositiveInfinity;
            _accel[i] = Vec3.Zero;
            PredictWindow(i, double.PositiveInfinity);
            return;
        }
        double duration = BallMotion.StateDuration(b, _k);
        _transitionTime[i] = Time + duration;
        var acc = BallMotion.Acceleration(b, _k);
        _accel[i] = acc;
        if (!BallMotion.Translates(b.State))
        {
            PredictWindow(i, duration);
            return;
        }

        double horizon = Math.Min(duration, MaxHorizon);
        var box = PathBox(b.Position, b.Velocity, acc, horizon);
        double r = _params.R;
        Span<double> c = stackalloc double[5];
        double best = double.PositiveInfinity;

        var segments = _geometry.Segments;
        for (int s = 0; s < segments.Length; s++)
        {
            if (!Overlaps(box, _segmentBoxes[s]))
            {
                continue;
            }
            var g = segments[s];
            // Signed distance of the centre from the face, less R: a quadratic.
            c[0] = Vec3.Dot(g.Normal, b.Position - g.Start) - r;
            c[1] = Vec3.Dot(g.Normal, b.Velocity);
            c[2] = 0.5 * Vec3.Dot(g.Normal, acc);
            double t = Polynomial.FirstEntry(c[..3], horizon, OverlapTolerance);
            if (t < best)
            {
                // The contact must fall on the face; past its ends the noses take over.
                var p = b.Position + b.Velocity * t + acc * (0.5 * t * t);
                double along = Vec3.Dot(p - g.Start, g.Direction);
                if (along >= 0 && along <= g.Length)
                {
                    best = t;
                    _railKind[i] = Kind.Segment;
                    _railIndex[i] = s;
                    // Nothing after the first contact matters: look no further than it.
                    horizon = t;
                    box = PathBox(b.Position, b.Velocity, acc, horizon);
                }
            }
        }
        var noses = _geometry.Noses;
        for (int s = 0; s < noses.Length; s++)
        {
            if (!Overlaps(box, _noseBoxes[s]))
            {
                continue;
            }
            double reach = r + noses[s].Radius;
            CircleGap(b.Position - noses[s].Centre, b.Velocity, acc, reach, c);
            double t = Polynomial.FirstEntry(c, horizon, 2 * reach * OverlapTolerance);
            if (t < best)
            {
                best = t;
                _railKind[i] = Kind.Nose;
                _railIndex[i] = s;
                horizon = t;
                box = PathBox(b.Position, b.Velocity, acc, horizon);
            }
        }
        var pockets = _geometry.Pockets;
        for (int s = 0; s < pockets.Length; s++)
        {
            if (!Overlaps(box, _pocketBoxes[s]))
            {
                continue;
            }
            CircleGap(b.Position - pockets[s].Centre, b.Velocity, acc, pockets[s].Radius, c);
            // Any centre inside the circle and going deeper is pocketed.
            double t = Polynomial.FirstEntry(c, horizon, double.PositiveInfinity);
            if (t < best)
            {
                best = t;
                _railKind[i] = Kind.Pocket;
                _railIndex[i] = s;
            }
        }
        _railTime[i] = Time + best;
        PredictWindow(i, Math.Min(duration, best));
    }

    // How far ahead ball i's pairs are predicted (until its state ends or it meets a cushion, after
    // which its path changes anyway, or on large tables until it has travelled about one grid
    // cell), the box around that path, and its grid cells. `remaining`: time to the first of the
    // state's end and the cushion (s).
    private void PredictWindow(int i, double remaining)
    {
        ref readonly var b = ref _balls[i];
        _refreshTime[i] = double.PositiveInfinity;
        _windowEnd[i] = Math.Min(_transitionTime[i], _railTime[i]);
        if (b.State == MotionState.Pocketed)
        {
            Unregister(i);
            return;
        }
        if (!BallMotion.Translates(b.State))
        {
            _windowBox[i] = (b.Position.X, b.Position.Y, b.Position.X, b.Position.Y);
            Register(i);
            return;
        }
        double horizon = Math.Min(remaining, MaxHorizon);
        var acc = _accel[i];
        if (_lookAhead < double.PositiveInfinity)
        {
            double reach = Math.Max(_lookAhead / Math.Max(b.Velocity.LengthXY, Math.Sqrt(_lookAhead * acc.LengthXY)), MinWindow);
            if (reach < horizon)
            {
                horizon = reach;
                _refreshTime[i] = Time + reach;
                _windowEnd[i] = _refreshTime[i];
            }
        }
        _windowBox[i] = PathBox(b.Position, b.Velocity, acc, horizon);
        Register(i);
    }

    // Time of the first contact of balls i < j, both synced to Time, or +infinity.
    private double PredictPair(int i, int j)
    {
        ref readonly var a = ref _balls[i];
        ref readonly var b = ref _balls[j];
        if (a.State == MotionState.Pocketed || b.State == MotionState.Pocketed
            || !(BallMotion.Translates(a.State) || BallMotion.Translates(b.State)))
        {
            return double.PositiveInfinity;
        }
        double r = _params.R;
        var ba = _windowBox[i];
        var bb = _windowBox[j];
        if (ba.X0 - bb.X1 > 2 * r || bb.X0 - ba.X1 > 2 * r || ba.Y0 - bb.Y1 > 2 * r || bb.Y0 - ba.Y1 > 2 * r)
        {
            return double.PositiveInfinity;
        }
        Sync(i);
        Sync(j);
        double horizon = Math.Min(Math.Min(_windowEnd[i], _windowEnd[j]) - Time, MaxHorizon);
        var d = b.Position - a.Position;
        var dv = b.Velocity - a.Velocity;
        var da = _accel[j] - _accel[i];
        if (ClearOf(d, dv, da, horizon, 2 * r))
        {
            return double.PositiveInfinity;
        }
        Span<double> c = stackalloc double[5];
        CircleGap(d, dv, da, 2 * r, c);
        double t = Polynomial.FirstEntry(c, horizon, 4 * r * OverlapTolerance);
        return Time + t;
    }

    private void AddPair(int i, int j, double t)
    {
        int count = _pairCount[i];
        if (count == _pairPartner[i].Length)
        {
            Array.Resize(ref _pairPartner[i], 2 * count);
            Array.Resize(ref _pairAt[i], 2 * count);
        }
        _pairPartner[i][count] = j;
        _pairAt[i][count] = t;
        _pairCount[i] = count + 1;
    }

    private void RemovePair(int i, int j)
    {
        var partners = _pairPartner[i];
        int count = _pairCount[i];
        for (int p = 0; p < count; p++)
        {
            if (partners[p] == j)
            {
                partners[p] = partners[count - 1];
                _pairAt[i][p] = _pairAt[i][count - 1];
                _pairCount[i] = count - 1;
                return;
            }
        }
    }

    // Drops every pair prediction of ball i, re-keying the partners whose earliest event it was.
    private void ClearPairs(int i)
    {
        var partners = _pairPartner[i];
        for (int p = 0; p < _pairCount[i]; p++)
        {
            int j = partners[p];
            RemovePair(j, i);
            if (_keyRank[j] == RankPair && (_keyA[j] == i || _keyB[j] == i))
            {
                UpdateKey(j);
            }
        }
        _pairCount[i] = 0;
    }

    // Balls whose grid cells ball i shares, into _candidates; returns their number.
    private int Candidates(int i)
    {
        var rect = _cellRect[i];
        if (rect.X0 < 0)
        {
            return 0;
        }
        if (++_stampValue == int.MaxValue)
        {
            Array.Clear(_stamp);
            _stampValue = 1;
        }
        _stamp[i] = _stampValue;
        int count = 0;
        for (int y = rect.Y0; y <= rect.Y1; y++)
        {
            for (int x = rect.X0; x <= rect.X1; x++)
            {
                int cell = y * _nx + x;
                var list = _cells[cell];
                for (int k = 0; k < _cellCount[cell]; k++)
                {
                    int j = list[k];
                    if (_stamp[j] != _stampValue)
                    {
                        _stamp[j] = _stampValue;
                        _candidates[count++] = j;
                    }
                }
            }
        }
        return count;
    }

    private void Register(int i)
    {
        double r = _params.R;
        var box = _windowBox[i];
        var rect = (CellOf(box.X0 - r - _gridX0, _nx), CellOf(box.Y0 - r - _gridY0, _ny),
            CellOf(box.X1 + r - _gridX0, _nx), CellOf(box.Y1 + r - _gridY0, _ny));
        if (rect == _cellRect[i])
        {
            return;
        }
        Unregister(i);
        _cellRect[i] = rect;
        for (int y = rect.Item2; y <= rect.Item4; y++)
        {
            for (int x = rect.Item1; x <= rect.Item3; x++)
            {
                int cell = y * _nx + x;
                int count = _cellCount[cell];
                if (count == _cells[cell].Length)
                {
                    Array.Resize(ref _cells[cell], 2 * count);
                }
                _cells[cell][count] = i;
                _cellCount[cell] = count + 1;
            }
        }
    }

    private void Unregister(int i)
    {
        var rect = _cellRect[i];
        if (rect.X0 < 0)
        {
            return;
        }
        for (int y = rect.Y0; y <= rect.Y1; y++)
        {
            for (int x = rect.X0; x <= rect.X1; x++)
            {
                int cell = y * _nx + x;
                var list = _cells[cell];
                int count = _cellCount[cell];
                for (int k = 0; k < count; k++)
                {
                    if (list[k] == i)
                    {
                        list[k] = list[count - 1];
                        _cellCount[cell] = count - 1;
                        break;
                    }
                }
            }
        }
        _cellRect[i] = (-1, -1, -1, -1);
    }

    private int CellOf(double offset, int cells)
    {
        double f = offset * _invCell;
        return f <= 0 ? 0 : f >= cells - 1 ? cells - 1 : (int)f;
    }

    // Ball i's earliest prediction, from scratch.
    private void ComputeKey(int i)
    {
        double t = _transitionTime[i];
        byte rank = RankTransition;
        int a = i, b = 0;
        if (_railTime[i] < t)
        {
            t = _railTime[i];
            rank = RankRail;
        }
        var partners = _pairPartner[i];
        var times = _pairAt[i];
        for (int p = 0; p < _pairCount[i]; p++)
        {
            int j = partners[p];
            int lo = Math.Min(i, j), hi = Math.Max(i, j);
            if (Less(times[p], RankPair, lo, hi, t, rank, a, b))
            {
                t = times[p];
                rank = RankPair;
                a = lo;
                b = hi;
            }
        }
        if (_refreshTime[i] < t)
        {
            t = _refreshTime[i];
            rank = RankRefresh;
            a = i;
            b = 0;
        }
        SetKey(i, t, rank, a, b);
    }

    private void SetKey(int i, double t, byte rank, int a, int b)
    {
        _keyTime[i] = t;
        _keyRank[i] = rank;
        _keyA[i] = a;
        _keyB[i] = b;
    }

    private void UpdateKey(int i)
    {
        ComputeKey(i);
        int pos = _heapPos[i];
        SiftUp(pos);
        SiftDown(_heapPos[i]);
    }

    private static bool Less(double t1, byte r1, int a1, int b1, double t2, byte r2, int a2, int b2) =>
        t1 != t2 ? t1 < t2 : r1 != r2 ? r1 < r2 : a1 != a2 ? a1 < a2 : b1 < b2;

    private bool Before(int x, int y) =>
        Less(_keyTime[x], _keyRank[x], _keyA[x], _keyB[x], _keyTime[y], _keyRank[y], _keyA[y], _keyB[y]);

    private void SiftUp(int pos)
    {
        int ball = _heap[pos];
        while (pos > 0)
        {
            int parent = (pos - 1) >> 1;
            int other = _heap[parent];
            if (!Before(ball, other))
            {
                break;
            }
            _heap[pos] = other;
            _heapPos[other] = pos;
            pos = parent;
        }
        _heap[pos] = ball;
        _heapPos[ball] = pos;
    }

    private void SiftDown(int pos)
    {
        int ball = _heap[pos];
        while (true)
        {
            int child = 2 * pos + 1;
            if (child >= _n)
            {
                break;
            }
            if (child + 1 < _n && Before(_heap[child + 1], _heap[child]))
            {
                child++;
            }
            int other = _heap[child];
            if (!Before(other, ball))
            {
                break;
            }
            _heap[pos] = other;
            _heapPos[other] = pos;
            pos = child;
        }
        _heap[pos] = ball;
        _heapPos[ball] = pos;
    }

    // True when d + v t + a t^2 / 2 provably stays longer than reach on [0, t] (bed plane): its
    // length is at least |d + v t| - |a| t^2 / 2, and the first term's minimum is a point-segment
    // distance. Sharper than the boxes (it knows both balls' timing), and far cheaper than the
    // quartic it saves; the margin keeps touching pairs for the root finder.
    private static bool ClearOf(Vec3 d, Vec3 v, Vec3 a, double t, double reach)
    {
        double vv = v.X * v.X + v.Y * v.Y;
        double s = vv > 0 ? Math.Clamp(-(d.X * v.X + d.Y * v.Y) / vv, 0, t) : 0;
        double x = d.X + v.X * s, y = d.Y + v.Y * s;
        double drift = 0.5 * Math.Sqrt(a.X * a.X + a.Y * a.Y) * t * t;
        double clear = reach * (1 + 1e-9) + drift;
        return x * x + y * y > clear * clear;
    }

    // |d + v t + a t^2 / 2|^2 - reach^2 as ascending coefficients (bed plane only).
    private static void CircleGap(Vec3 d, Vec3 v, Vec3 a, double reach, Span<double> c)
    {
        var h = a.XY * 0.5;
        var dv = v.XY;
        var dd = d.XY;
        c[4] = Vec3.Dot(h, h);
        c[3] = 2 * Vec3.Dot(h, dv);
        c[2] = Vec3.Dot(dv, dv) + 2 * Vec3.Dot(h, dd);
        c[1] = 2 * Vec3.Dot(dv, dd);
        c[0] = Vec3.Dot(dd, dd) - reach * reach;
    }

    // Exact bounding box of r0 + v t + a t^2 / 2 on [0, T]: each coordinate is extreme at an end
    // or at its vertex.
    private static (double, double, double, double) PathBox(Vec3 r0, Vec3 v, Vec3 a, double t)
    {
        var (x0, x1) = Range(r0.X, v.X, a.X, t);
        var (y0, y1) = Range(r0.Y, v.Y, a.Y, t);
        return (x0, y0, x1, y1);
    }

    private static (double Min, double Max) Range(double p, double v, double a, double t)
    {
        double end = p + v * t + 0.5 * a * t * t;
        double min = Math.Min(p, end);
        double max = Math.Max(p, end);
        if (a != 0)
        {
            double tv = -v / a;
            if (tv > 0 && tv < t)
            {
                double vertex = p + 0.5 * v * tv;
                min = Math.Min(min, vertex);
                max = Math.Max(max, vertex);
            }
        }
        return (min, max);
    }

    private static bool Overlaps((double X0, double Y0, double X1, double Y1) a, (double X0, double Y0, double X1, double Y1) b) =>
        a.X0 <= b.X1 && b.X0 <= a.X1 && a.Y0 <= b.Y1 && b.Y0 <= a.Y1;
}
