using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Physics.Collisions.BallPocket;
using Billiards.Core.Physics.Collisions.BallTable;
using static Billiards.Core.Tests.Physics.Collisions.CollisionKit;

namespace Billiards.Core.Tests.Physics.Collisions.BallTable;

/// <summary>
/// The ball-table and ball-pocket models of the registry, against the rigid sphere's point impact
/// on a plane (the frictional landing's remarks): e_t on the normal speed, Coulomb or no-slip
/// friction, and the same answer for a surface of any tilt.
/// </summary>
public class BallTableModelTests
{
    public static IEnumerable<object[]> TableModels() => ModelRegistry.BallTableModels.Select(m => new object[] { m.Name });

    private static IBallTableModel Table(string name) => ModelRegistry.FindBallTable(name)!;

    [Fact]
    public void TheRegistryListsTheLandingAndThePocketDropAndTheDefaultsUseThem()
    {
        Assert.Equal(["frictional-inelastic"], ModelRegistry.BallTableNames);
        Assert.Equal(["canonical"], ModelRegistry.BallPocketNames);
        Assert.Same(FrictionalLanding.Instance, ModelRegistry.FindBallTable("frictional-inelastic"));
        Assert.Same(CanonicalPocket.Instance, ModelRegistry.FindBallPocket("canonical"));
        Assert.Null(ModelRegistry.FindBallTable("newton"));
        Assert.Null(ModelRegistry.FindBallPocket("newton"));
        Assert.Same(ModelRegistry.BallTableModels[0], InteractionModels.Default.BallTable);
        Assert.Same(ModelRegistry.BallPocketModels[0], InteractionModels.Default.BallPocket);
    }

    /// <summary>A ball without spin falling straight onto the bed at 2 m/s leaves at e_t times that, with nothing else changed.</summary>
    [Theory]
    [MemberData(nameof(TableModels))]
    public void AStraightDropReboundsAtETTimesItsSpeed(string name)
    {
        var b = new BallState { Position = new Vec3(0, 0, R), Velocity = new Vec3(0, 0, -2) };
        double impact = Table(name).Resolve(ref b, Vec3.UnitZ, P);
        Assert.Equal(2, impact, 15);
        AssertClose(new Vec3(0, 0, P.ET * 2), b.Velocity, 1e-15, "velocity");
        AssertClose(Vec3.Zero, b.Spin, 1e-15, "spin");
    }

    /// <summary>
    /// A landing with little slip stops it (no-slip: the contact point leaves with no tangential
    /// velocity, v and R w along it as 5/7 and 2/7); with much slip the friction is Coulomb's,
    /// mu_s (1 + e_t) v_n off the tangential speed. Energy never rises.
    /// </summary>
    [Theory]
    [MemberData(nameof(TableModels))]
    public void TheLandingsFrictionStopsASmallSlipAndIsCoulombsForALargeOne(string name)
    {
        var small = new BallState { Position = new Vec3(0, 0, R), Velocity = new Vec3(0.1, 0, -2) };
        double before = Energy(small);
        Table(name).Resolve(ref small, Vec3.UnitZ, P);
        double slip = small.Velocity.X - R * small.Spin.Y;
        Assert.True(Math.Abs(slip) < 1e-15, $"slip left {slip}");
        Assert.Equal(0.1 * 5 / 7, small.Velocity.X, 15);
        Assert.True(Energy(small) <= before);

        var large = new BallState { Position = new Vec3(0, 0, R), Velocity = new Vec3(3, 0, -2) };
        before = Energy(large);
        Table(name).Resolve(ref large, Vec3.UnitZ, P);
        Assert.Equal(3 - P.MuS * (1 + P.ET) * 2, large.Velocity.X, 14);
        Assert.Equal(2.5 / R * P.MuS * (1 + P.ET) * 2, large.Spin.Y, 10); // towards rolling on
        Assert.True(Energy(large) <= before);
    }

    /// <summary>
    /// The interface is in space: a surface tilted any way gives the bed's answer turned with it
    /// (velocity and spin rotate alike), to round-off; so a rail's top or a slope needs no model of its own.
    /// </summary>
    [Theory]
    [MemberData(nameof(TableModels))]
    public void ATiltedSurfaceGivesTheBedsAnswerTurned(string name)
    {
        // Rodrigues' rotation by 0.9 rad about (1, 2, 3).
        var axis = new Vec3(1, 2, 3).Normalized();
        double c = Math.Cos(0.9), s = Math.Sin(0.9);
        Vec3 Rotate(Vec3 v) => v * c + Vec3.Cross(axis, v) * s + axis * (Vec3.Dot(axis, v) * (1 - c));
        foreach (var (v, w) in new[] { (new Vec3(1.5, -0.4, -2), new Vec3(30, 10, -20)), (new Vec3(0.05, 0.02, -1), Vec3.Zero), (new Vec3(4, 1, -0.5), new Vec3(-50, 80, 5)) })
        {
            var flat = new BallState { Velocity = v, Spin = w };
            double impactFlat = Table(name).Resolve(ref flat, Vec3.UnitZ, P);
            var tilted = new BallState { Velocity = Rotate(v), Spin = Rotate(w) };
            double impactTilted = Table(name).Resolve(ref tilted, Rotate(Vec3.UnitZ), P);
            Assert.Equal(impactFlat, impactTilted, 12);
            AssertClose(Rotate(flat.Velocity), tilted.Velocity, 1e-12, "velocity");
            AssertClose(Rotate(flat.Spin), tilted.Spin, 1e-9, "spin");
        }
    }

    /// <summary>The canonical drop takes the ball out of play at once, where it is, and reports its speed.</summary>
    [Fact]
    public void TheCanonicalDropStopsTheBallInItsPocket()
    {
        var b = new BallState { Position = new Vec3(1.2, 0.6, 0.05), Velocity = new Vec3(1, 2, -2), Spin = new Vec3(5, 6, 7), State = MotionState.Airborne, Pocket = -1 };
        double speed = CanonicalPocket.Instance.Drop(ref b, 4);
        Assert.Equal(3, speed, 15);
        Assert.Equal(MotionState.Pocketed, b.State);
        Assert.Equal(4, b.Pocket);
        Assert.Equal(Vec3.Zero, b.Velocity);
        Assert.Equal(Vec3.Zero, b.Spin);
        Assert.Equal(new Vec3(1.2, 0.6, 0.05), b.Position);
    }
}
