using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Table;

/// <summary>
/// The table-bound guarantee, the table's half: a scene whose ball radius the table cannot hold is
/// refused at load with the reason, the capture circle spans the jaws, and what counts as on the
/// table (the simulation's half: Physics/Standard/TableBoundSimulationTests).
/// </summary>
public class TableBoundGuaranteeTests
{
    private static string Scene(string physics, string table = """{ "preset": "pool-9ft" }""") => $$"""
        { "format": "billiards-scene/1", "table": {{table}}, "physics": {{physics}},
          "rack": { "game": "eight-ball", "seed": 1 },
          "balls": [ { "id": "cue", "position": [-0.635, 0.0] } ],
          "shot": { "speed": 20.0, "aim_deg": 0.0 } }
        """;

    [Fact]
    public void AHardBreakWithR0005IsRefusedBecauseTheCushionsCannotHoldIt()
    {
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse(Scene("""{ "params": { "R": 0.005 } }"""), "r.json"));
        Assert.Equal("$.physics.params.R", e.JsonPath);
        Assert.Contains("does not meet the cushions", e.Problem, StringComparison.Ordinal);
        Assert.Contains("[0.01829, 0.03658]", e.Problem, StringComparison.Ordinal);
    }

    [Fact]
    public void ASmallBallUnderLowCushionsIsHeldBecauseTheCaptureCircleWidensToTheJaws()
    {
        var scene = SceneLoader.Parse(Scene("""{ "params": { "R": 0.005 } }""", """{ "preset": "pool-9ft", "cushion_height": 0.007 }"""), "r.json");
        Assert.True(RadiusLimits.CaptureSpansJaws(scene.Table, 0.005));
        // The circle spans the channel a centre can reach: wider than R there.
        Assert.All(TableGeometry.Build(scene.Table, 0.005).Pockets.ToArray(), p => Assert.True(p.Radius > 0.005));
    }

    [Fact]
    public void ABallWiderThanTheMouthsIsRefused()
    {
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse(
            Scene("""{ "params": { "R": 0.06 } }""", """{ "preset": "pool-9ft", "cushion_height": 0.08 }"""), "r.json"));
        Assert.Contains("does not fit through the pockets", e.Problem, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("pool-9ft")]
    [InlineData("pool-8ft")]
    [InlineData("pool-7ft")]
    [InlineData("thesis")]
    [InlineData("pocketless")]
    public void TheRegulationBallIsHeldByEveryPreset(string preset)
    {
        Assert.Null(RadiusLimits.Problem(TableSpec.FromPreset(preset), PhysicsParams.DefaultRadius));
    }

    // The capture chord across the jaws, worked by hand for the 9 ft corner pocket at the default
    // radius: the centre's channel is 2 x 25.6 mm wide where the circle (R = 28.6 mm) lies, so the
    // circle keeps R; at R = 25 mm the channel is 2 x 29.7 mm, and the circle widens to 29.7 mm.
    [Theory]
    [InlineData(0.028575, 0.028575)]
    [InlineData(0.025, 0.0297)]
    public void TheCaptureCircleSpansTheJawsWideningPastRForSmallBalls(double radius, double expected)
    {
        var table = TableSpec.FromPreset("pool-9ft");
        Assert.True(RadiusLimits.CaptureSpansJaws(table, radius));
        Assert.Equal(expected, TableGeometry.Build(table, radius).Pockets[0].Radius, 4);
    }

    [Fact]
    public void BallsInAPocketMouthAreOnTheTableAndFarOutsideAreNot()
    {
        var table = TableSpec.FromPreset("pool-9ft");
        double r = PhysicsParams.DefaultRadius;
        Assert.True(TableBounds.Contains(table, new Vec3(0.02, table.HalfWidth + 0.01, r), r));   // in the side pocket's mouth
        Assert.False(TableBounds.Contains(table, new Vec3(0.6, table.HalfWidth + 0.01, r), r));   // behind a rail
        Assert.False(TableBounds.Contains(table, new Vec3(107.7, 111.1, r), r));
        Assert.False(TableBounds.Contains(TableSpec.FromPreset("pocketless"), new Vec3(0.02, table.HalfWidth + 0.01, r), r));
    }
}
