using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Scenes;

/// <summary>Snooker in scenes: the rack, the balls' size and names (scene-format.md).</summary>
public class SnookerSceneTests
{
    private const double R = 0.02625;

    [Fact]
    public void ASnookerSceneRacks22BallsOf525MmAnd142GAndReadsSnookersBallNames()
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
    public void APoolSceneRefusesASnookerBallNamingPoolsIds()
    {
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse("""
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
              "balls": [ { "id": "red-1", "position": [0.0, 0.0] } ] }
            """, "p.json"));
        Assert.Equal("$.balls[0].id", e.JsonPath);
        Assert.Contains("\"cue\" or \"1\" .. \"15\"", e.Problem, StringComparison.Ordinal);
    }
}
