using System.Numerics;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Setup;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Physics.Thesis.ThesisKit;

namespace Billiards.Core.Tests.Physics.Thesis;

/// <summary>Formel 20-29 with Listings 2-3 (seed 4.3.4), and the rails they run against.</summary>
public class RailCollisionTests
{
    private static readonly Vector3 FootNormal = new(-1, 0, 0); // the foot cushion faces -x
    private static readonly float Cos30 = MathF.Sqrt(3) / 2;

    private static Vector3 Dir(float degrees, float zSign) =>
        new(MathF.Cos(degrees * MathF.PI / 180), 0, zSign * MathF.Sin(degrees * MathF.PI / 180));

    [Fact]
    public void WithoutEffetTheReboundIsTheMirrorImageTimes09()
    {
        // 200 cm/s at 30 deg to the normal: alpha = 30, h = y x n = (0, 0, 1), dir = n + h tan 30
        // = (-cos 30, 0, sin 30) normalised: the reflection of Formel 21; times 0.9 * 200 = 180.
        var v = PhysicsEngine.Rebound(200 * Dir(30, 1), FootNormal, true, null);
        AssertVector(180 * new Vector3(-Cos30, 0, 0.5f), v);
    }

    [Fact]
    public void SideEffetWidensTheAngleComingFromOneSide()
    {
        var queue = new ThesisCue { EX = 1, EY = 1 };
        // c = v x n has c.y = -sin 30 < 0: alpha += e_x 0.3 f, f = 200 / 4 = 50: 30 + 15 = 45 deg.
        var v = PhysicsEngine.Rebound(200 * Dir(30, 1), FootNormal, true, queue);
        AssertVector(180 * new Vector3(-MathF.Sqrt(0.5f), 0, MathF.Sqrt(0.5f)), v);
        Assert.Equal(0.2f, queue.EX, 1e-6f);   // e_x *= 0.2
        Assert.Equal(-0.2f, queue.EY, 1e-6f);  // e_y *= -0.2
    }

    [Fact]
    public void SideEffetNarrowsTheAngleComingFromTheOtherSide()
    {
        var queue = new ThesisCue { EX = 1 };
        // v = 200 (cos 30, 0, -sin 30): c.y = +sin 30 > 0: alpha -= 15 -> 15 deg, h = n x y = (0, 0, -1).
        var v = PhysicsEngine.Rebound(200 * Dir(30, -1), FootNormal, true, queue);
        AssertVector(180 * new Vector3(-MathF.Cos(MathF.PI / 12), 0, -MathF.Sin(MathF.PI / 12)), v);
    }

    [Fact]
    public void TheReboundAngleIsCappedAt89Degrees()
    {
        var queue = new ThesisCue { EX = 2.86f };
        // |v| = 400: f = 100; alpha = 80 + 2.86 * 0.3 * 100 = 165.8 -> 89; dir = (-cos 89, 0, sin 89), * 360.
        var v = PhysicsEngine.Rebound(400 * Dir(80, 1), FootNormal, true, queue);
        float a = 89 * MathF.PI / 180;
        AssertVector(360 * new Vector3(-MathF.Cos(a), 0, MathF.Sin(a)), v);
    }

    [Fact]
    public void ALargeOppositeEffetMaySendTheBallAcrossTheNormal()
    {
        // The listing caps alpha from above only: 30 + (-2.86) * 0.3 * 100 = -55.8 deg,
        // tan(-55.8 deg) < 0 flips h: the ball comes off on the other side of the normal.
        var queue = new ThesisCue { EX = -2.86f };
        var v = PhysicsEngine.Rebound(400 * Dir(30, 1), FootNormal, true, queue);
        float a = -55.8f * MathF.PI / 180;
        AssertVector(360 * new Vector3(-MathF.Cos(a), 0, MathF.Sin(a)), v);
        Assert.True(v.Z < 0);
    }

    [Fact]
    public void APocketBackWallKeepsAHundredthOfTheHorizontalSpeed()
    {
        var v = PhysicsEngine.Rebound(200 * Dir(30, 1), FootNormal, false, null);
        AssertVector(1.8f * new Vector3(-Cos30, 0, 0.5f), v, 1e-4f);
    }

    [Fact]
    public void ABallThatCrossedTheFootCushionIsPutBackOnItAndRebounds()
    {
        // The foot cushion's triangles lie at x = 122.5 - 2.86 = 119.64. The ball is 0.5 cm past,
        // moving (100, 0, 50): the line meets the plane at t = -0.005 s, at z = 10 - 0.25.
        var ball = At(1, 120.14f, 10, vx: 100, vz: 50);
        var engine = Engine("thesis", ball);
        int hit = engine.CalculateRailCollision(ball);
        Assert.Equal("foot", Initializer.CushionNames[engine.Rails[hit].Feature]);
        AssertVector(new Vector3(119.64f, Y, 9.75f), ball.Position, 1e-4f);
        AssertVector(new Vector3(-90, 0, 45), ball.Velocity); // mirror image, times 0.9
        var e = Assert.Single(engine.Events!.AsSpan().ToArray());
        Assert.Equal(EventKind.BallCushion, e.Kind);
        Assert.Equal(1.0, e.Speed, 1e-6); // normal approach 100 cm/s
    }

    [Fact]
    public void ABallInFrontOfEveryCushionIsLeftAlone()
    {
        var ball = At(0, 119, 10, vx: 100, vz: 50);
        var engine = Engine("thesis", ball);
        engine.Queue.EX = 1;
        Assert.Equal(-1, engine.CalculateRailCollision(ball));
        Assert.Equal(new Vector3(100, 0, 50), ball.Velocity);
        Assert.Equal(1, engine.Queue.EX);
    }

