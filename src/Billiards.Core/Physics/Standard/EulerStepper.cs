using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// The naive baseline of the accuracy report: explicit Euler on the same forces as the closed
/// form, with collisions found by overlap at the end of each step and resolved by the same
/// collision models. First order in dt; it can tunnel and it detects contacts late.
/// </summary>
/// <remarks>
/// A state ends when its step would overshoot: sliding when the slip would reverse, rolling when
/// the velocity would, spin about z when it would change sign. Nothing else is clever on purpose.
/// </remarks>
public sealed class EulerStepper
{
    private readonly BallState[] _balls;
    private readonly BallId[] _ids;
    private readonly PhysicsParams _params;
    private readonly MotionConstants _k;
    private readonly TableGeometry _geometry;
    private readonly IBallBallModel _ballBall;
    private readonly IBallCushionModel _ballCushion;
    private readonly EventLog _log;
    private readonly Landing _landing;
    private readonly Vec3[] _start;

    // How far behind a face or inside a circle a ball may start and still count as touching it (m).
    private const double ContactSlack = 1e-9;

    /// <summary>Creates a stepper over the balls (shared, changed in place) on <paramref name="model"/>'s table, with its collision models.</summary>
    public EulerStepper(BallState[] balls, IReadOnlyList<BallId> ids, StandardTableModel model, EventLog log)
    {
        ArgumentNullException.ThrowIfNull(model);
        _balls = balls;
        _ids = [.. ids];
        _params = model.Parameters;
        _k = model.Constants;
        _geometry = model.Geometry;
        _ballBall = model.BallBall;
        _ballCushion = model.BallCushion;
        _log = log;
        _landing = new Landing(model, _ids, log);
        _start = new Vec3[balls.Length];
        for (int i = 0; i < balls.Length; i++)
        {
            BallMotion.Classify(ref _balls[i], _k);
        }
    }

    /// <summary>When true, orientations are integrated.</summary>
    public bool TrackOrientation { get; set; }

    /// <summary>True when no ball moves or spins.</summary>
    public bool IsAtRest
    {
        get
        {
            foreach (ref readonly var b in _balls.AsSpan())
            {
                if (BallMotion.IsActive(b.State))
                {
                    return false;
                }
            }
            return true;
        }
    }

    /// <summary>Re-classifies every ball after the caller restored their state.</summary>
    public void Restart()
    {
        for (int i = 0; i < _balls.Length; i++)
        {
            BallMotion.Classify(ref _balls[i], _k);
        }
    }

    /// <summary>Re-classifies a ball after an outside change (a cue strike).</summary>
    public void BallChanged(int index) => BallMotion.Classify(ref _balls[index], _k);

    /// <summary>One explicit Euler step of <paramref name="dt"/> seconds ending at <paramref name="timeAfter"/>.</summary>
    public void Step(double dt, double timeAfter)
    {
        bool translating = false;
        for (int i = 0; i < _balls.Length; i++)
        {
            _start[i] = _balls[i].Position;
            if (BallMotion.IsActive(_balls[i].State))
            {
                Integrate(ref _balls[i], dt);
                if (_balls[i].State == MotionState.Airborne)
                {
                    ComeDown(ref _balls[i], i, timeAfter);
                }
                translating |= BallMotion.Translates(_balls[i].State);
            }
        }
        // Every contact needs a ball that moves (a resting or spinning pair never overlaps anew).
        if (translating)
        {
            DetectAndResolve(dt, timeAfter);
        }
    }

    // Found by overlap, like every contact here: the step that took a ball in the air below the
    // rails' top decides what it comes down on there (where its straight path crossed that
    // height), and the step that took it below the bed lands it.
    private void ComeDown(ref BallState b, int i, double time)
    {
        double top = _landing.RailTop;
        var p0 = _start[i];
        if (p0.Z >= top && b.Position.Z < top)
        {
            double s = (p0.Z - top) / (p0.Z - b.Position.Z);
            var at = p0 + (b.Position - p0) * s;
            var surface = _geometry.SurfaceUnder(at);
            if (surface.Kind != SurfaceKind.Bed)
            {
                b.Position = new Vec3(at.X, at.Y, top);
                _landing.OnSurface(ref b, i, surface, time);
                return;
            }
        }
        if (b.Position.Z <= _k.R)
        {
            _landing.OnBed(ref b, i, time);
        }
    }

