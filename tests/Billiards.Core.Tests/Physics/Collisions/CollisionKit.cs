using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;

namespace Billiards.Core.Tests.Physics.Collisions;

/// <summary>Balls, cushions and the quantities the collision model tests compare.</summary>
internal static class CollisionKit
{
    public static readonly PhysicsParams P = PhysicsParams.Default;
    public static readonly double R = P.R;

    /// <summary>The default cushion's contact height, 0.64 of the ball's diameter (m).</summary>
    public static readonly double Height = 0.64 * 2 * R;

    /// <summary>The foot cushion: at +x, its normal pointing back onto the bed.</summary>
    public static readonly Vec3 Normal = new(-1, 0, 0);

    public static IEnumerable<object[]> CushionModels() => ModelRegistry.BallCushionModels.Select(m => new object[] { m.Name });

    public static IEnumerable<object[]> BallBallModels() => ModelRegistry.BallBallModels.Select(m => new object[] { m.Name });

    public static IBallCushionModel Cushion(string name) => ModelRegistry.FindBallCushion(name)!;

    public static IBallBallModel BallBall(string name) => ModelRegistry.FindBallBall(name)!;

    /// <summary>
    /// A ball moving into the foot cushion at <paramref name="speed"/> (m/s), <paramref name="angleDeg"/>
    /// from the cushion's normal (0 = head-on), with <paramref name="follow"/> times natural roll
    /// (negative: draw) and side spin w_z = <paramref name="side"/> speed / R.
    /// </summary>
    public static BallState Incoming(double speed, double angleDeg, double follow = 0, double side = 0)
    {
        double a = angleDeg * Math.PI / 180;
        var v = new Vec3(speed * Math.Cos(a), speed * Math.Sin(a), 0);
        var spin = Vec3.Cross(Vec3.UnitZ, v) / R * follow + new Vec3(0, 0, side * speed / R);
        return new BallState { Position = new Vec3(0, 0, R), Velocity = v, Spin = spin };
    }

    /// <summary>Kinetic energy, translation and rotation (J).</summary>
    public static double Energy(in BallState b) => 0.5 * P.M * b.Velocity.LengthSquared + 0.5 * P.Inertia * b.Spin.LengthSquared;

    /// <summary>The mirror image in the plane y = 0: y velocity flips, and so do the spin's x and z (a pseudovector).</summary>
    public static BallState Mirror(BallState b) => b with
    {
        Position = b.Position with { Y = -b.Position.Y },
        Velocity = b.Velocity with { Y = -b.Velocity.Y },
        Spin = new Vec3(-b.Spin.X, b.Spin.Y, -b.Spin.Z),
    };

    public static void AssertClose(Vec3 expected, Vec3 actual, double tolerance, string what)
    {
        Assert.True((expected - actual).Length <= tolerance, $"{what}: expected {expected}, got {actual} (tolerance {tolerance})");
    }
}
