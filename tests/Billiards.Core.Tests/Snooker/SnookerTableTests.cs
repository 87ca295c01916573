using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Snooker;

/// <summary>The snooker table, its ball set and its rack (rules.md "Snooker", scene-format.md).</summary>
public class SnookerTableTests
{
    private static readonly TableSpec Table = TableSpec.FromPreset("snooker-12ft");
    private const double R = 0.02625;

    [Fact]
    public void The_table_has_the_WPBSA_playing_area_and_snookers_tighter_rounded_pockets()
    {
        Assert.Equal(3.569, Table.Length);
        Assert.Equal(1.778, Table.Width);
        Assert.Equal(6, Table.Pockets.Count);
        Assert.All(Table.Pockets, p => Assert.Equal(p.IsCorner ? 0.086 : 0.092, p.Mouth));
        var pool = TableSpec.FromPreset("pool-9ft");
        Assert.All(Table.Pockets.Zip(pool.Pockets), p => Assert.True(p.First.Mouth < p.Second.Mouth));
        // Rounded: the noses at the jaws are four times pool's.
        Assert.All(TableGeometry.Build(Table, R).Noses.ToArray(), n => Assert.Equal(0.02, n.Radius));
    }

    [Fact]
    public void Snookers_balls_are_held_by_snookers_table()
    {
        Assert.Null(RadiusLimits.Problem(Table, R));
        Assert.True(RadiusLimits.CaptureSpansJaws(Table, R));
    }

    [Fact]
    public void The_baulk_line_the_D_and_the_six_spots_stand_where_the_rules_put_them()
    {
        double baulk = -3.569 / 2 + 0.737;
        Assert.Equal(baulk, SnookerTable.BaulkLineX(Table), 12);
        Assert.Equal(new Vec3(baulk, -0.292, R), SnookerTable.Spot(Table, "yellow", R));
        Assert.Equal(new Vec3(baulk, 0.292, R), SnookerTable.Spot(Table, "green", R));
        Assert.Equal(new Vec3(baulk, 0, R), SnookerTable.Spot(Table, "brown", R));
        Assert.Equal(new Vec3(0, 0, R), SnookerTable.Spot(Table, "blue", R));
        Assert.Equal(new Vec3(3.569 / 4, 0, R), SnookerTable.Spot(Table, "pink", R));
        Assert.Equal(3.569 / 2 - 0.324, SnookerTable.Spot(Table, "black", R).X, 12);
        Assert.True(SnookerTable.InD(Table, new Vec3(baulk - 0.2, 0.2, R)));
        Assert.False(SnookerTable.InD(Table, new Vec3(baulk + 0.01, 0, R)));     // in front of the line
        Assert.False(SnookerTable.InD(Table, new Vec3(baulk - 0.25, 0.2, R)));   // in baulk, outside the arc
    }