    private void Integrate(ref BallState b, double dt)
    {
        double r = _k.R;
        var spin0 = b.Spin;
        switch (b.State)
        {
            case MotionState.Airborne:
                b.Position += b.Velocity * dt;
                b.Velocity = new Vec3(b.Velocity.X, b.Velocity.Y, b.Velocity.Z - _k.G * dt);
                if (TrackOrientation)
                {
                    BallMotion.Rotate(ref b.Orientation, b.Spin * dt);
                }
                return;
            case MotionState.Sliding:
                {
                    var u = BallMotion.Slip(b, r);
                    var uHat = u.Normalized();
                    var a = uHat * -_k.SlidingDeceleration;
                    double alpha = 2.5 * _k.SlidingDeceleration / r;
                    var v0 = b.Velocity;
                    b.Position += b.Velocity * dt;
                    b.Velocity += a * dt;
                    b.Spin = new Vec3(b.Spin.X - alpha * uHat.Y * dt, b.Spin.Y + alpha * uHat.X * dt, b.Spin.Z);
                    if (Vec3.Dot(BallMotion.Slip(b, r), u) <= 0)
                    {
                        // The slip would reverse inside the step: friction only ever brings it to
                        // zero, where the ball rolls at v0 - 2/7 u0 (the slip law). Without this a
                        // step longer than the sliding phase reverses the ball and adds energy.
                        b.Velocity = v0 - u * (2.0 / 7.0);
                        BallMotion.EndState(ref b, _k);
                    }
                    break;
                }
            case MotionState.Rolling:
                {
                    var v0 = b.Velocity;
                    b.Position += b.Velocity * dt;
                    b.Velocity -= v0.Normalized() * (_k.RollingDeceleration * dt);
                    b.Spin = new Vec3(-b.Velocity.Y / r, b.Velocity.X / r, b.Spin.Z);
                    if (Vec3.Dot(b.Velocity, v0) <= 0)
                    {
                        BallMotion.EndState(ref b, _k);
                    }
                    break;
                }
        }
        BallMotion.DecaySpinZ(ref b, dt, _k);
        if (b.State == MotionState.Spinning && b.Spin.Z == 0)
        {
            BallMotion.EndState(ref b, _k);
        }
        if (TrackOrientation)
        {
            BallMotion.Rotate(ref b.Orientation, (spin0 + b.Spin) * (0.5 * dt));
        }
    }

