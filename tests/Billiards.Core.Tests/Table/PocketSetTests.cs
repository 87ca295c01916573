using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Table;

/// <summary>A table's pockets are data: a table with other pockets needs no code of its own.</summary>
public class PocketSetTests
{
    // Four corner pockets of 86 mm at 135 deg and no side pockets: a table no preset has.
    private static readonly PocketSet Corners = new(
    [
        new PocketSpec("head-left", -1, 1, 0.086, 135),
        new PocketSpec("head-right", -1, -1, 0.086, 135),
        new PocketSpec("foot-left", 1, 1, 0.086, 135),
        new PocketSpec("foot-right", 1, -1, 0.086, 135),
    ]);

    private static readonly TableSpec FourPockets = TableSpec.FromPreset("pool-9ft") with { Pockets = Corners };

    private static StandardSimulation Roll(double x, double y, double aimDeg)
    {
        var scene = SceneLoader.Parse($$"""
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "model": "standard" },
              "balls": [ { "id": "cue", "position": [{{x.ToString(System.Globalization.CultureInfo.InvariantCulture)}}, {{y.ToString(System.Globalization.CultureInfo.InvariantCulture)}}] } ] }
            """, "four-pockets.json") with { Table = FourPockets };
        var sim = new StandardSimulation(scene);
        sim.Strike(new ShotSpec(1.2, aimDeg));
        sim.AdvanceTo(60);
        return sim;
    }

    [Fact]
    public void The_pool_table_has_the_six_pockets_of_the_contract_in_index_order()
    {
        var pockets = TableSpec.FromPreset("pool-9ft").Pockets;
        Assert.Equal(["head-left", "head-right", "side-left", "side-right", "foot-left", "foot-right"], pockets.Select(p => p.Name));
        Assert.Equal([0, 1, 2, 3, 4, 5], pockets.Ids.Select(p => p.Index));
        Assert.Empty(TableSpec.FromPreset("pocketless").Pockets);
        Assert.False(TableSpec.FromPreset("pocketless").HasPockets);
    }

    [Fact]
    public void A_set_parses_only_its_own_names_and_names_ids_by_index()
    {
        Assert.True(Corners.TryParse("foot-left", out var footLeft));
        Assert.Equal(new PocketId(2, "foot-left"), footLeft);
        Assert.False(Corners.TryParse("side-left", out var none));
        Assert.Equal(PocketId.None, none);
        Assert.Equal(PocketId.None, Corners.Id(4));
        Assert.Equal("foot-right", Corners.NameOf(3));
        Assert.Equal("none", PocketId.None.ToName());
    }

    [Fact]
    public void Two_pockets_in_one_place_or_of_one_name_are_refused()
    {
        Assert.Throws<ArgumentException>(() => new PocketSet([new("a", 1, 1, 0.1, 140), new("b", 1, 1, 0.1, 140)]));
        Assert.Throws<ArgumentException>(() => new PocketSet([new("a", 1, 1, 0.1, 140), new("a", -1, 1, 0.1, 140)]));
        Assert.Throws<ArgumentException>(() => new PocketSet([new("a", 2, 1, 0.1, 140)]));
    }

    [Fact]
    public void The_geometry_of_a_table_of_four_pockets_has_their_circles_and_jaws_and_whole_long_rails()
    {
        var geometry = TableGeometry.Build(FourPockets, PhysicsParams.DefaultRadius);
        Assert.Equal([0, 1, 2, 3], geometry.Pockets.ToArray().Select(p => p.Pocket));
        // 6 rails and two jaws for each of the four pockets, named after them.
        Assert.Equal(6 + 8, geometry.Segments.Length);
        Assert.Equal(8, geometry.CushionNames.Count(n => n.Contains("-jaw-", StringComparison.Ordinal)));
        Assert.DoesNotContain(geometry.CushionNames, n => n.StartsWith("side", StringComparison.Ordinal));
        // Without a side pocket the long rail's two halves meet at its middle.
        var leftHead = geometry.Segments[2];
        var leftFoot = geometry.Segments[3];
        Assert.Equal(0, leftHead.End.X, 12);
        Assert.Equal(0, leftFoot.Start.X, 12);
        // Each corner's mouth, 86 mm, cuts the rails by mouth / sqrt 2 before the jaw's nose.
        Assert.True(geometry.Segments[0].End.Y < FourPockets.HalfWidth - 0.086 / Math.Sqrt(2));
    }

    [Fact]
    public void A_ball_sent_at_the_middle_of_a_long_rail_bounces_where_a_pool_table_has_a_side_pocket()
    {
        var sim = Roll(0, 0, 90);
        var ball = sim.Balls[0];
        Assert.False(ball.IsPocketed);
        Assert.Contains(sim.Events.AsSpan().ToArray(), e => e.Kind == EventKind.BallCushion && sim.Cushion(e).IsRail);
    }

    [Fact]
    public void A_ball_sent_into_a_corner_drops_into_the_pocket_the_set_names()
    {
        // From the centre straight at the foot-left corner's capture circle.
        var circle = TableGeometry.Build(FourPockets, PhysicsParams.DefaultRadius).Pockets[2];
        var sim = Roll(0, 0, Math.Atan2(circle.Centre.Y, circle.Centre.X) * 180 / Math.PI);
        var drop = sim.Events.AsSpan().ToArray().Single(e => e.Kind == EventKind.BallPocket);
        Assert.Equal(Corners.Ids[2], sim.Pocket(drop));
        Assert.Equal("foot-left", sim.FeatureName(EventKind.BallPocket, drop.Feature));
        Assert.Equal(PoolBalls.Cue, drop.A);
    }
}
