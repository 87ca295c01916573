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
// Cost: a step without events only advances the active balls in closed form; predictions are made
// once per change of a ball, not per step, and an axis-aligned box around each ball's path until
// its state ends is a broad phase that keeps far pairs and far cushions from the root solver.
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

    // Predictions, in absolute time.
    private readonly double[] _transitionTime;
    private readonly double[] _railTime;
    private readonly Kind[] _railKind;
    private readonly int[] _railIndex;
    private readonly double[] _pairTime; // [i * n + j], i < j
    private readonly (double X0, double Y0, double X1, double Y1)[] _pathBox;
    private readonly Vec3[] _accel;

    // The TC model's memory: each ball's last contact partner (a ball index, or _n + cushion
    // feature) and its time; and the parameters with elastic restitution for repeat contacts.
    private readonly int[] _lastPartner;
    private readonly double[] _lastContactTime;
    private readonly PhysicsParams _elastic;

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

        _transitionTime = new double[_n];
        _railTime = new double[_n];
        _railKind = new Kind[_n];
        _railIndex = new int[_n];
        _pairTime = new double[_n * _n];
        _pathBox = new (double, double, double, double)[_n];
        _accel = new Vec3[_n];
        _lastPartner = new int[_n];
        _lastContactTime = new double[_n];
        _elastic = parameters with { EB = 1, EC = 1 };
        ForgetContacts();
        _pairTime.AsSpan().Fill(double.PositiveInfinity);
        for (int i = 0; i < _n; i++)
        {
            BallMotion.Classify(ref _balls[i], _k);
        }
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

    /// <summary>Time of the next event (s), or +infinity when nothing will happen.</summary>
    public double NextEventTime => FindNext(out _, out _, out _);

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
        _pairTime.AsSpan().Fill(double.PositiveInfinity);
        for (int i = 0; i < _n; i++)
        {
            BallMotion.Classify(ref _balls[i], _k);
        }
        PredictAll();
    }

    /// <summary>
    /// Call after changing a ball's velocity or spin from outside (a cue strike): re-classifies
    /// its state and re-predicts everything that involves it.
    /// </summary>
    public void BallChanged(int index)
    {
        BallMotion.Classify(ref _balls[index], _k);
        Repredict(index);
        CountActive();
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
            double t = FindNext(out var kind, out int a, out int b);
            if (t > time)
            {
                break;
            }
            Process(t, kind, a, b);
        }
        if (ActiveCount > 0 || !stopAtRest)
        {
            AdvanceAll(time - Time);
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
        double t = FindNext(out var kind, out int a, out int b);
        if (double.IsFinite(t))
        {
            Process(t, kind, a, b);
        }
    }

    private void Process(double t, Kind kind, int a, int b)
    {
        if (t < Time)
        {
            t = Time; // a contact found "now" after round-off
        }
        AdvanceAll(t - Time);
        Time = t;
        EventCount++;

        if (t == _lastEventTime)
        {
            if (++_eventsThisInstant > MaxEventsPerInstant)
            {
                // Frozen balls that keep re-colliding at one instant: drop this prediction; it
                // comes back when either ball next changes. Counted, so it is never silent.
                EventCapHits++;
                _eventsThisInstant = 0;
                Suppress(kind, a, b);
                return;
            }
        }
        else
        {
            _lastEventTime = t;
            _eventsThisInstant = 0;
        }

        switch (kind)
        {
            case Kind.Transition:
                BallMotion.EndState(ref _balls[a], _k);
                Repredict(a);
                break;
            case Kind.Pair:
                ResolvePair(a, b);
                break;
            case Kind.Segment:
                {
                    var s = _geometry.Segments[b];
                    ResolveCushion(a, s.Normal, s.Feature);
                    break;
                }
            case Kind.Nose:
                {
                    var nose = _geometry.Noses[b];
                    var normal = (_balls[a].Position - nose.Centre).XY.Normalized();
                    ResolveCushion(a, normal, nose.Feature);
                    break;
                }
            case Kind.Pocket:
                Pocket(a, _geometry.Pockets[b].Pocket);
                break;
        }
        CountActive();
    }

    private void Suppress(Kind kind, int a, int b)
    {
        switch (kind)
        {
            case Kind.Pair:
                _pairTime[a * _n + b] = double.PositiveInfinity;
                break;
            case Kind.Transition:
                _transitionTime[a] = double.PositiveInfinity;
                break;
            default:
                _railTime[a] = double.PositiveInfinity;
                break;
        }
    }

    private void ResolvePair(int i, int j)
    {
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
        ball.Velocity = Vec3.Zero;
        ball.Spin = Vec3.Zero;
        ball.State = MotionState.Pocketed;
        ball.Pocket = pocket;
        _log.Add(new SimEvent(Time, EventKind.BallPocket, _ids[i], _ids[i], pocket, 0));
        Repredict(i);
    }

    private void AdvanceAll(double dt)
    {
        if (dt <= 0 || ActiveCount == 0)
        {
            return;
        }
        bool track = TrackOrientation;
        for (int i = 0; i < _n; i++)
        {
            if (BallMotion.IsActive(_balls[i].State))
            {
                BallMotion.Advance(ref _balls[i], dt, _k, track);
            }
        }
    }

    private void CountActive()
    {
        int count = 0;
        for (int i = 0; i < _n; i++)
        {
            if (BallMotion.IsActive(_balls[i].State))
            {
                count++;
            }
        }
        ActiveCount = count;
    }

    // The earliest prediction; ties go to transitions, then rails, then pairs, each in index order,
    // so that both integrators resolve simultaneous events in the same order.
    private double FindNext(out Kind kind, out int a, out int b)
    {
        double best = double.PositiveInfinity;
        kind = Kind.None;
        a = -1;
        b = -1;
        for (int i = 0; i < _n; i++)
        {
            if (_transitionTime[i] < best)
            {
                best = _transitionTime[i];
                kind = Kind.Transition;
                a = i;
            }
        }
        for (int i = 0; i < _n; i++)
        {
            if (_railTime[i] < best)
            {
                best = _railTime[i];
                kind = _railKind[i];
                a = i;
                b = _railIndex[i];
            }
        }
        for (int i = 0; i < _n; i++)
        {
            int row = i * _n;
            for (int j = i + 1; j < _n; j++)
            {
                if (_pairTime[row + j] < best)
                {
                    best = _pairTime[row + j];
                    kind = Kind.Pair;
                    a = i;
                    b = j;
                }
            }
        }
        return best;
    }

    private void PredictAll()
    {
        for (int i = 0; i < _n; i++)
        {
            PredictBall(i);
        }
        for (int i = 0; i < _n; i++)
        {
            for (int j = i + 1; j < _n; j++)
            {
                PredictPair(i, j);
            }
        }
        CountActive();
    }

    private void Repredict(int i)
    {
        PredictBall(i);
        for (int j = 0; j < _n; j++)
        {
            if (j != i)
            {
                PredictPair(Math.Min(i, j), Math.Max(i, j));
            }
        }
    }

    // State end, path box and first rail / jaw / pocket contact of one ball.
    private void PredictBall(int i)
    {
        ref readonly var b = ref _balls[i];
        _railTime[i] = double.PositiveInfinity;
        _railKind[i] = Kind.None;
        if (!BallMotion.IsActive(b.State))
        {
            _transitionTime[i] = double.PositiveInfinity;
            _accel[i] = Vec3.Zero;
            _pathBox[i] = (b.Position.X, b.Position.Y, b.Position.X, b.Position.Y);
            return;
        }
        double duration = BallMotion.StateDuration(b, _k);
        _transitionTime[i] = Time + duration;
        var acc = BallMotion.Acceleration(b, _k);
        _accel[i] = acc;
        double horizon = Math.Min(duration, MaxHorizon);
        _pathBox[i] = PathBox(b.Position, b.Velocity, acc, horizon);
        if (!BallMotion.Translates(b.State))
        {
            return;
        }

        var box = _pathBox[i];
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
    }

    private void PredictPair(int i, int j)
    {
        int slot = i * _n + j;
        _pairTime[slot] = double.PositiveInfinity;
        ref readonly var a = ref _balls[i];
        ref readonly var b = ref _balls[j];
        if (a.State == MotionState.Pocketed || b.State == MotionState.Pocketed
            || !(BallMotion.Translates(a.State) || BallMotion.Translates(b.State)))
        {
            return;
        }
        double r = _params.R;
        var ba = _pathBox[i];
        var bb = _pathBox[j];
        if (ba.X0 - bb.X1 > 2 * r || bb.X0 - ba.X1 > 2 * r || ba.Y0 - bb.Y1 > 2 * r || bb.Y0 - ba.Y1 > 2 * r)
        {
            return;
        }
        double horizon = Math.Min(Math.Min(_transitionTime[i], _transitionTime[j]) - Time, MaxHorizon);
        Span<double> c = stackalloc double[5];
        CircleGap(b.Position - a.Position, b.Velocity - a.Velocity, _accel[j] - _accel[i], 2 * r, c);
        double t = Polynomial.FirstEntry(c, horizon, 4 * r * OverlapTolerance);
        _pairTime[slot] = Time + t;
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
