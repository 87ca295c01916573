using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>Speeds and spins at the extremes: a ball nudged at 1e-9 m/s, and 500 rad/s of spin in place.</summary>
public class ExtremeSpeedAndSpinTests
{
    private const double Nudge = 1e-9;

    /// <summary>
    /// A ball nudged at 1e-9 m/s along 30 deg, no spin. By hand it slides for
    /// 2 v / (7 mu_s g) = 2e-9 / 13.734 = 1.5e-10 s over 12 v^2 / (49 mu_s g) = 1.2e-19 m, then rolls
    /// from 5/7 e-9 m/s for 7.3e-9 s over (5/7 e-9)^2 / (2 mu_r g) = 2.6e-18 m. So it must be at rest
    /// after the first step (or at once, if the engine calls it stationary), exactly still and
    /// without spin, and it may move no further than round-off of a 1 m coordinate (1e-15 m).
    /// </summary>
    [Theory]
    [MemberData(nameof(AllIntegrators), MemberType = typeof(StabilityKit))]
    public void BallNudgedAtOneNanometrePerSecondComesToRestInOneStep(string integrator, double dt)
    {
        var start = new Vec3(0.3, -0.2, R);
        var sim = Create(integrator, dt, [Ball(0, start.X, start.Y, Nudge * Math.Cos(Math.PI / 6), Nudge * Math.Sin(Math.PI / 6))]);
        sim.AdvanceTo(10);

        // Euler is explicit: its first step moves the ball by v0 dt before friction can stop it,
        // and it rolls (at 5/7 v0) into a second step. Its bounds are those, not the closed form's.
        bool explicitEuler = integrator == "euler";
        double restBy = explicitEuler ? 2 * dt : dt;
        double travel = explicitEuler ? Nudge * 2 * dt + 1e-15 : 1e-15;
        Assert.True(sim.IsAtRest, "a 1e-9 m/s ball did not come to rest");
        Assert.True(sim.Time <= restBy + 1e-12, $"rest took until t = {sim.Time:R} (dt {dt:R})");
        AssertFinite(sim, "nudge");
        var b = sim.Balls[0];
        AssertVec(Vec3.Zero, b.Velocity, 0, "b.Velocity");
        AssertVec(Vec3.Zero, b.Spin, 0, "b.Spin");
        Assert.Equal(MotionState.Stationary, b.State);
        Assert.True((b.Position - start).Length <= travel, $"the ball moved {(b.Position - start).Length:E2} m");
        // Never backwards: the displacement is along the nudge (30 deg).
        Assert.True(Vec3.Dot(b.Position - start, new Vec3(Math.Cos(Math.PI / 6), Math.Sin(Math.PI / 6), 0)) >= 0, "the ball moved backwards");
    }

    /// <summary>
    /// The same nudge into a ball it already touches (frozen pair): a head-on impact at 1e-9 m/s
    /// at t = 0. Both must come to rest in a step, finite, stationary, with no overlap and no more
    /// movement than the nanometre-per-second budget allows (1e-15 m).
    /// </summary>
    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void NudgeIntoAFrozenNeighbourComesToRestInOneStep(string integrator, double dt)
    {
        var sim = Create(integrator, dt, [Ball(0, 0, 0, Nudge), Ball(1, 2 * R, 0)]);
        sim.AdvanceTo(10);

        Assert.True(sim.IsAtRest);
        Assert.True(sim.Time <= dt + 1e-12, $"rest took until t = {sim.Time:R}");
        AssertFinite(sim, "nudge pair");
        AssertNoOverlap(sim, "nudge pair");
        Assert.All(sim.Balls.ToArray(), b => Assert.Equal(MotionState.Stationary, b.State));
        Assert.True(Math.Abs(sim.Balls[0].Position.X) <= 1e-15 && Math.Abs(sim.Balls[1].Position.X - 2 * R) <= 1e-15,
            $"positions {Fmt(sim.Balls[0].Position)} {Fmt(sim.Balls[1].Position)}");
        Assert.Equal(0, sim.EventCapHits);
    }

    /// <summary>
    /// 500 rad/s about z, in place. Spin about z decays at 5 mu_sp g / (2R) with mu_sp = 4/9 R,
    /// i.e. at (10/9) g = 10.9 rad/s^2, so w_z(t) = 500 - 10.9 t and it stops at
    /// T = 500 / 10.9 = 45.871560 s. Checked after every step: w_z on the line to 1e-9 rad/s
    /// (see below for the round-off budget, far inside 1e-6 relative),
    /// no velocity, no drift of the centre (bit for bit), and rest at the first step boundary at
    /// or after T (the event solver: at T itself, to 1e-9 s). Euler accumulates w -= 10.9 dt
    /// (up to 367,000 times), so it gets 1e-6 rad/s and rest within one step of T.
    /// The exact integrator re-bases the closed form at every step, so it too accumulates
    /// round-off: 367,000 steps (dt 1/8000) times half an ulp of 500 (5.7e-14) is 2.1e-8 rad/s, and
    /// the summed step times drift by about 2e-11 s (2e-10 rad/s): tolerance 1e-7 rad/s, which
    /// still pins the stopping time to 1e-8 s (2e-10 relative).
    /// </summary>
    [Theory]
    [MemberData(nameof(AllIntegrators), MemberType = typeof(StabilityKit))]
    public void SpinOf500RadPerSecondInPlaceStopsInTheAnalyticTimeWithoutDrift(string integrator, double dt)
    {
        const double w0 = 500;
        const double decel = 10.0 / 9.0 * G; // 5 mu_sp g / (2R) with mu_sp = 4R/9
        double stop = w0 / decel;            // 45.871559633 s
        Assert.Equal(10.9, decel, 12);
        double tolerance = integrator == Integrators.Euler ? 1e-6 : 1e-7;

        var start = new Vec3(-0.4, 0.1, R);
        var sim = Create(integrator, dt, [Ball(0, start.X, start.Y, spin: new Vec3(0, 0, w0))]);
        Assert.Equal(MotionState.Spinning, sim.Balls[0].State);
        while (!sim.IsAtRest && sim.Time < 60)
        {
            Advance(sim);
            var b = sim.Balls[0];
            AssertVec(start, b.Position, 0, "b.Position");
            AssertVec(Vec3.Zero, b.Velocity, 0, "b.Velocity");
            Assert.Equal(0, b.Spin.X);
            Assert.Equal(0, b.Spin.Y);
            double expected = Math.Max(0, w0 - decel * sim.Time);
            Assert.True(Math.Abs(b.Spin.Z - expected) <= tolerance, $"w_z at t = {sim.Time:R}: {b.Spin.Z:R}, expected {expected:R}");
        }
        Assert.True(sim.IsAtRest, "still spinning at 60 s");
        Assert.Equal(MotionState.Stationary, sim.Balls[0].State);
        Assert.Equal(0, sim.Balls[0].Spin.Z);
        if (integrator == Integrators.Event)
        {
            Assert.Equal(stop, sim.Time, 1e-9);
        }
        else
        {
            double late = integrator == Integrators.Euler ? 2 * dt : dt;
            Assert.True(sim.Time >= stop - (integrator == Integrators.Euler ? dt : 1e-9) && sim.Time <= stop + late + 1e-9,
                $"rest at t = {sim.Time:R}, analytic {stop:R} (dt {dt:R})");
        }
    }
}
