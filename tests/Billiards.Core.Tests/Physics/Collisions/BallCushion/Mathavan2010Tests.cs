using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions.BallCushion;
using static Billiards.Core.Tests.Physics.Collisions.CollisionKit;

namespace Billiards.Core.Tests.Physics.Collisions.BallCushion;

/// <summary>Mathavan, Jackson and Parkin (2010): the limits of its equations, its figures' shape and the error of its step.</summary>
public class Mathavan2010Tests
{
    // The paper's ball and cushion: a snooker ball (0.1406 kg, 26.25 mm), h = 7R/5 (sin theta = 2/5),
    // e = 0.98, table friction 0.212, cushion friction 0.14.
    private static readonly PhysicsParams Paper = PhysicsParams.Default with { M = 0.1406, R = 0.02625, EC = 0.98, MuS = 0.212, FC = 0.14 };
    private const double PaperHeight = 0.03675;

    // The paper's inputs: speed V0, incidence alpha from the cushion line (90 = head-on), topspin
    // w_T = kT V0 / R along the line of travel, sidespin w_S = kS V0 / R.
    private static (double Speed, double AngleDeg) Rebound(double alphaDeg, double kT, double kS, double v0 = 1)
    {
        double a = alphaDeg * Math.PI / 180;
        var v = new Vec3(v0 * Math.Sin(a), v0 * Math.Cos(a), 0);
        var spin = Vec3.Cross(Vec3.UnitZ, v) / Paper.R * kT + new Vec3(0, 0, kS * v0 / Paper.R);
        var b = new BallState { Position = new Vec3(0, 0, Paper.R), Velocity = v, Spin = spin };
        Mathavan2010.Instance.Resolve(ref b, Normal, PaperHeight, Paper);
        // The rebound angle from the cushion line, past 90 when the ball comes back against its run.
        return (b.Velocity.LengthXY, Math.Atan2(-b.Velocity.X, b.Velocity.Y) * 180 / Math.PI);
    }

    [Fact]
    public void SlidingSidespinAtTheEquatorDeflectsByFrictionTimesTheNormalImpulse()
    {
        // h = R and a head-on stun ball with w_z = 2 v / R: the contact slides sideways throughout
        // (the slip falls by 7/2 f_c (1 + e) v < 2 v), the table carries no extra load, so the side
        // velocity is f_c (1 + e) v and the normal e v: the rebound leaves atan(f_c (1 + e) / e) off the normal.
        foreach (double e in new[] { 0.85, 0.98 })
        {
            var p = P with { EC = e, FC = 0.14 };
            var b = Incoming(1.5, 0, 0, 2);
            Mathavan2010.Instance.Resolve(ref b, Normal, R, p);
            AssertClose(new Vec3(-e * 1.5, -0.14 * (1 + e) * 1.5, 0), b.Velocity, 1e-12, $"rebound at e = {e}");
            Assert.Equal(2 * 1.5 / R - 2.5 * 0.14 * (1 + e) * 1.5 / R, b.Spin.Z, 1e-9);
        }
    }

    [Fact]
    public void FollowAtTheEquatorLiftsTheBallOffTheClothAndKeepsTheRestitution()
    {
        // h = R, head-on with natural roll: the contact point moves down, cushion friction pushes the
        // ball up, the table carries nothing, so the normal rebound is e v and friction only takes
        // f_c (1 + e) m v R / I of the roll.
        var b = Incoming(1, 0, 1, 0);
        double roll = b.Spin.Y;
        Mathavan2010.Instance.Resolve(ref b, Normal, R, P);
        AssertClose(new Vec3(-P.EC, 0, 0), b.Velocity, 1e-12, "rebound");
        Assert.Equal(roll - P.FC * (1 + P.EC) * P.M * R / P.Inertia, b.Spin.Y, 1e-9);
        Assert.Equal(0, b.Spin.Z, 12);
    }

    [Fact]
    public void TheFiguresShapesHold()
    {
        // The shape of the paper's rebound figures (V0 = 1 m/s, incidence 0-90 deg): a head-on ball
        // without sidespin comes straight back whatever its topspin; sidespin of either sense
        // deflects a head-on ball by the same angle to either side; follow (kT = 0, 1, 2) raises
        // the rebound speed at every incidence.
        foreach (double kT in new[] { -1.0, 0, 1, 2 })
        {
            Assert.Equal(90, Rebound(90, kT, 0).AngleDeg, 6);
        }
        foreach (double kS in new[] { 1.0, 2 })
        {
            Assert.Equal(180, Rebound(90, 1, kS).AngleDeg + Rebound(90, 1, -kS).AngleDeg, 6);
            Assert.NotEqual(90, Rebound(90, 1, kS).AngleDeg, 0);
        }
        for (double alpha = 10; alpha <= 90; alpha += 10)
        {
            double stun = Rebound(alpha, 0, 0).Speed, roll = Rebound(alpha, 1, 0).Speed, twice = Rebound(alpha, 2, 0).Speed;
            Assert.True(stun < roll && roll < twice, $"at {alpha} deg: {stun}, {roll}, {twice}");
        }
    }

    [Fact]
    public void TheStepLeavesTheStatedError()
    {
        // Against the extrapolation at 16 times finer steps, over the range the remarks state.
        double worstV = 0, worstW = 0;
        foreach (double speed in new[] { 0.5, 1, 2, 4 })
        {
            foreach (double angle in new[] { 0.0, 15, 30, 45, 60, 75, 85 })
            {
                foreach (double follow in new[] { -1.0, 0, 1, 2 })
                {
                    foreach (double side in new[] { -1.0, 0, 1 })
                    {
                        var b = Incoming(speed, angle, follow, side);
                        var fine = b;
                        Mathavan2010.Instance.Resolve(ref b, Normal, Height, P);
                        Mathavan2010.ResolveExtrapolated(ref fine, Normal, Height, P, 16 * Mathavan2010.CompressionSteps);
                        worstV = Math.Max(worstV, (b.Velocity - fine.Velocity).Length / speed);
                        worstW = Math.Max(worstW, (b.Spin - fine.Spin).Length * R / speed);
                    }
                }
            }
        }
        Assert.True(worstV <= Mathavan2010.StepErrorBound, $"velocity error {worstV:E2} of the speed");
        Assert.True(worstW <= Mathavan2010.SpinErrorBound, $"spin error {worstW:E2} of speed / R");
        // And the bound is not loose by more than a factor of 3: it says what the step leaves.
        Assert.True(worstV > Mathavan2010.StepErrorBound / 3, $"velocity error {worstV:E2} is far below the stated bound");
    }
}