    private void DetectAndResolve(double dt, double time)
    {
        double r = _params.R;
        var balls = _balls.AsSpan();
        for (int i = 0; i < balls.Length; i++)
        {
            ref var a = ref balls[i];
            if (BallMotion.IsOut(a.State))
            {
                continue;
            }
            for (int j = i + 1; j < balls.Length; j++)
            {
                ref var b = ref balls[j];
                if (BallMotion.IsOut(b.State) || !(BallMotion.Translates(a.State) || BallMotion.Translates(b.State)))
                {
                    continue;
                }
                // In space: a ball in the air passes over the balls below it (on the bed, z is equal).
                var d = b.Position - a.Position;
                if (d.LengthSquared >= 4 * r * r)
                {
                    continue;
                }
                var n = d.Normalized();
                double approach = Vec3.Dot(a.Velocity - b.Velocity, n);
                if (approach <= 0)
                {
                    continue;
                }
                _ballBall.Resolve(ref a, ref b, _params);
                // Overlap detection finds balls inside each other: put them back in touch, half
                // each along the line of centres (as the thesis model's Formel 11 does); a ball on
                // the bed stays on it.
                var correction = n * (0.5 * (2 * r - d.Length));
                a.Position -= a.State == MotionState.Airborne ? correction : correction.XY;
                b.Position += b.State == MotionState.Airborne ? correction : correction.XY;
                BallMotion.Classify(ref a, _k);
                BallMotion.Classify(ref b, _k);
                _log.Add(new SimEvent(time, EventKind.BallBall, _ids[i], _ids[j], -1, approach));
            }
        }

        for (int i = 0; i < balls.Length; i++)
        {
            ref var b = ref balls[i];
            if (!BallMotion.Translates(b.State))
            {
                continue;
            }
            bool high = b.State == MotionState.Airborne && b.Position.Z >= _landing.RailTop;
            if (high)
            {
                continue; // above the rails: no cushion, jaw or hole reaches it
            }
            // A swept contact (the ball stopped on a face or nose) replaces the overlap tests; the
            // pocket test below still runs, since a bounce in a mouth can leave it over the hole.
            if (!SweepBoundary(ref b, i, time))
            {
                foreach (ref readonly var s in _geometry.Segments)
                {
                    double gap = Vec3.Dot(s.Normal, b.Position - s.Start) - r;
                    if (gap >= 0)
                    {
                        continue; // the common case: not overlapping this face's line
                    }
                    double along = Vec3.Dot(b.Position - s.Start, s.Direction);
                    double approach = -Vec3.Dot(b.Velocity, s.Normal);
                    // Overlapping, on the face, approaching, and no deeper than this step's travel could
                    // take a ball that was in front of the face: a long step must not let a fast ball
                    // through the cushion, and the bound keeps balls in a pocket's mouth, behind the
                    // line of a neighbouring cushion, from being caught by it.
                    if (gap > -r - approach * dt && along >= 0 && along <= s.Length && approach > 0)
                    {
                        b.Position -= s.Normal * gap; // back onto the face
                        Cushion(ref b, i, s.Normal, s.Feature, approach, time);
                    }
                }
                foreach (ref readonly var nose in _geometry.Noses)
                {
                    var d = (b.Position - nose.Centre).XY;
                    double reach = r + nose.Radius;
                    if (d.LengthSquared < reach * reach)
                    {
                        var n = d.Normalized();
                        double approach = -Vec3.Dot(b.Velocity, n);
                        if (approach > 0)
                        {
                            var touching = nose.Centre + n * reach;
                            b.Position = new Vec3(touching.X, touching.Y, b.Position.Z);
                            Cushion(ref b, i, n, nose.Feature, approach, time);
                        }
                    }
                }
            }
            foreach (ref readonly var pocket in _geometry.Pockets)
            {
                if (b.State != MotionState.Pocketed && (b.Position - pocket.Centre).XY.LengthSquared < pocket.Radius * pocket.Radius)
                {
                    Drop(ref b, i, pocket.Pocket, time);
                    break;
                }
            }
            if (b.State is not (MotionState.Pocketed or MotionState.Airborne) && !TableBounds.Contains(_geometry.Spec, b.Position, r))
            {
                LeftTheTable(ref b, i, time);
            }
        }
    }

    /// <summary>
    /// A ball whose step ended off the table (neither on the bed nor in a mouth). Every cushion
    /// face and nose is swept, so the only way out is through a mouth: a ball bounced deep in the
    /// jaws within one long step (a hard masse at dt 0.1) can travel on past the jaws' ends, over
    /// the hole, without its straight path meeting the capture circle. Over the hole it falls: it
    /// drops into the pocket whose capture circle its step's path came nearest. Should that path
    /// pass no mouth (which the sweep rules out), the ball goes back to where the step started
    /// and stops, so that no result ever holds a ball off the table.
    /// </summary>
    private void LeftTheTable(ref BallState b, int i, double time)
    {
        double best = double.PositiveInfinity;
        int nearest = -1;
        var p0 = _start[i];
        var d = (b.Position - p0).XY;
        foreach (ref readonly var pocket in _geometry.Pockets)
        {
            var f = (pocket.Centre - p0).XY;
            double s = d.LengthSquared > 0 ? Math.Clamp(Vec3.Dot(f, d) / d.LengthSquared, 0, 1) : 0;
            double distance = (f - d * s).Length;
            if (distance < best)
            {
                (best, nearest) = (distance, pocket.Pocket);
            }
        }
        var spec = _geometry.Spec;
        double reach = spec.Pockets.Max(p => p.Mouth) / 2 + 2 * _params.R;
        if (nearest >= 0 && best <= reach)
        {
            Drop(ref b, i, nearest, time);
            return;
        }
        b.Position = _start[i];
        b.Velocity = Vec3.Zero;
        b.Spin = new Vec3(0, 0, b.Spin.Z);
        BallMotion.Classify(ref b, _k);
    }

