using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using static Billiards.Core.Tests.Physics.Collisions.CollisionKit;

namespace Billiards.Core.Tests.Physics.Collisions.BallCushion;

/// <summary>What every cushion model of the registry must do: lose energy, leave the cushion, mirror, restitute.</summary>
public class CushionModelTests
{
    public static IEnumerable<object[]> Models() => CushionModels();

    [Theory]
    [MemberData(nameof(Models))]
    public void NoImpactAddsEnergyAndEveryBallLeavesTheCushion(string name)
    {
        var model = Cushion(name);
        foreach (double speed in new[] { 0.1, 0.5, 1, 2, 4, 8, 12 })
        {
            for (double angle = 0; angle <= 89; angle += 4)
            {
                foreach (double follow in new[] { -2.0, -1, 0, 1, 2 })
                {
                    foreach (double side in new[] { -2.0, -1, 0, 1, 2 })
                    {
                        var b = Incoming(speed, angle, follow, side);
                        double before = Energy(b);
                        model.Resolve(ref b, Normal, Height, P);
                        Assert.True(Energy(b) <= before * (1 + 1e-12), $"{name}: energy rose at {speed} m/s, {angle} deg, follow {follow}, side {side}");
                        Assert.True(b.Velocity.X < 0, $"{name}: the ball did not leave at {speed} m/s, {angle} deg, follow {follow}, side {side}");
                        Assert.Equal(0, b.Velocity.Z);
                    }
                }
            }
        }
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void TheMirrorShotReboundsAsTheMirrorImage(string name)
    {
        var model = Cushion(name);
        foreach (var (speed, angle, follow, side) in new[] { (2.0, 30.0, 0.0, 0.0), (1.0, 60.0, 1.0, 0.5), (5.0, 10.0, -1.0, -1.5), (0.7, 75.0, 2.0, 1.0) })
        {
            var b = Incoming(speed, angle, follow, side);
            var m = Mirror(b);
            model.Resolve(ref b, Normal, Height, P);
            model.Resolve(ref m, Normal, Height, P);
            AssertClose(Mirror(b).Velocity, m.Velocity, 1e-12, $"{name} velocity");
            AssertClose(Mirror(b).Spin, m.Spin, 1e-9, $"{name} spin");
        }
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void AHeadOnStunShotAtTheEquatorReboundsWithTheRestitutionAndNoSpin(string name)
    {
        // With the cushion touching the ball at its equator (h = R) nothing slips at a stun shot
        // head-on: every model then reduces to the normal restitution e_c and creates no spin.
        var model = Cushion(name);
        foreach (double e in new[] { 0.5, 0.85, 0.98 })
        {
            var p = P with { EC = e };
            var b = Incoming(2, 0);
            model.Resolve(ref b, Normal, R, p);
            AssertClose(new Vec3(-2 * e, 0, 0), b.Velocity, 1e-12, $"{name} rebound at e = {e}");
            AssertClose(Vec3.Zero, b.Spin, 1e-12, $"{name} spin at e = {e}");
        }
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void ABallMovingAwayIsLeftAlone(string name)
    {
        var b = Incoming(1, 0, 1, 1);
        b.Velocity = -b.Velocity;
        var before = b;
        Cushion(name).Resolve(ref b, Normal, Height, P);
        Assert.Equal(before.Velocity, b.Velocity);
        Assert.Equal(before.Spin, b.Spin);
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void RightEnglishThrowsTheReboundToTheRight(string name)
    {
        // Moving +x with w_z > 0: the contact slides towards +y, so friction pushes the ball to -y.
        var b = Incoming(2, 0, 0, 1);
        Cushion(name).Resolve(ref b, Normal, Height, P);
        Assert.True(b.Velocity.Y < 0, $"{name}: vy = {b.Velocity.Y}");
    }
}
