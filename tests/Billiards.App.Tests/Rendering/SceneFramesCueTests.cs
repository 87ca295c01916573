using System.Numerics;
using Billiards.App.Rendering;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Rendering;

public class SceneFramesCueTests
{
    private static Scene Load(string json) => SceneLoader.Parse(json, "cue.json");

    [Fact]
    public void AtRestWithoutAShotTheCueAddressesTheCueBallAlongTheView()
    {
        var scene = Load("""{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [-0.635, 0.1] } ] }""");
        var frame = SceneFrames.Build(scene, 0, 1280, 720);
        Assert.True(frame.Cue.Visible);
        var ball = new Vector3(-0.635f, 0.1f, 0.028575f);
        Assert.Equal(ball, frame.Cue.BallCentre);
        // The seed aims along ball - camera in the bed plane.
        var expected = Vector3.Normalize(new Vector3(ball.X - frame.Eye.X, ball.Y - frame.Eye.Y, 0));
        Assert.Equal(expected.X, frame.Cue.AimDirection.X, 6);
        Assert.Equal(expected.Y, frame.Cue.AimDirection.Y, 6);
        Assert.Equal(0, frame.Cue.AimDirection.Z);
        Assert.Equal(SceneFrames.AddressElevationDegrees, frame.Cue.ElevationDegrees);
    }

    [Fact]
    public void AShotSetsTheCuesAimElevationAndTip()
    {
        var scene = Load("""{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "speed": 2, "aim_deg": 90, "tip": [0.2, -0.3], "elevation_deg": 12 } }""");
        var cue = SceneFrames.Build(scene, 0, 640, 360).Cue;
        Assert.True(cue.Visible);
        Assert.Equal(0, cue.AimDirection.X, 6);
        Assert.Equal(1, cue.AimDirection.Y, 6);
        Assert.Equal((12f, new Vector2(0.2f, -0.3f)), (cue.ElevationDegrees, cue.TipOffset));
    }

    [Fact]
    public void WhileBallsRollTheCueIsHiddenAndAtRestItIsBack()
    {
        var scene = Load("""{ "format": "billiards-scene/1", "table": { "preset": "pocketless" }, "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "speed": 1, "aim_deg": 0 } }""");
        Assert.False(SceneFrames.Build(scene, 0.5, 640, 360).Cue.Visible);
        // 1 m/s centre hit: slides 0.146 s, then rolls from 5/7 m/s for 0.714 / (0.01 * 9.81) = 7.3 s.
        Assert.True(SceneFrames.Build(scene, 20, 640, 360).Cue.Visible);
    }

    [Fact]
    public void NoCueBallNoCue()
    {
        var scene = Load("""{ "format": "billiards-scene/1", "balls": [ { "id": "5", "position": [0, 0] } ] }""");
        Assert.False(SceneFrames.Build(scene, 0, 640, 360).Cue.Visible);
    }
}
