using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Roots;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard.Events;

/// <summary>What a ball's cushion prediction meets.</summary>
internal enum RailKind : byte
{
    /// <summary>Nothing.</summary>
    None,
    /// <summary>A straight cushion or jaw face.</summary>
    Segment,
    /// <summary>A jaw's circular nose.</summary>
    Nose,
    /// <summary>A pocket's capture circle.</summary>
    Pocket,
    /// <summary>Coming down from above the rails' top over the floor, beyond the rails: the ball leaves the table.</summary>
    OffTable,
    /// <summary>Coming down from above onto the top of a cushion or rail (the index is the nearest cushion feature).</summary>
    RailTop,
}

/// <summary>
/// The narrow phase: for one ball synced to the engine's time, when its motion state ends and its
/// first contact with a cushion face, jaw nose or pocket; how far ahead its pairs are predicted
/// (its pair window, registered with the broad phase); and for two balls, their first contact.
/// Every contact is a polynomial root (a quadratic for faces, a quartic for circles and pairs).
/// Each prediction looks only as far as the end of the current states of the balls involved (after
/// that the polynomials change, and the transition re-predicts).
/// </summary>
internal sealed class Predictor
{
    // Longest look-ahead (s) when no friction would ever end a state.
    private const double MaxHorizon = 1e4;

    // How far a gap may already be below zero and still count as a new contact (m, or m^2 / (2R)
    // for squared gaps): a few ulps of table coordinates, far less than anything physical.
    private const double OverlapTolerance = 1e-9;

    // Shortest pair look-ahead (s), so that a refresh always moves the clock on.
    private const double MinWindow = 1e-6;

    private readonly BallState[] _balls;
    private readonly MotionConstants _k;
    private readonly double _r;
    private readonly TableGeometry _geometry;
    private readonly double _railTop;
    private readonly BroadPhase _grid;

    private readonly FeatureBoxes _features;

    private readonly double[] _transitionTime;
    private readonly double[] _railTime;
    private readonly RailKind[] _railKind;
    private readonly int[] _railIndex;
    private readonly Vec3[] _accel;

    // Per ball pair look-ahead: pairs are predicted until _windowEnd (the state's end, or the
    // refresh time _refreshTime when the path is cut to about one grid cell); _windowBox bounds
    // the path until then.
    private readonly double[] _windowEnd;
    private readonly double[] _refreshTime;
    private readonly (double X0, double Y0, double X1, double Y1)[] _windowBox;

    /// <summary>A predictor over the balls (read, never changed) that registers windows with the grid.</summary>
    public Predictor(BallState[] balls, StandardTableModel model, BroadPhase grid)
    {
        _balls = balls;
        _k = model.Constants;
        _r = _k.R;
        _geometry = model.Geometry;
        _railTop = model.Geometry.Spec.RailHeight + _r;
        _features = model.Features;
        _grid = grid;

        int n = balls.Length;
        _transitionTime = new double[n];
        _railTime = new double[n];
        _railKind = new RailKind[n];
        _railIndex = new int[n];
        _accel = new Vec3[n];
        _windowEnd = new double[n];
        _refreshTime = new double[n];
        _windowBox = new (double, double, double, double)[n];
    }

    /// <summary>When ball i's motion state ends (s, absolute).</summary>
    public double TransitionTime(int i) => _transitionTime[i];

    /// <summary>When ball i meets its first cushion, jaw or pocket (s, absolute).</summary>
    public double RailTime(int i) => _railTime[i];

    /// <summary>What ball i's cushion prediction meets.</summary>
    public RailKind RailKindOf(int i) => _railKind[i];

    /// <summary>Index of the face, nose or pocket ball i's cushion prediction meets.</summary>
    public int RailIndex(int i) => _railIndex[i];

    /// <summary>When ball i's pair window runs out before its state ends (s, absolute), else +infinity.</summary>
    public double RefreshTime(int i) => _refreshTime[i];

    /// <summary>Ball i's acceleration in its current state (m/s^2).</summary>
    public Vec3 Acceleration(int i) => _accel[i];

    /// <summary>Drops ball i's transition prediction (the event cap suppressed it).</summary>
    public void DropTransition(int i) => _transitionTime[i] = double.PositiveInfinity;

    /// <summary>Drops ball i's cushion prediction (the event cap suppressed it).</summary>
    public void DropRail(int i) => _railTime[i] = double.PositiveInfinity;

