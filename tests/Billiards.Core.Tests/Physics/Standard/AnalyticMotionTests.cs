using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Xunit.Abstractions;
using static Billiards.Core.Tests.Physics.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// The analytic checks of physics-standard-model.md, at several fixed steps: the exact integrator
/// must reproduce the closed form to 1e-6 relative whatever dt is. Expected values are computed
/// here from the formulas, not taken from a run.
/// </summary>
public class AnalyticMotionTests(ITestOutputHelper output)
{
    private const double MuS = 0.2, MuR = 0.01;
    private const double Tolerance = 1e-6;

    public static TheoryData<double> Steps => new(Dts);

    // Steps the exact integrator and reconstructs the sliding -> rolling transition of a ball moving
    // along +x from the last sliding step and the first rolling step: the two velocity lines
    // (deceleration mu_s g, then mu_r g) meet at the transition time.
    private static (double Time, double Distance, double RollingSpeed) SlideToRoll(StandardSimulation sim, double x0)
    {
        BallState before = sim.Balls[0];
        double tBefore = sim.Time;
        while (sim.Balls[0].State == MotionState.Sliding)
        {
            before = sim.Balls[0];
            tBefore = sim.Time;
            sim.Step();
        }
        var after = sim.Balls[0];
        Assert.Equal(MotionState.Rolling, after.State);
        double tAfter = sim.Time;
        double vb = before.Velocity.X, va = after.Velocity.X;
        // Sliding: v = vb + sign * mu_s g (t - tb), the sign opposing the slip.
        double slip = BallMotionSlipX(before);
        double aSlide = -Math.Sign(slip) * MuS * G;
        double aRoll = -Math.Sign(va) * MuR * G;
        double ts = (va - aRoll * tAfter - vb + aSlide * tBefore) / (aSlide - aRoll);
        double vr = va - aRoll * (tAfter - ts);
        double dt = tAfter - ts;
        double xs = after.Position.X - vr * dt - 0.5 * aRoll * dt * dt;
        return (ts, xs - x0, vr);
    }

    // Steps to rest; returns the first ball's state and time at the last step boundary before it stopped.
    private static (BallState State, double Time) LastActiveStep(StandardSimulation sim)
    {
        var last = sim.Balls[0];
        double tLast = sim.Time;
        while (!sim.IsAtRest)
        {
            last = sim.Balls[0];
            tLast = sim.Time;
            sim.Step();
        }
        return (last, tLast);
    }

    private static double BallMotionSlipX(in BallState b) => b.Velocity.X - R * b.Spin.Y;

    [Theory]
    [MemberData(nameof(Steps))]
    public void CentreBallHitSlidesThenRolls(double dt)
    {
        double v0 = 2;
        double expectedTime = 2 * v0 / (7 * MuS * G);            // 0.291248 s
        double expectedDistance = 12 * v0 * v0 / (49 * MuS * G); // 0.499282 m
        double expectedSpeed = 5 * v0 / 7;                       // 1.428571 m/s
        var sim = Create("exact", dt, BigTable, null, "", Ball("cue", -4.5, 0, v0, 0));
        var (t, d, v) = SlideToRoll(sim, -4.5);
        output.WriteLine($"dt {dt:R}: sliding time {t:R} s, distance {d:R} m, rolling speed {v:R} m/s");
        AssertRelative(expectedTime, t, Tolerance, "sliding time");
        AssertRelative(expectedDistance, d, Tolerance, "sliding distance");
        AssertRelative(expectedSpeed, v, Tolerance, "rolling speed");
        Assert.Equal(0.291248, expectedTime, 6);
        Assert.Equal(0.499282, expectedDistance, 6);
        Assert.Equal(1.428571, expectedSpeed, 6);
    }

    [Theory]
    [MemberData(nameof(Steps))]
    public void RollingToRest(double dt)
    {
        double v = 5.0 * 2 / 7;
        double expectedTime = v / (MuR * G);            // 14.5624 s
        double expectedDistance = v * v / (2 * MuR * G); // 10.4017 m
        Assert.Equal(14.5624, expectedTime, 4);
        Assert.Equal(10.4017, expectedDistance, 4);
        // Along the diagonal of the 10 x 5 m table, the only straight line long enough.
        double ux = 9.9 / Math.Sqrt(9.9 * 9.9 + 4.9 * 4.9), uy = 4.9 / Math.Sqrt(9.9 * 9.9 + 4.9 * 4.9);
        var sim = Create("exact", dt, BigTable, null, "",
            Ball("cue", -4.95, -2.45, v * ux, v * uy, -v * uy / R, v * ux / R));
        Assert.Equal(MotionState.Rolling, sim.Balls[0].State);
        var (last, tLast) = LastActiveStep(sim);
        Assert.Empty(sim.Events.AsSpan().ToArray());
        double restTime = tLast + last.Velocity.Length / (MuR * G);
        double distance = Math.Sqrt(Math.Pow(sim.Balls[0].Position.X + 4.95, 2) + Math.Pow(sim.Balls[0].Position.Y + 2.45, 2));
        AssertRelative(expectedTime, restTime, Tolerance, "rolling time");
        AssertRelative(expectedDistance, distance, Tolerance, "rolling distance");
    }

