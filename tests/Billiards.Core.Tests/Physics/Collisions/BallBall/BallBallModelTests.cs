using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions.BallBall;
using static Billiards.Core.Tests.Physics.Collisions.CollisionKit;

namespace Billiards.Core.Tests.Physics.Collisions.BallBall;

/// <summary>What every ball-ball model of the registry must do, and the Mathavan 2014 model's own limits.</summary>
public class BallBallModelTests
{
    public static IEnumerable<object[]> Models() => BallBallModels();

    // A cue ball moving +x at `speed` into a resting object ball at the cut angle, with follow and side as in CollisionKit.
    private static (BallState A, BallState B) Shot(double speed, double cutDeg, double follow = 0, double side = 0)
    {
        double c = cutDeg * Math.PI / 180;
        var a = Incoming(speed, 0, follow, side);
        var b = new BallState { Position = new Vec3(2 * R * Math.Cos(c), 2 * R * Math.Sin(c), R) };
        return (a, b);
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void AHeadOnStunShotTradesSpeedWithTheRestitutionAndMakesNoSpin(string name)
    {
        foreach (double e in new[] { 0.5, 0.95 })
        {
            var (a, b) = Shot(2, 0);
            CollisionKit.BallBall(name).Resolve(ref a, ref b, P with { EB = e });
            AssertClose(new Vec3((1 - e), 0, 0), a.Velocity, 1e-12, $"{name} cue ball at e = {e}");
            AssertClose(new Vec3((1 + e), 0, 0), b.Velocity, 1e-12, $"{name} object ball at e = {e}");
            AssertClose(Vec3.Zero, a.Spin, 1e-12, $"{name} cue ball spin");
            AssertClose(Vec3.Zero, b.Spin, 1e-12, $"{name} object ball spin");
        }
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void NoCollisionAddsEnergy(string name)
    {
        var model = CollisionKit.BallBall(name);
        foreach (double speed in new[] { 0.2, 1, 3, 8 })
        {
            for (double cut = 0; cut <= 85; cut += 5)
            {
                foreach (double follow in new[] { -2.0, -1, 0, 1, 2 })
                {
                    foreach (double side in new[] { -1.0, 0, 1 })
                    {
                        var (a, b) = Shot(speed, cut, follow, side);
                        double before = Energy(a) + Energy(b);
                        model.Resolve(ref a, ref b, P);
                        Assert.True(Energy(a) + Energy(b) <= before * (1 + 1e-12), $"{name}: energy rose at {speed} m/s, cut {cut}, follow {follow}, side {side}");
                        Assert.Equal(0, a.Velocity.Z);
                        Assert.Equal(0, b.Velocity.Z);
                    }
                }
            }
        }
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void TheMirrorShotGivesTheMirrorImage(string name)
    {
        foreach (var (speed, cut, follow, side) in new[] { (2.0, 30.0, 0.0, 0.0), (1.0, 50.0, 1.0, 0.5), (4.0, 15.0, -1.0, -1.0) })
        {
            var (a, b) = Shot(speed, cut, follow, side);
            var (ma, mb) = (Mirror(a), Mirror(b));
            CollisionKit.BallBall(name).Resolve(ref a, ref b, P);
            CollisionKit.BallBall(name).Resolve(ref ma, ref mb, P);
            AssertClose(Mirror(a).Velocity, ma.Velocity, 1e-12, $"{name} cue ball");
            AssertClose(Mirror(b).Velocity, mb.Velocity, 1e-12, $"{name} object ball");
            AssertClose(Mirror(a).Spin, ma.Spin, 1e-9, $"{name} cue ball spin");
            AssertClose(Mirror(b).Spin, mb.Spin, 1e-9, $"{name} object ball spin");
        }
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void ACutStunShotThrowsTheObjectBallForward(string name)
    {
        // Cut-induced throw: friction drags the object ball towards the cue ball's direction, so it
        // leaves at less than the cut angle off the cue ball's line (TP A-14), by a few degrees.
        var (a, b) = Shot(1, 30);
        CollisionKit.BallBall(name).Resolve(ref a, ref b, P);
        double angle = Math.Atan2(b.Velocity.Y, b.Velocity.X) * 180 / Math.PI;
        Assert.InRange(angle, 30 - 6, 30 - 0.2);
    }

    [Fact]
    public void WithoutTableFrictionMathavanConservesMomentum()
    {
        // The balls' forces are equal and opposite; only the cloth takes momentum.
        var p = P with { MuS = 0 };
        var (a, b) = Shot(3, 40, 1.5, 1);
        var before = a.Velocity + b.Velocity;
        FrictionalMathavan.Instance.Resolve(ref a, ref b, p);
        AssertClose(before, a.Velocity + b.Velocity, 1e-12, "momentum");
    }

    [Fact]
    public void TheMathavanStepLeavesTheStatedError()
    {
        double worst = 0;
        foreach (double speed in new[] { 0.5, 2, 8 })
        {
            foreach (double cut in new[] { 0.0, 20, 40, 60, 80 })
            {
                foreach (double follow in new[] { -1.0, 0, 1 })
                {
                    foreach (double side in new[] { -1.0, 0, 1 })
                    {
                        var (a, b) = Shot(speed, cut, follow, side);
                        var (fa, fb) = (a, b);
                        FrictionalMathavan.Instance.Resolve(ref a, ref b, P);
                        FrictionalMathavan.Resolve(ref fa, ref fb, P, 64 * FrictionalMathavan.CompressionSteps);
                        worst = Math.Max(worst, Math.Max((a.Velocity - fa.Velocity).Length, (b.Velocity - fb.Velocity).Length) / speed);
                    }
                }
            }
        }
        Assert.True(worst <= FrictionalMathavan.StepErrorBound, $"velocity error {worst:E2} of the speed");
        Assert.True(worst > FrictionalMathavan.StepErrorBound / 3, $"velocity error {worst:E2} is far below the stated bound");
    }

    [Fact]
    public void AlciatoresFrictionIsTakenAtEachStep()
    {
        var (a, b) = Shot(2, 30);
        var (ca, cb) = (a, b);
        FrictionalMathavan.Instance.Resolve(ref a, ref b, P with { MuBModel = BallBallFriction.Alciatore });
        FrictionalMathavan.Instance.Resolve(ref ca, ref cb, P);
        Assert.NotEqual(ca.Velocity, a.Velocity);
    }
}
