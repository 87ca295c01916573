using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Scenes;

/// <summary>A scene written by <see cref="SceneWriter"/> reads back to the same scene and plays the same shot bit for bit.</summary>
public class SceneWriterTests
{
    [Theory]
    [InlineData("stun.json")]
    [InlineData("eight-ball-break.json")]
    [InlineData("thesis-nine-ball-break.json")]
    [InlineData("masse.json")]
    [InlineData("bank.json")]
    public void AWrittenSceneReadsBackEqualAndPlaysItsShotBitForBit(string file)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file));
        var text = System.Text.Encoding.UTF8.GetString(SceneWriter.ToUtf8(scene));
        var back = SceneLoader.Parse(text, "written.json");
        Assert.Equal(scene.Table, back.Table);
        Assert.Equal(scene.Physics.Model, back.Physics.Model);
        Assert.Equal(scene.Physics.Integrator, back.Physics.Integrator);
        Assert.Equal(scene.Physics.Dt, back.Physics.Dt);
        Assert.Equal(scene.Physics.Params, back.Physics.Params);
        Assert.Equal(scene.Physics.Models, back.Physics.Models);
        Assert.Equal(scene.Balls, back.Balls);
        Assert.Equal(scene.Shot, back.Shot);
        Assert.Null(back.Rack); // the rack's balls are written as balls

        var a = SimulationRunner.Run(scene, new RunOptions());
        var b = SimulationRunner.Run(back, new RunOptions());
        Assert.Equal(a.Simulation.Events.Count, b.Simulation.Events.Count);
        var ba = a.Simulation.Balls.ToArray();
        var bb = b.Simulation.Balls.ToArray();
        for (int i = 0; i < ba.Length; i++)
        {
            Assert.Equal(ba[i].Position, bb[i].Position);
            Assert.Equal(ba[i].State, bb[i].State);
        }
    }
}