    [Fact]
    public void EventSolverStopsAtTheExactRestTime()
    {
        double v = 5.0 * 2 / 7;
        double ux = 9.9 / Math.Sqrt(9.9 * 9.9 + 4.9 * 4.9), uy = 4.9 / Math.Sqrt(9.9 * 9.9 + 4.9 * 4.9);
        var sim = Create("event", 1.0 / 250, BigTable, null, "",
            Ball("cue", -4.95, -2.45, v * ux, v * uy, -v * uy / R, v * ux / R));
        RunToRest(sim);
        AssertRelative(v / (MuR * G), sim.Time, Tolerance, "rest time");
    }

    [Theory]
    [MemberData(nameof(Steps))]
    public void SpinDown(double dt)
    {
        double w = 10;
        double expected = w / (5 * (4.0 / 9 * R) * G / (2 * R)); // 0.917431 s
        Assert.Equal(0.917431, expected, 6);
        // The spec's check takes pooltool's mu_sp = 4/9 R (pool's cloth spins down at TP B.2's 10 rad/s^2).
        var sim = Create("exact", dt, BigTable, null, $"\"mu_sp\": {F(4.0 / 9 * R)}", Ball("cue", 0, 0, wz: w));
        Assert.Equal(MotionState.Spinning, sim.Balls[0].State);
        var (last, tLast) = LastActiveStep(sim);
        double restTime = tLast + Math.Abs(last.Spin.Z) / (10.0 / 9 * G);
        AssertRelative(expected, restTime, Tolerance, "spin-down time");
        Assert.Equal(0.0, sim.Balls[0].Position.X);
    }

    [Theory]
    [InlineData(-1.0, 1.0 / 30)]
    [InlineData(-1.0, 1.0 / 250)]
    [InlineData(-1.0, 1.0 / 4000)]
    [InlineData(2.0, 1.0 / 30)]
    [InlineData(2.0, 1.0 / 250)]
    [InlineData(2.0, 1.0 / 4000)]
    public void SlipLawEndsRollingAtV0MinusTwoSeventhsOfSlip(double spinFactor, double dt)
    {
        // R w_y = spinFactor * v0 along the rolling sense: -1 is backspin, 2 is over-spin.
        double v0 = 2;
        double wy = spinFactor * v0 / R;
        double u0 = v0 - R * wy;
        double expected = v0 - 2.0 / 7 * u0; // 0.857143 (backspin), 2.571429 (topspin)
        Assert.Equal(spinFactor < 0 ? 0.857143 : 2.571429, expected, 6);
        var sim = Create("exact", dt, BigTable, null, "", Ball("cue", -4.5, 0, v0, 0, 0, wy));
        var (_, _, v) = SlideToRoll(sim, -4.5);
        AssertRelative(expected, v, Tolerance, "rolling speed after the slip law");
    }

    [Fact]
    public void NaturalRollTipHeightGivesNoSlip()
    {
        var p = PhysicsParams.Default;
        var o = CueStrike.Strike(new ShotSpec(2.0, 30, 0, 0.4), p);
        var b = new BallState { Velocity = o.Velocity, Spin = o.Spin };
        var u = BallMotion.Slip(b, p.R);
        Assert.True(u.LengthXY < 1e-12 * o.Velocity.Length, $"slip {u.LengthXY}");
        Assert.True(o.Velocity.Length > 0);
    }

    [Theory]
    [InlineData(20.0, 0.2, 1.19936, 1e-5)]
    [InlineData(30.0, 0.5, 1.886, 1e-3)]
    public void SquirtAngle(double massRatio, double side, double expectedDeg, double tolerance)
    {
        double formula = Math.Atan(2.5 * side * Math.Sqrt(1 - side * side) / (1 + massRatio + 2.5 * (1 - side * side))) * 180 / Math.PI;
        Assert.Equal(expectedDeg, formula, 3);
        double deg = CueStrike.SquirtAngle(side, massRatio) * 180 / Math.PI;
        AssertRelative(expectedDeg, deg, tolerance, "squirt");
        // And the strike uses it: m_e = m / ratio, right english sends the ball left of the aim line.
        var p = PhysicsParams.Default with { CueEndMass = PhysicsParams.DefaultMass / massRatio };
        var o = CueStrike.Strike(new ShotSpec(2.0, 0, side, 0), p);
        AssertRelative(expectedDeg, Math.Atan2(o.Velocity.Y, o.Velocity.X) * 180 / Math.PI, tolerance, "strike direction");
    }

    [Fact]
    public void CentreStrikeSpeedIsElasticCueBallImpact()
    {
        var p = PhysicsParams.Default;
        var o = CueStrike.Strike(new ShotSpec(2.0, 0), p);
        AssertRelative(2 * 2.0 / (1 + p.M / p.CueMass), o.Velocity.X, 1e-12, "ball speed");
        Assert.Equal(0, o.Spin.Length, 12);
    }
}