    [Fact]
    public void The_ball_set_has_the_white_fifteen_reds_and_the_six_colours_with_their_values_without_numbers()
    {
        var set = BallSet.Snooker;
        Assert.Equal(22, set.Count);
        Assert.Equal(["cue", .. Enumerable.Range(1, 15).Select(k => $"red-{k}"), "yellow", "green", "brown", "blue", "pink", "black"], set.Balls.Select(b => b.Name));
        Assert.Equal([0, .. Enumerable.Repeat(1, 15), 2, 3, 4, 5, 6, 7], set.Balls.Select(b => b.Value));
        Assert.All(set.Balls, b => Assert.False(b.Look.Numbered || b.Look.Striped));
        Assert.Equal([set.Ids[0]], set.CueBalls);
        Assert.Equal(0.0525 / 2, set.Radius);
        Assert.Equal(0.142, set.Mass);
        // Names are unique across the sets: an id writes and reads as its ball's name.
        Assert.True(BallSet.Snooker.TryParse("pink", out var pink));
        Assert.Equal("pink", pink.ToString());
        Assert.Equal("7", new BallId(7).ToString());
        var red = BallSet.Snooker.Kind(BallSet.Snooker.Group("reds")[0]).Look;
        var pinkLook = BallSet.Snooker.Kind(pink).Look;
        Assert.True(red.Red > 0.5f && red.Green < 0.2f && pinkLook.Red > 0.8f && pinkLook.Blue > 0.4f);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(99)]
    public void The_rack_places_all_22_balls_the_colours_on_their_spots_the_reds_behind_the_pink_the_cue_ball_in_the_D(int seed)
    {
        var rack = Initializer.Rack(new RackSpec(RackGame.Snooker, seed), Table, R);
        Assert.Equal(BallSet.Snooker.Ids.Select(b => b.Value).Order(), rack.Select(b => b.Id.Value).Order());
        Assert.Null(Placement.Check(Table, R, rack, out _));
        foreach (string colour in BallSet.Colours)
        {
            Assert.Equal(SnookerTable.Spot(Table, colour, R), rack.Single(b => b.Id == BallSet.Colour(colour)).Position);
        }
        Assert.True(SnookerTable.InD(Table, rack.Single(b => b.Id == BallSet.Snooker.CueBalls[0]).Position));
        var pink = SnookerTable.Spot(Table, "pink", R);
        var reds = rack.Where(b => BallSet.Snooker.Group("reds").Contains(b.Id)).Select(b => b.Position).ToList();
        Assert.Equal(15, reds.Count);
        Assert.All(reds, p => Assert.True(p.X > pink.X && p.X < SnookerTable.Spot(Table, "black", R).X - 2 * R));
        // The apex red is as close to the pink as the jitter allows without touching: under 3 mm.
        double gap = reds.Min(p => (p - pink).Length) - 2 * R;
        Assert.InRange(gap, 0, 0.003);
    }

    [Fact]
    public void A_snooker_scene_racks_22_balls_of_52_5_mm_and_142_g_and_reads_snookers_ball_names()
    {
        var scene = SceneLoader.Parse("""
            { "format": "billiards-scene/1", "table": { "preset": "snooker-12ft" },
              "rack": { "game": "snooker", "seed": 3 },
              "balls": [ { "id": "black", "position": [1.0, 0.5] } ] }
            """, "s.json");
        Assert.Equal(22, scene.Balls.Count);
        Assert.Equal(R, scene.Physics.Params.R);
        Assert.Equal(0.142, scene.Physics.Params.M);
        Assert.Equal(new Vec3(1.0, 0.5, R), scene.Balls.Single(b => b.Id.ToString() == "black").Position);
    }

    [Fact]
    public void A_pool_scene_refuses_a_snooker_ball_naming_pools_ids()
    {
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse("""
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
              "balls": [ { "id": "red-1", "position": [0.0, 0.0] } ] }
            """, "p.json"));
        Assert.Equal("$.balls[0].id", e.JsonPath);
        Assert.Contains("\"cue\" or \"1\" .. \"15\"", e.Problem, StringComparison.Ordinal);
    }

    /// <summary>Shots at and along every pocket of the snooker table, exact and event: every ball ends on the table or pocketed.</summary>
    [Theory]
    [InlineData("exact")]
    [InlineData("event")]
    public void Shots_into_every_snooker_pocket_end_on_the_table_or_pocketed(string integrator)
    {
        var physics = PhysicsConfig.Default with { Integrator = ModelRegistry.FindIntegrator(ModelRegistry.Standard, integrator)!, Params = BallSet.Snooker.DefaultParams };
        for (int aim = -180; aim < 180; aim += 10)
        {
            foreach (var start in new[] { new Vec3(0.3, 0.1, R), new Vec3(-1.5, 0.8, R), new Vec3(1.6, -0.5, R) })
            {
                var scene = new Scene("pockets", null, Table, physics, null, [new BallSetup(BallSet.Snooker.CueBalls[0], start, Vec3.Zero, Vec3.Zero)], new ShotSpec(12, aim), null) { BallSet = BallSet.Snooker };
                var b = SimulationRunner.Run(scene, new RunOptions()).Simulation.Balls[0];
                Assert.True(b.IsPocketed || TableBounds.Contains(Table, b.Position, R), $"{integrator}, from {start} at {aim} deg: ended at {b.Position}");
            }
        }
    }
}
