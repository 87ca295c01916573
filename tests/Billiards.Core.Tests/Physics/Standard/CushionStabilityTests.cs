using Billiards.Core.Physics;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Balls frozen to a cushion (centre exactly R from the nose) and a ball into a corner, on the
/// pocketless 9 ft table: cushions at x = +-1.27 m and y = +-0.635 m.
/// </summary>
public class CushionStabilityTests
{
    private static readonly double XMax = Pocketless.HalfLength - R; // 1.241425
    private static readonly double YMax = Pocketless.HalfWidth - R;  // 0.606425

    /// <summary>
    /// Along the cushion: a ball touching the +y cushion moves along +x at 2 m/s, no spin. It
    /// neither approaches nor leaves the cushion, so nothing may happen there: it slides and rolls
    /// as on open cloth. Closed form (physics-standard-model.md): sliding lasts
    /// 2 v0 / (7 mu_s g) = 4 / 13.734 = 0.291248 s and covers 12 v0^2 / (49 mu_s g) = 0.499282 m,
    /// then it rolls from 5 v0 / 7 = 1.428571 m/s with x = xs + v1 s - mu_r g s^2 / 2. By t = 1 s it
    /// has gone 0.499 + 1.429 * 0.709 - 0.049 * 0.502 = 1.487 m, from x = -1 to 0.487 (short of
    /// the foot cushion). Tolerance 1e-9 m.
    /// </summary>
    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void BallFrozenToACushionShotAlongItNeitherSticksNorTunnelsNorGainsEnergy(string integrator, double dt)
    {
        const double v0 = 2;
        var sim = Create(integrator, dt, [Ball(0, -1, YMax, vx: v0)]);
        StepChecked(sim, 1, "along the cushion");
        sim.AdvanceTo(1);

        double t = sim.Time;
        double a = MuS * G;
        double ts = 2 * v0 / (7 * a);
        double xs = 12 * v0 * v0 / (49 * a);
        double v1 = 5 * v0 / 7;
        double s = t - ts;
        double expectedX = -1 + xs + v1 * s - 0.5 * MuR * G * s * s;
        var b = sim.Balls[0];
        Assert.True(Math.Abs(b.Position.X - expectedX) <= 1e-9, $"x at t = {t:R}: {b.Position.X:R}, expected {expectedX:R}");
        Assert.Equal(YMax, b.Position.Y, 1e-12);
        Assert.Equal(0, b.Velocity.Y, 1e-12);
        Assert.Equal(v1 - MuR * G * s, b.Velocity.X, 1e-9);
        Assert.Empty(EventsOf(sim, EventKind.BallCushion));
    }

