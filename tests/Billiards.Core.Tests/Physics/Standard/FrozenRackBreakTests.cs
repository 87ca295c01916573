using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// A frozen 15-ball rack (every neighbour exactly 2R apart) broken with a centre hit from the head
/// spot, on the pocketless 9 ft table (2.54 x 1.27 m between the noses) so that "on the bed" is a
/// plain rectangle: |x| at most 1.27 - R, |y| at most 0.635 - R.
/// </summary>
public class FrozenRackBreakTests
{
    // A centre hit (StabilityKit.CueSpeedFor) gives the ball 12 m/s and no spin.
    private const double BreakSpeed = 12;

    // The run must end well before this (s): the fastest ball after the break is far below
    // 12 m/s, and a roll from 12 m/s would take 12 / (mu_r g) = 122 s, which nothing reaches.
    private const double RestLimit = 150;

    private static Simulation Break(string integrator, double dt, double ballSpeed, bool withRack = true)
    {
        var balls = withRack ? FrozenRack(Pocketless) : [];
        var head = Initializer.HeadSpot(Pocketless, R);
        balls.Add(Ball(0, head.X, head.Y));
        var sim = Create(integrator, dt, balls);
        sim.Strike(new ShotSpec(CueSpeedFor(ballSpeed), 0));
        return sim;
    }

    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void BreakTerminatesStaysFiniteOnTheBedWithoutOverlapAndNeverGainsEnergy(string integrator, double dt)
    {
        var sim = Break(integrator, dt, BreakSpeed);
        // Energy just after the strike: 1/2 m 12^2 = 12.247 J (no spin).
        Assert.Equal(0.5 * M * BreakSpeed * BreakSpeed, KineticEnergy(sim.Balls), 1e-9);

        StepChecked(sim, RestLimit, $"frozen break {integrator} dt {dt:R}", checkOverlap: true);

        Assert.True(sim.IsAtRest, $"not at rest after {RestLimit} s");
        AssertNoOverlap(sim, "at rest");
        foreach (var b in sim.Balls)
        {
            AssertVec(Vec3.Zero, b.Velocity, 0, "b.Velocity");
        }
        Assert.NotEmpty(EventsOf(sim, EventKind.BallBall));
    }

    /// <summary>
    /// Momentum at the first impact. The cue ball slides without spin, so before the impact
    /// x(t) = x0 + v0 t - mu_s g t^2 / 2 and v(t) = v0 - mu_s g t (sliding lasts 2 v0 / (7 mu_s g) = 1.75 s).
    /// The cue ball touches the apex when it has covered d = (L/4 + L/4) - 2R = 1.27 - 0.05715 = 1.21285 m.
    /// We choose the ball speed (about 12 m/s) so that this happens delta = 1e-7 s before a step
    /// boundary t1 + delta = k dt, so the step that holds the impact ends just past it; then
    /// v0 = (d + mu_s g t1^2 / 2) / t1. Over delta the cloth changes each ball's velocity by at most
    /// mu_s g delta = 1.962e-7 m/s (sliding; rolling is 20 times less), so the 16 balls' total
    /// momentum / m may move by 16 * 1.962e-7 = 3.1e-6 m/s at most; plus 1e-9 for round-off.
    /// The cue ball's velocity just before the impact comes from the same shot without the rack
    /// (stepped to k dt, plus mu_s g delta back), and is checked against v0 - mu_s g t1.
    /// </summary>
    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void TotalMomentumRightAfterTheFirstImpactEqualsTheCueBallsJustBefore(string integrator, double dt)
    {
        const double delta = 1e-7;
        double d = Pocketless.HalfLength - 2 * R; // head spot -L/4 to apex L/4, less the contact distance
        double a = MuS * G;
        double nominal = (BreakSpeed - Math.Sqrt(BreakSpeed * BreakSpeed - 2 * a * d)) / a; // 0.1011 s at 12 m/s
        double end = Math.Max(1, Math.Round(nominal / dt)) * dt;
        double t1 = end - delta;
        double v0 = (d + 0.5 * a * t1 * t1) / t1;
        Assert.InRange(v0, 11.5, 12.5); // still a 12 m/s break

        var alone = Break(integrator, dt, v0, withRack: false);
        alone.AdvanceTo(end);
        Assert.Equal(end, alone.Time, 1e-12);
        double vCue = alone.Balls[0].Velocity.X + a * delta; // the cue ball just before the impact
        Assert.Equal(v0 - a * t1, vCue, 1e-9);

        var sim = Break(integrator, dt, v0);
        int steps = 0;
        while (EventsOf(sim, EventKind.BallBall).Count == 0 && steps++ < 100_000)
        {
            sim.Step();
        }
        if (integrator == Integrators.Event)
        {
            sim.AdvanceTo(end); // the event solver stops at the impact; take it to the same time
        }
        var first = EventsOf(sim, EventKind.BallBall)[0];
        Assert.Equal(t1, first.Time, 1e-9);
        Assert.Equal(end, sim.Time, 1e-12);
        Assert.Empty(EventsOf(sim, EventKind.BallCushion));

        var p = Momentum(sim.Balls) / M;
        double tolerance = 16 * a * delta + 1e-9;
        Assert.True(Math.Abs(p.X - vCue) <= tolerance && Math.Abs(p.Y) <= tolerance,
            $"momentum / m after the first impact {Fmt(p)} vs cue ball's before ({vCue:R}, 0); tolerance {tolerance:E2} m/s");
        // The impact really spread the momentum: the cue ball kept only a small part of it.
        Assert.True(Math.Abs(sim.Balls[0].Velocity.X) < 0.5 * vCue, $"cue ball still at {Fmt(sim.Balls[0].Velocity)}");
    }

    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void TheSameBreakTwiceEndsBitForBitTheSame(string integrator, double dt)
    {
        var first = Break(integrator, dt, BreakSpeed);
        first.AdvanceTo(RestLimit);
        var second = Break(integrator, dt, BreakSpeed);
        second.AdvanceTo(RestLimit);

        Assert.True(first.IsAtRest && second.IsAtRest);
        Assert.Equal(first.Time, second.Time);
        Assert.Equal(first.EventCapHits, second.EventCapHits);
        Assert.Equal(first.Events.AsSpan().ToArray(), second.Events.AsSpan().ToArray());
        for (int i = 0; i < first.Balls.Length; i++)
        {
            var a = first.Balls[i];
            var b = second.Balls[i];
            double[] x = [a.Position.X, a.Position.Y, a.Position.Z, a.Velocity.X, a.Velocity.Y, a.Velocity.Z, a.Spin.X, a.Spin.Y, a.Spin.Z];
            double[] y = [b.Position.X, b.Position.Y, b.Position.Z, b.Velocity.X, b.Velocity.Y, b.Velocity.Z, b.Spin.X, b.Spin.Y, b.Spin.Z];
            Assert.Equal(x.Select(BitConverter.DoubleToInt64Bits), y.Select(BitConverter.DoubleToInt64Bits));
            Assert.Equal(a.State, b.State);
            Assert.Equal(a.Pocket, b.Pocket);
        }
    }
}