    /// <summary>State end, first rail / jaw / pocket contact and pair window of ball i, synced to <paramref name="time"/>.</summary>
    public void PredictBall(int i, double time)
    {
        ref readonly var b = ref _balls[i];
        _railTime[i] = double.PositiveInfinity;
        _railKind[i] = RailKind.None;
        if (!BallMotion.IsActive(b.State))
        {
            _transitionTime[i] = double.PositiveInfinity;
            _accel[i] = Vec3.Zero;
            PredictWindow(i, double.PositiveInfinity, time);
            return;
        }
        double duration = BallMotion.StateDuration(b, _k);
        _transitionTime[i] = time + duration;
        var acc = BallMotion.Acceleration(b, _k);
        _accel[i] = acc;
        if (!BallMotion.Translates(b.State))
        {
            PredictWindow(i, duration, time);
            return;
        }

        double horizon = Math.Min(duration, MaxHorizon);
        var box = PathBox(b.Position, b.Velocity, acc, horizon);
        double r = _r;
        bool airborne = b.State == MotionState.Airborne;
        Coefficients c = default;
        double best = double.PositiveInfinity;
        if (airborne && ComesDownOffTheBed(b, horizon, out double down, out var surface))
        {
            // Nothing below the rails' top meets a ball above it, so this is its first contact.
            best = down;
            (_railKind[i], _railIndex[i]) = surface.Kind switch
            {
                SurfaceKind.Pocket => (RailKind.Pocket, surface.Index),
                SurfaceKind.Rail => (RailKind.RailTop, surface.Index),
                _ => (RailKind.OffTable, -1),
            };
            horizon = down;
            box = PathBox(b.Position, b.Velocity, acc, horizon);
        }

        var segments = _geometry.Segments;
        for (int s = 0; s < segments.Length; s++)
        {
            if (!Overlaps(box, _features.Segments[s]))
            {
                continue;
            }
            var g = segments[s];
            // Signed distance of the centre from the face, less R: a quadratic.
            c[0] = Vec3.Dot(g.Normal, b.Position - g.Start) - r;
            c[1] = Vec3.Dot(g.Normal, b.Velocity);
            c[2] = 0.5 * Vec3.Dot(g.Normal, acc);
            double t = Polynomial.FirstEntry(ref c, 2, horizon, OverlapTolerance);
            if (t < best)
            {
                // The contact must fall on the face; past its ends the noses take over.
                var p = b.Position + b.Velocity * t + acc * (0.5 * t * t);
                double along = Vec3.Dot(p - g.Start, g.Direction);
                if (along >= 0 && along <= g.Length && !(airborne && Clears(b, t)))
                {
                    best = t;
                    _railKind[i] = RailKind.Segment;
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
            if (!Overlaps(box, _features.Noses[s]))
            {
                continue;
            }
            double reach = r + noses[s].Radius;
            CircleGap(b.Position - noses[s].Centre, b.Velocity, acc, reach, ref c);
            double t = Polynomial.FirstEntry(ref c, 4, horizon, 2 * reach * OverlapTolerance);
            if (t < best && !(airborne && Clears(b, t)))
            {
                best = t;
                _railKind[i] = RailKind.Nose;
                _railIndex[i] = s;
                horizon = t;
                box = PathBox(b.Position, b.Velocity, acc, horizon);
            }
        }
        var pockets = _geometry.Pockets;
        for (int s = 0; s < pockets.Length; s++)
        {
            if (!Overlaps(box, _features.Pockets[s]))
            {
                continue;
            }
            CircleGap(b.Position - pockets[s].Centre, b.Velocity, acc, pockets[s].Radius, ref c);
            // Any centre inside the circle and going deeper is pocketed; from the air only a ball
            // low enough to pass under the rails' top (one higher flies over the hole).
            double t = Polynomial.FirstEntry(ref c, 4, horizon, double.PositiveInfinity);
            if (t < best && !(airborne && Clears(b, t)))
            {
                best = t;
                _railKind[i] = RailKind.Pocket;
                _railIndex[i] = s;
            }
        }
        _railTime[i] = time + best;
        PredictWindow(i, Math.Min(duration, best), time);
    }

    // True when a ball in the air is, t seconds on, with its bottom above the rails' top: it
    // passes over the cushions and jaws there, and over the pockets' holes.
    private bool Clears(in BallState b, double t) =>
        b.Position.Z + b.Velocity.Z * t - 0.5 * _k.G * t * t >= _railTop;

    // When a ball in the air comes down to the rails' top (the later root of a quadratic; none
    // when it never gets so high) over something other than the bed, and what: a hole, a rail or
    // the floor (TableGeometry.SurfaceUnder). Over the bed it falls on, between the cushions, to
    // the bed's own landing.
    private bool ComesDownOffTheBed(in BallState b, double horizon, out double t, out TableSurface surface)
    {
        surface = default;
        double c0 = b.Position.Z - _railTop, vz = b.Velocity.Z, g = _k.G;
        t = double.PositiveInfinity;
        double disc = vz * vz + 2 * g * c0;
        if (disc < 0 || (c0 < 0 && vz <= 0))
        {
            return false;
        }
        // c0 + vz t - g t^2 / 2 = 0, its later root, in the form without cancellation.
        double root = Math.Sqrt(disc);
        t = vz > 0 ? (vz + root) / g : root - vz > 0 ? 2 * c0 / (root - vz) : 0;
        if (!(t <= horizon))
        {
            return false;
        }
        surface = _geometry.SurfaceUnder(b.Position + b.Velocity * t);
        return surface.Kind != SurfaceKind.Bed;
    }

    /// <summary>
    /// How far ahead ball i's pairs are predicted (until its state ends or it meets a cushion, after
    /// which its path changes anyway, or on large tables until it has travelled about one grid
    /// cell), the box around that path, and its grid cells. <paramref name="remaining"/>: time to
    /// the first of the state's end and the cushion (s).
    /// </summary>
    public void PredictWindow(int i, double remaining, double time)
    {
        ref readonly var b = ref _balls[i];
        _refreshTime[i] = double.PositiveInfinity;
        _windowEnd[i] = Math.Min(_transitionTime[i], _railTime[i]);
        if (BallMotion.IsOut(b.State))
        {
            _grid.Unregister(i);
            return;
        }
        if (!BallMotion.Translates(b.State))
        {
            _windowBox[i] = (b.Position.X, b.Position.Y, b.Position.X, b.Position.Y);
            _grid.Register(i, _windowBox[i]);
            return;
        }
        double horizon = Math.Min(remaining, MaxHorizon);
        var acc = _accel[i];
        double lookAhead = _grid.LookAhead;
        if (lookAhead < double.PositiveInfinity)
        {
            double reach = Math.Max(lookAhead / Math.Max(b.Velocity.LengthXY, Math.Sqrt(lookAhead * acc.LengthXY)), MinWindow);
            if (reach < horizon)
            {
                horizon = reach;
                _refreshTime[i] = time + reach;
                _windowEnd[i] = _refreshTime[i];
            }
        }
        _windowBox[i] = PathBox(b.Position, b.Velocity, acc, horizon);
        _grid.Register(i, _windowBox[i]);
    }

    /// <summary>
    /// False when balls i and j cannot meet before either's window ends: a pocketed ball, neither
    /// translating, or window boxes more than 2R apart. Needs no sync.
    /// </summary>
    public bool MayMeet(int i, int j)
    {
        ref readonly var a = ref _balls[i];
        ref readonly var b = ref _balls[j];
        if (BallMotion.IsOut(a.State) || BallMotion.IsOut(b.State)
            || !(BallMotion.Translates(a.State) || BallMotion.Translates(b.State)))
        {
            return false;
        }
        double r = _r;
        var ba = _windowBox[i];
        var bb = _windowBox[j];
        return !(ba.X0 - bb.X1 > 2 * r || bb.X0 - ba.X1 > 2 * r || ba.Y0 - bb.Y1 > 2 * r || bb.Y0 - ba.Y1 > 2 * r);
    }

    // True when the relative path d + v t + a t^2 / 2 (bed plane), t in [0, t], provably stays
    // farther than reach from the origin, by a margin above every rounding error of the quartic's
    // coefficients, its evaluation and the degree cut (about 1e-14 of the largest term M^2, where
    // M bounds |d| + |v| t + |a| t^2 / 2): then every value the root finder computes on [0, t] is
    // positive and it would return +infinity too, bit for bit the same answer without the solve.
    // The path lies in the triangle of its quadratic Bezier control points, d, d + v t / 2 and
    // its end; this catches what ClearOf's straight line plus drift misses on long, curved paths.
    private static bool HullClear(Vec3 d, Vec3 v, Vec3 a, double t, double reach)
    {
        if (!(t > 0))
        {
            return false;
        }
        double hx = 0.5 * a.X, hy = 0.5 * a.Y;
        double m = Math.Sqrt(d.X * d.X + d.Y * d.Y) + Math.Sqrt(v.X * v.X + v.Y * v.Y) * t + Math.Sqrt(hx * hx + hy * hy) * t * t;
        double margin = 1e-13 * (m * m + reach * reach) + 1e-9 * reach * reach;
        double dist = TriangleDistance(d.X, d.Y, d.X + v.X * (0.5 * t), d.Y + v.Y * (0.5 * t),
            d.X + v.X * t + hx * t * t, d.Y + v.Y * t + hy * t * t);
        return dist > reach && (dist - reach) * (dist + reach) > margin;
    }

    // Distance from the origin to the triangle (a, b, c), 0 inside.
    private static double TriangleDistance(double ax, double ay, double bx, double by, double cx, double cy)
    {
        double c1 = (bx - ax) * (-ay) - (by - ay) * (-ax);
        double c2 = (cx - bx) * (-by) - (cy - by) * (-bx);
        double c3 = (ax - cx) * (-cy) - (ay - cy) * (-cx);
        if ((c1 >= 0 && c2 >= 0 && c3 >= 0) || (c1 <= 0 && c2 <= 0 && c3 <= 0))
        {
            return 0;
        }
        return Math.Sqrt(Math.Min(SegmentDistance2(ax, ay, bx, by), Math.Min(SegmentDistance2(bx, by, cx, cy), SegmentDistance2(cx, cy, ax, ay))));
    }

    // Squared distance from the origin to the segment (a, b).
    private static double SegmentDistance2(double ax, double ay, double bx, double by)
    {
        double ex = bx - ax, ey = by - ay;
        double ee = ex * ex + ey * ey;
        double s = ee > 0 ? Math.Clamp(-(ax * ex + ay * ey) / ee, 0, 1) : 0;
        double x = ax + ex * s, y = ay + ey * s;
        return x * x + y * y;
    }

    /// <summary>Time of the first contact of balls i &lt; j, both synced to <paramref name="time"/> (s, absolute), or +infinity.</summary>
    public double PairContact(int i, int j, double time)
    {
        ref readonly var a = ref _balls[i];
        ref readonly var b = ref _balls[j];
        double r = _r;
        double horizon = Math.Min(Math.Min(_windowEnd[i], _windowEnd[j]) - time, MaxHorizon);
        var d = b.Position - a.Position;
        var dv = b.Velocity - a.Velocity;
        var da = _accel[j] - _accel[i];
        if (ClearOf(d, dv, da, horizon, 2 * r))
        {
            return double.PositiveInfinity;
        }
        if (HullClear(d, dv, da, horizon, 2 * r))
        {
            return double.PositiveInfinity;
        }
        Coefficients c = default;
        SphereGap(d, dv, da, 2 * r, ref c);
        double t = Polynomial.FirstEntry(ref c, 4, horizon, 4 * r * OverlapTolerance);
        return time + t;
    }

    /// <summary>Copies another predictor's per-ball predictions (same table and balls count).</summary>
    public void CopyFrom(Predictor other)
    {
        other._transitionTime.CopyTo(_transitionTime, 0);
        other._railTime.CopyTo(_railTime, 0);
        other._railKind.CopyTo(_railKind, 0);
        other._railIndex.CopyTo(_railIndex, 0);
        other._accel.CopyTo(_accel, 0);
        other._windowEnd.CopyTo(_windowEnd, 0);
        other._refreshTime.CopyTo(_refreshTime, 0);
        other._windowBox.CopyTo(_windowBox, 0);
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
    private static void CircleGap(Vec3 d, Vec3 v, Vec3 a, double reach, ref Coefficients c)
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

    // |d + v t + a t^2 / 2|^2 - reach^2 in space, for two balls: a ball in the air moves on a
    // parabola, so the gap of two balls is still a quartic. On the bed every z term is exactly 0
    // (both centres at z = R, no vertical velocity or acceleration), so bed pairs get the same
    // coefficients, bit for bit, as in the plane. The bed-plane culls (ClearOf, HullClear, the
    // boxes) stay valid: a horizontal distance never exceeds the distance in space.
    private static void SphereGap(Vec3 d, Vec3 v, Vec3 a, double reach, ref Coefficients c)
    {
        var h = a * 0.5;
        c[4] = Vec3.Dot(h, h);
        c[3] = 2 * Vec3.Dot(h, v);
        c[2] = Vec3.Dot(v, v) + 2 * Vec3.Dot(h, d);
        c[1] = 2 * Vec3.Dot(v, d);
        c[0] = Vec3.Dot(d, d) - reach * reach;
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
