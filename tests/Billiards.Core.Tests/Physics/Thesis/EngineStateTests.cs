using System.Numerics;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Physics.Thesis;

/// <summary>The thesis engine's saved state carries its random source: the game reset's orientations repeat.</summary>
public class EngineStateTests
{
    private const float Y = 2.86f;

    private static (PhysicsEngine Engine, Ball[] Balls) Pocket8(Random random)
    {
        // The 8 ball runs straight into the foot-right pocket (ShotEndTests): the shot ends in a game
        // reset, which draws new orientations for every ball.
        var balls = new[]
        {
            new Ball(0, new Vector3(-60, Y, 0)) { IsCue = true },
            new Ball(8, new Vector3(110, Y, 51)) { Velocity = 200 * Vector3.Normalize(new Vector3(1, 0, 1)) },
        };
        var table = TableSpec.FromPreset("thesis");
        var engine = new PhysicsEngine(balls, Initializer.InitRails(table), ThesisTable.From(table), new ThesisCue(), 1.0 / 250, random)
        {
            Events = new EventLog(),
        };
        return (engine, balls);
    }

    private static Quaternion[] RunToRest(PhysicsEngine engine, Ball[] balls)
    {
        for (int k = 0; k < 100_000 && !engine.IsAtRest; k++)
        {
            engine.CalculatePhysics();
        }
        Assert.Equal(ShotEnd.GameReset, engine.LastShotEnd);
        return [.. balls.Select(b => b.Orientation)];
    }

    [Fact]
    public void ALoadedStateRepeatsTheGameResetsOrientations()
    {
        var (engine, balls) = Pocket8(new SeededRandom(5));
        engine.Queue.EX = 1.5f;
        var state = engine.CreateState();
        engine.CalculatePhysics();
        engine.Save(state);
        var first = RunToRest(engine, balls);

        engine.Load(state);
        Assert.Equal(1.5f, engine.Queue.EX); // the reset cleared it; the state brought it back
        Assert.False(engine.IsAtRest);
        var second = RunToRest(engine, balls);
        Assert.Equal(first, second);

        // The orientations do depend on where the random source stands: one that has moved on
        // (as it has after the first reset, had the state not carried it) draws others.
        var movedOn = new SeededRandom(5);
        for (int k = 0; k < 8; k++)
        {
            movedOn.NextSingle();
        }
        var (other, otherBalls) = Pocket8(movedOn);
        Assert.NotEqual(first, RunToRest(other, otherBalls));
    }

    [Fact]
    public void AnEngineWithAPlainRandomCannotBeSaved()
    {
        var (engine, _) = Pocket8(new Random(5));
        Assert.Throws<InvalidOperationException>(() => engine.CreateState());
    }
}
