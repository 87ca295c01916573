using System.Numerics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Setup;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Thesis.ThesisKit;

namespace Billiards.Core.Tests.Thesis;

/// <summary>Formel 30 and Listing 4 (seed 4.3.5): the pocket test.</summary>
public class PocketTests
{
    private static readonly ThesisTable Table = ThesisTable.From(TableSpec.FromPreset("thesis"));

    [Fact]
    public void The_thesis_table_has_the_seeds_pocket_constants()
    {
        Assert.Equal(new Vector3(124.5f, 0, 65.5f), Table.CornerPocket);
        Assert.Equal(new Vector3(0, 0, 69), Table.SidePocket);
        Assert.Equal(4.5f, Table.CornerPocketRadius);
        Assert.Equal(4.5f, Table.SidePocketRadius);
        Assert.Equal(117f, Table.PocketZoneX);
        Assert.Equal(58f, Table.PocketZoneZ);
    }

    [Theory]
    // |(124.5, 65.5) - (121.5, 63.5)| = sqrt(9 + 4) = 3.61 < 4.5, in each quadrant; +x foot, +z right.
    [InlineData(121.5f, 63.5f, "foot-right")]
    [InlineData(121.5f, -63.5f, "foot-left")]
    [InlineData(-121.5f, 63.5f, "head-right")]
    [InlineData(-121.5f, -63.5f, "head-left")]
    // |(0, 69) - (2, 66)| = sqrt(4 + 9) = 3.61 < 4.5.
    [InlineData(2f, 66f, "side-right")]
    [InlineData(-2f, -66f, "side-left")]
    public void Near_a_pocket_centre_the_ball_is_pocketed(float x, float z, string pocket)
    {
        Assert.Equal(pocket, PoolPockets.Set.NameOf(Table.PocketAt(new Vector3(x, Y, z))));
    }

    [Theory]
    [InlineData(120f, 60f)]     // sqrt(4.5^2 + 5.5^2) = 7.1 from the corner pocket
    [InlineData(124.5f, 61f)]   // exactly 4.5: the test is strict
    [InlineData(0f, 64.4f)]     // 4.6 from the side pocket
    [InlineData(116.9f, 57.9f)] // inside the zone |x| <= 117, |z| <= 58: never tested
    [InlineData(0f, 0f)]
    public void Elsewhere_the_ball_is_not(float x, float z)
    {
        Assert.Equal(-1, Table.PocketAt(new Vector3(x, Y, z)));
    }

    [Fact]
    public void The_pocketless_table_has_no_pockets()
    {
        var pocketless = ThesisTable.From(TableSpec.FromPreset("pocketless"));
        Assert.Equal(-1, pocketless.PocketAt(new Vector3(124.5f, Y, 65.5f)));
    }

    [Fact]
    public void A_pocketed_ball_falls_at_981_times_its_mass_and_is_logged_once()
    {
        var ball = At(5, 121.5f, 63.5f, vx: 10, vz: 10);
        var engine = Engine("thesis", ball);
        Assert.Equal(5, engine.CheckForPockets(ball));
        // Listing 4: velocity.y = -981 * 0.17 = -166.77; the horizontal velocity stays.
        AssertVector(new Vector3(10, -166.77f, 10), ball.Velocity);
        Assert.Equal(5, ball.Pocket);
        engine.CheckForPockets(ball);
        var e = Assert.Single(engine.Events!.AsSpan().ToArray());
        Assert.Equal(EventKind.BallPocket, e.Kind);
        Assert.Equal(5, e.Feature);
    }

    [Fact]
    public void A_dropping_ball_leaves_play_below_minus_20_cm()
    {
        var ball = At(5, 124.5f, 65.5f);
        var other = At(1, 0, 0, vx: 100); // keeps the shot going
        var engine = Engine("thesis", ball, other);
        engine.CheckForPockets(ball);
        // Falling at ~166.77 cm/s (damped a little each step) from 2.86 to -20 takes at least
        // 22.86 / 166.77 * 250 = 34.3 steps; well before 60 it is out of play.
        for (int i = 0; i < 34; i++)
        {
            engine.CalculatePhysics();
        }
        Assert.False(ball.IsPocketed);
        for (int i = 0; i < 26; i++)
        {
            engine.CalculatePhysics();
        }
        Assert.True(ball.IsPocketed);
        Assert.True(ball.Position.Y < PhysicsEngine.DropDepth);
        Assert.Equal(Vector3.Zero, ball.Velocity);
    }
}