    /// <summary>
    /// Into the cushion: a ball touching the foot cushion (x = 1.27 - R) moves into it at 2 m/s,
    /// no spin, so the impact is at t = 0. Han 2005 by hand, with sin(theta_a) = h/R - 1 = 1.28 - 1
    /// = 0.28 and cos^2 = 1 - 0.0784 = 0.9216: c = v cos, s = (v sin, 0); P_zE = (1 + e_c) c m =
    /// 1.85 * 0.96 m v = 1.776 m v; P_zS = |s| / A = (2/7) 0.28 m v = 0.08 m v, not above f_c P_zE = 0.3552 m v,
    /// so the contact sticks and P_xE = 0.08 m v. Back in the table frame the normal impulse is
    /// P_xE sin + P_zE cos = (0.0224 + 1.70496) m v = 1.72736 m v, so the ball leaves at
    /// -0.72736 v = -1.45472 m/s. Only the friction impulse P_xE has a torque (the normal passes
    /// through the centre): |dw_y| = R P_xE / I = 0.2 v / R, turning the ball forward in its new
    /// direction, so the slip is u_x = -0.72736 v + 0.2 v = -0.52736 v: still sliding backwards, and
    /// the cloth pushes +x, v_x(t) = -0.72736 v + mu_s g t, for 2 * 0.52736 * 2 / (7 * 1.962) = 0.154 s
    /// (longer than any step). Tolerance 1e-9 m/s.
    /// </summary>
    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void BallFrozenToACushionShotIntoItBouncesBackWithHanRestitutionAndDoesNotTunnel(string integrator, double dt)
    {
        const double v0 = 2;
        var sim = Create(integrator, dt, [Ball(0, XMax, 0, vx: v0)]);
        sim.AdvanceTo(dt);

        var cushion = EventsOf(sim, EventKind.BallCushion);
        Assert.Single(cushion);
        Assert.Equal(0, cushion[0].Time, 1e-12);
        Assert.Equal(v0, cushion[0].Speed, 1e-12);
        Assert.Equal("foot", sim.FeatureName(EventKind.BallCushion, cushion[0].Feature));
        double expected = -0.72736 * v0 + MuS * G * sim.Time;
        var b = sim.Balls[0];
        Assert.True(Math.Abs(b.Velocity.X - expected) <= 1e-9 && Math.Abs(b.Velocity.Y) <= 1e-12,
            $"after the bounce, t = {sim.Time:R}: v = {Fmt(b.Velocity)}, expected ({expected:R}, 0)");
        AssertOnBed(sim, "into the cushion");

        // On its way back: 1.45 m/s leaves the ball short of the head cushion by t = 1.5 s
        // (sliding 0.154 s, then rolling at under 1.3 m/s: about 1.9 m of the 2.48 m).
        StepChecked(sim, 1.5, "into the cushion");
        Assert.Single(EventsOf(sim, EventKind.BallCushion));
        Assert.True(sim.Balls[0].Position.X < XMax - 1, $"the ball did not come back: {Fmt(sim.Balls[0].Position)}");
    }

    /// <summary>
    /// Into the (+x, +y) corner at 45 deg: the ball starts 0.5 m from the corner contact point on
    /// both axes, at 3 m/s along (1, 1)/sqrt2 with no spin, so it slides straight (slip along v) and
    /// touches both cushions at the same instant, after 0.707 m (sliding lasts 6 / 13.734 = 0.437 s
    /// and covers 12 * 9 / (49 * 1.962) = 1.123 m, so it still slides). Both cushions must act at
    /// that instant and send it back out with both components reversed; then it rolls about the
    /// table (3 s here), finite, on the bed, never gaining energy.
    /// </summary>
    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void BallIntoACornerHitsBothCushionsAtOnceAndComesBackOut(string integrator, double dt)
    {
        double v = 3 / Math.Sqrt(2);
        var sim = Create(integrator, dt, [Ball(0, XMax - 0.5, YMax - 0.5, vx: v, vy: v)]);
        while (EventsOf(sim, EventKind.BallCushion).Count < 2 && sim.Time < 1)
        {
            Advance(sim);
            AssertFinite(sim, "corner");
            AssertOnBed(sim, "corner");
        }
        var cushion = EventsOf(sim, EventKind.BallCushion);
        Assert.True(cushion.Count >= 2, $"expected both cushions, got {cushion.Count} events by t = {sim.Time:R}");
        var names = cushion.Take(2).Select(e => sim.FeatureName(EventKind.BallCushion, e.Feature)).Order().ToList();
        Assert.Equal(["foot", "left-foot"], names);
        Assert.Equal(cushion[0].Time, cushion[1].Time, 1e-9);
        // Sliding straight: 0.707 m = 3 t - 0.981 t^2, t = (3 - sqrt(9 - 4 * 0.981 * 0.7071)) / 1.962.
        double distance = 0.5 * Math.Sqrt(2);
        double tHit = (3 - Math.Sqrt(9 - 2 * MuS * G * distance)) / (MuS * G);
        Assert.Equal(tHit, cushion[0].Time, 1e-9);

        var b = sim.Balls[0];
        Assert.True(b.Velocity.X < 0 && b.Velocity.Y < 0, $"the ball did not come back out of the corner: v = {Fmt(b.Velocity)}");
        StepChecked(sim, 3, "corner");
        Assert.True(sim.Balls[0].Position.X < XMax - 0.1 || sim.Balls[0].Position.Y < YMax - 0.1, "the ball stayed in the corner");
    }
}
