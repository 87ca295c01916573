using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

public class ResetTests
{
    private static (BallState[] Final, int Events, double Time) Play(Billiards.Core.Physics.Simulation sim, Scene scene)
    {
        sim.Strike(scene.Shot!);
        sim.AdvanceTo(600);
        return (sim.Balls.ToArray(), sim.Events.Count, sim.Time);
    }

    [Theory]
    [InlineData("thesis-eight-ball-break.json")]
    [InlineData("thesis-nine-ball-break.json")]
    [InlineData("eight-ball-break.json")]
    [InlineData("nine-ball-break.json")]
    public void AResetTableReplaysTheShotBitForBit(string file)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file));
        var sim = SimulationFactory.Create(scene);
        var first = Play(sim, scene);
        Assert.True(sim.IsAtRest);
        Assert.True(first.Events > 0);

        sim.Reset();
        Assert.Equal(0, sim.Time);
        Assert.Equal(0, sim.StepCount);
        Assert.Equal(0, sim.Events.Count);
        for (int i = 0; i < scene.Balls.Count; i++)
        {
            Assert.Equal(scene.Balls[i].Position.X, sim.Balls[i].Position.X, 6);
            Assert.Equal(scene.Balls[i].Position.Y, sim.Balls[i].Position.Y, 6);
            Assert.NotEqual(MotionState.Pocketed, sim.Balls[i].State);
        }

        var second = Play(sim, scene);
        Assert.Equal(first.Time, second.Time);
        Assert.Equal(first.Events, second.Events);
        Assert.Equal(first.Final.Select(b => (b.Position, b.Velocity, b.State, b.Pocket)), second.Final.Select(b => (b.Position, b.Velocity, b.State, b.Pocket)));
    }

    [Fact]
    public void Vec3PrintsItsComponents() => Assert.Equal("(1, -2.5, 0.1)", new Vec3(1, -2.5, 0.1).ToString());
}