    /// <summary>
    /// The table-bound guarantee at any step: the straight path a ball's centre took this step
    /// (from its start to where integration and pair corrections left it) is tested against every
    /// cushion face, jaw nose and capture circle, and the first one it crossed from the table's
    /// side takes it: the ball stops there and bounces, or drops. Overlap alone misses a ball that
    /// travels further in one step than a face's depth or a capture circle's width. Ball-ball
    /// contacts stay overlap-detected: that is this baseline's nature.
    /// </summary>
    /// <returns>True when the path crossed the boundary and the ball was handled.</returns>
    private bool SweepBoundary(ref BallState b, int i, double time)
    {
        double r = _params.R;
        var p0 = _start[i];
        var d = (b.Position - p0).XY;
        if (d.LengthSquared == 0)
        {
            return false;
        }
        double first = double.PositiveInfinity;
        int kind = 0, index = -1;
        var segments = _geometry.Segments;
        for (int k = 0; k < segments.Length; k++)
        {
            ref readonly var s = ref segments[k];
            double g0 = Vec3.Dot(s.Normal, p0 - s.Start) - r;
            double g1 = Vec3.Dot(s.Normal, b.Position - s.Start) - r;
            // Started behind the face's line (a ball in a mouth), or never reached it. A ball left
            // touching a face by the last bounce starts on the line, give or take round-off.
            if (g0 < -ContactSlack || g1 >= 0)
            {
                continue;
            }
            double t = Math.Max(g0, 0) / (Math.Max(g0, 0) - g1);
            double along = Vec3.Dot(p0 + d * t - s.Start, s.Direction);
            if (along >= 0 && along <= s.Length && t < first)
            {
                (first, kind, index) = (t, 1, k);
            }
        }
        var noses = _geometry.Noses;
        for (int k = 0; k < noses.Length; k++)
        {
            double t = Entry(p0, d, noses[k].Centre, r + noses[k].Radius);
            if (t < first)
            {
                (first, kind, index) = (t, 2, k);
            }
        }
        var pockets = _geometry.Pockets;
        for (int k = 0; k < pockets.Length; k++)
        {
            double t = Entry(p0, d, pockets[k].Centre, pockets[k].Radius);
            if (t < first)
            {
                (first, kind, index) = (t, 3, k);
            }
        }
        if (kind == 0)
        {
            return false;
        }
        var at = p0 + d * first;
        b.Position = new Vec3(at.X, at.Y, b.Position.Z);
        if (kind == 3)
        {
            Drop(ref b, i, pockets[index].Pocket, time);
            return true;
        }
        var normal = kind == 1 ? segments[index].Normal : (b.Position - noses[index].Centre).XY.Normalized();
        int feature = kind == 1 ? segments[index].Feature : noses[index].Feature;
        double approach = -Vec3.Dot(b.Velocity, normal);
        if (approach > 0)
        {
            Cushion(ref b, i, normal, feature, approach, time);
        }
        return true;
    }

    // Where along p0 + s d (s in [0, 1]) a centre outside the circle first reaches it; infinity if it does not.
    private static double Entry(Vec3 p0, Vec3 d, Vec3 centre, double radius)
    {
        var f = (p0 - centre).XY;
        double c = f.LengthSquared - radius * radius;
        if (c < -2 * radius * ContactSlack)
        {
            return double.PositiveInfinity; // already inside: the overlap tests deal with it
        }
        c = Math.Max(c, 0);
        double a = d.LengthSquared, bh = Vec3.Dot(f, d);
        double disc = bh * bh - a * c;
        if (bh >= 0 || disc < 0)
        {
            return double.PositiveInfinity;
        }
        double s = c / (-bh + Math.Sqrt(disc)); // the smaller root, without cancellation
        return s <= 1 ? s : double.PositiveInfinity;
    }

    private void Drop(ref BallState b, int i, int pocket, double time) => _landing.Drop(ref b, i, pocket, time);

    private void Cushion(ref BallState b, int i, Vec3 normal, int feature, double approach, double time)
    {
        _ballCushion.Resolve(ref b, normal, _geometry.CushionHeight, _params);
        BallMotion.Classify(ref b, _k);
        _log.Add(new SimEvent(time, EventKind.BallCushion, _ids[i], _ids[i], feature, approach));
    }
}