    // The foot-right corner jaw: from the nose end (122.5, zn), zn = 63.5 + 6.5 - 7.75 - 6.5 / tan 35,
    // at 35 deg to the foot cushion, direction (sin 35, cos 35); its triangles lie 2.86 towards the
    // balls along the normal (-cos 35, sin 35). Where does that line reach z = 57?
    private static float JawXAt(float z)
    {
        double a = 35 * Math.PI / 180;
        double zn = 63.5 + 6.5 - 7.75 - 6.5 / Math.Tan(a);                    // 52.967
        double x0 = 122.5 - 2.86 * Math.Cos(a), z0 = zn + 2.86 * Math.Sin(a);   // (120.157, 54.607)
        double s = (z - z0) / Math.Cos(a);
        return (float)(x0 + s * Math.Sin(a));                                   // 121.833 at z = 57
    }

    [Fact]
    public void AtACornerPocketTheNearestOfSeveralCrossingsWins()
    {
        var rails = Initializer.InitRails(TableSpec.FromPreset("thesis"));
        // Along z = 57 the line of motion crosses the foot-right jaw (3.83 cm ahead) and, far behind,
        // the head-right jaw; the foot cushion ends before z = 57 and the long cushion is parallel.
        int k = PhysicsEngine.FindNearestHit(rails, new Vector3(118, Y, 57), new Vector3(100, 0, 0), out var point);
        Assert.Equal("foot-right-jaw", Initializer.CushionNames[rails[k].Feature]);
        AssertVector(new Vector3(JawXAt(57), Y, 57), point);
        // The mirror image: now the nearer crossing is the one later in the list.
        k = PhysicsEngine.FindNearestHit(rails, new Vector3(-118, Y, 57), new Vector3(-100, 0, 0), out point);
        Assert.Equal("head-right-jaw", Initializer.CushionNames[rails[k].Feature]);
        AssertVector(new Vector3(-JawXAt(57), Y, 57), point);
    }

    [Fact]
    public void ABallPastAJawReboundsOffTheJaw()
    {
        var ball = At(1, 122, 57, vx: 100);
        var engine = Engine("thesis", ball);
        engine.CalculateRailCollision(ball);
        AssertVector(new Vector3(JawXAt(57), Y, 57), ball.Position);
        // Formel 21 with n = (-cos 35, 0, sin 35): v - 2 (v.n) n = (1 - 2 cos^2 35, 0, 2 sin 35 cos 35)
        // = (-cos 70, 0, sin 70), times 0.9 * 100.
        float a = 70 * MathF.PI / 180;
        AssertVector(90 * new Vector3(-MathF.Cos(a), 0, MathF.Sin(a)), ball.Velocity);
    }

    [Theory]
    [InlineData("thesis", 72)]      // 6 cushions + 12 jaws + 6 * 3 back chords, two triangles each: the seed's 72
    [InlineData("pocketless", 12)]  // 6 cushions
    [InlineData("pool-9ft", 72)]
    [InlineData("pool-8ft", 72)]
    [InlineData("pool-7ft", 72)]
    public void EveryTableGetsItsTrianglesWithHorizontalUnitNormals(string preset, int count)
    {
        var rails = Initializer.InitRails(TableSpec.FromPreset(preset));
        Assert.Equal(count, rails.Length);
        foreach (var rail in rails)
        {
            Assert.Equal(1, rail.Normal.Length(), 1e-5f);
            Assert.Equal(0, rail.Normal.Y);
            Assert.Equal(rail.Feature < 12, rail.IsBouncing);
        }
    }

    [Theory]
    [InlineData("thesis", 122.5f, 63.5f)]
    [InlineData("pocketless", 127f, 63.5f)]
    public void CushionsLieARadiusInsideTheNosesFacingTheBalls(string preset, float halfLength, float halfWidth)
    {
        var rails = Initializer.InitRails(TableSpec.FromPreset(preset));
        foreach (var rail in rails.Where(r => r.Feature < 6))
        {
            // Head faces +x, foot -x; left cushions (seed -z) face +z, right ones -z.
            var (normal, coordinate, limit) = Initializer.CushionNames[rail.Feature] switch
            {
                "head" => (Vector3.UnitX, rail.P1.X, -halfLength),
                "foot" => (-Vector3.UnitX, rail.P1.X, halfLength),
                "left-head" or "left-foot" => (Vector3.UnitZ, rail.P1.Z, -halfWidth),
                _ => (-Vector3.UnitZ, rail.P1.Z, halfWidth),
            };
            AssertVector(normal, rail.Normal, 1e-6f);
            Assert.Equal(limit - MathF.Sign(limit) * 2.86f, coordinate, 1e-4f);
        }
    }

    [Theory]
    [InlineData("thesis")]
    [InlineData("pool-9ft")]
    [InlineData("pool-8ft")]
    [InlineData("pool-7ft")]
    public void ABallStoppedByABackWallIsInsideThatPocketsTestCircle(string preset)
    {
        var spec = TableSpec.FromPreset(preset);
        var table = ThesisTable.From(spec);
        foreach (var rail in Initializer.InitRails(spec).Where(r => !r.IsBouncing))
        {
            Assert.Equal(rail.Feature - 12, table.PocketAt(rail.P1 with { Y = Y }));
            Assert.Equal(rail.Feature - 12, table.PocketAt(rail.P2 with { Y = Y }));
        }
    }
}
