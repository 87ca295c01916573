using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Collisions.BallBall;
using static Billiards.Core.Tests.Physics.Collisions.CollisionKit;

namespace Billiards.Core.Tests.Physics.Collisions.BallBall;

/// <summary>
/// Every ball-ball model of the registry in the air: the line of centres in space, no table
/// contact for a ball in the air (what the engine used to bypass the chosen model for).
/// </summary>
public class BallBallInTheAirTests
{
    public static IEnumerable<object[]> Models() => BallBallModels();

    // Two balls in the air touching along `n` (from a to b), a at the origin 0.3 m up.
    private static (BallState A, BallState B) InTheAir(Vec3 n, Vec3 va, Vec3 vb, Vec3 wa = default, Vec3 wb = default)
    {
        var a = new BallState { Position = new Vec3(0, 0, 0.3), Velocity = va, Spin = wa, State = MotionState.Airborne };
        var b = new BallState { Position = a.Position + n * (2 * R), Velocity = vb, Spin = wb, State = MotionState.Airborne };
        return (a, b);
    }

    /// <summary>
    /// Without friction or spin, two balls in the air meeting along a line 40 deg off the bed trade
    /// their normal speeds by e_b (v_a' = v_a + n ((1 + e)/2)(v_b - v_a) . n) and keep the rest,
    /// vertical parts included; to the Mathavan step's stated error.
    /// </summary>
    [Theory]
    [MemberData(nameof(Models))]
    public void FrictionlessBallsInTheAirTradeTheirNormalSpeedsInSpace(string name)
    {
        var n = new Vec3(Math.Cos(0.7), 0.2, -Math.Sin(0.7)).Normalized();
        var va = new Vec3(2, 0.5, -1);
        var vb = new Vec3(-0.5, 0, 1.5);
        var (a, b) = InTheAir(n, va, vb);
        var p = P with { MuB = 0 };
        CollisionKit.BallBall(name).Resolve(ref a, ref b, p);
        double approach = Vec3.Dot(va - vb, n);
        var change = n * (0.5 * (1 + p.EB) * approach);
        double tolerance = FrictionalMathavan.StepErrorBound * approach;
        AssertClose(va - change, a.Velocity, tolerance, $"{name}: ball a");
        AssertClose(vb + change, b.Velocity, tolerance, $"{name}: ball b");
        AssertClose(Vec3.Zero, a.Spin + b.Spin, 1e-12, $"{name}: spin");
    }

    /// <summary>
    /// With friction and spin, nothing outside acts on two balls in the air: their momentum in
    /// space is kept (to round-off) and their energy never rises.
    /// </summary>
    [Theory]
    [MemberData(nameof(Models))]
    public void BallsInTheAirKeepTheirMomentumInSpace(string name)
    {
        var n = new Vec3(0.6, -0.3, 0.5).Normalized();
        var (a, b) = InTheAir(n, new Vec3(3, -1, 1), new Vec3(-1, 0.5, -2), new Vec3(40, -20, 60), new Vec3(-10, 30, 5));
        var before = a.Velocity + b.Velocity;
        double energy = Energy(a) + Energy(b);
        CollisionKit.BallBall(name).Resolve(ref a, ref b, P);
        AssertClose(before, a.Velocity + b.Velocity, 1e-12, $"{name}: momentum");
        Assert.True(Energy(a) + Energy(b) <= energy * (1 + 1e-12), $"{name}: energy rose");
        Assert.True(Math.Abs(a.Velocity.Z - 1) > 1e-3, $"{name}: the impact should change the vertical speeds");
    }

    /// <summary>
    /// A ball in the air coming down onto one at rest on the bed, 30 deg above the bed plane: the
    /// one on the bed is pushed away along the bed and into it (never lifted), the one in the air
    /// thrown back up and away.
    /// </summary>
    [Theory]
    [MemberData(nameof(Models))]
    public void ABallFromTheAirDrivesABallOnTheBedAwayAndIntoIt(string name)
    {
        var n = new Vec3(Math.Cos(Math.PI / 6), 0, -Math.Sin(Math.PI / 6));
        var b = new BallState { Position = new Vec3(0, 0, R), State = MotionState.Stationary };
        var a = new BallState { Position = b.Position - n * (2 * R), Velocity = new Vec3(1, 0, -2), State = MotionState.Airborne };
        CollisionKit.BallBall(name).Resolve(ref a, ref b, P);
        Assert.True(b.Velocity.X > 0.1, $"{name}: the ball on the bed should move away, {b.Velocity}");
        Assert.True(b.Velocity.Z <= 0, $"{name}: the ball on the bed was lifted, {b.Velocity}");
        Assert.True(a.Velocity.Z > -2 && a.Velocity.X < 1, $"{name}: the ball in the air should be thrown back, {a.Velocity}");
    }
}
