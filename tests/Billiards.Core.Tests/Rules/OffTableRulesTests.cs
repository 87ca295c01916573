using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Rules.RulesKit;

namespace Billiards.Core.Tests.Rules;

/// <summary>rules.md, balls driven off the table: the <c>ball-off-table</c> foul, jumped balls spotted or left off per game, the 8 off the table.</summary>
public class OffTableRulesTests
{
    [Fact]
    public void AnObjectBallOffTheTableIsAFoulAndIsSpottedIn8Ball()
    {
        var before = At(GameRules.EightBall, shot: 3);
        var r = Judge(before, ShotBuilder.Of(GameRules.EightBall).Hit(3).Rail(3).Jump(5));
        Assert.False(r.Legal);
        Assert.Equal([Foul.BallOffTable], r.Fouls);
        Assert.Equal([B(5)], r.Spot);
        Assert.Equal(BallInHand.Table, r.BallInHand);
        Assert.False(r.GameOver);
    }

    [Fact]
    public void TheEightOffTheTableLoses8Ball()
    {
        var before = At(GameRules.EightBall, shot: 3);
        var r = Judge(before, ShotBuilder.Of(GameRules.EightBall).Hit(3).Rail(3).Jump(8));
        Assert.Contains(Foul.BallOffTable, r.Fouls);
        Assert.Contains(Foul.EightBallOffTable, r.Fouls);
        Assert.True(r.GameOver);
        Assert.Equal(1, r.Winner);
        Assert.DoesNotContain(B(8), r.Spot);
    }

    [Fact]
    public void TheEightOffTheTableOnTheBreakLosesToo()
    {
        var r = Judge(Start(GameRules.EightBall), ShotBuilder.Of(GameRules.EightBall).Hit(1).Rail(2, 3, 4, 5).Jump(8));
        Assert.Contains(Foul.EightBallOffTable, r.Fouls);
        Assert.True(r.GameOver);
    }

    [Fact]
    public void In9BallJumpedBallsStayOffButTheNineIsSpotted()
    {
        var before = At(GameRules.NineBall, shot: 3);
        var r = Judge(before, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1).Jump(4).Jump(9));
        Assert.Equal([Foul.BallOffTable], r.Fouls);
        Assert.Equal([B(9)], r.Spot);
        Assert.Equal(BallInHand.Table, r.BallInHand);
        // The 4 stays off: the lowest on the table for the next shot is still the 1.
    }

    [Fact]
    public void In10BallTheTenIsSpottedAndOnTheBreakItIsStillAFoul()
    {
        var r = Judge(Start(GameRules.TenBall), ShotBuilder.Of(GameRules.TenBall).Hit(1).Rail(2, 3, 4, 5).Jump(10));
        Assert.Contains(Foul.BallOffTable, r.Fouls);
        Assert.Equal([B(10)], r.Spot);
    }

    [Fact]
    public void In14Point1JumpedBallsAreSpottedAndTheCueBallOffIsBallInHandInTheKitchen()
    {
        var before = At(GameRules.StraightPool, shot: 3) with { Call = new Call(B(3), PoolPockets.FootLeft) };
        var r = Judge(before, ShotBuilder.Of(GameRules.StraightPool).Hit(3).Rail(3).Jump(6).Jump(0));
        Assert.Equal([Foul.BallOffTable], r.Fouls);
        Assert.Equal([B(6)], r.Spot);
        Assert.Equal(BallInHand.Kitchen, r.BallInHand);
    }

    [Fact]
    public void ACueBallOffTheTableIsBallInHandLikeAScratch()
    {
        var r = Judge(At(GameRules.NineBall, shot: 3), ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1).Jump(0));
        Assert.Equal([Foul.BallOffTable], r.Fouls);
        Assert.Empty(r.Spot);
        Assert.Equal(BallInHand.Table, r.BallInHand);
    }

    [Fact]
    public void ABallTossedOverTheFootRailEndsOffTheTableAndIsAFoulIn8Ball()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("flight/eight-ball-over-the-foot-rail.json"));
        var run = SimulationRunner.Run(scene, new RunOptions());
        var sim = run.Simulation;
        int five = sim.IndexOf(B(5));
        Assert.Equal(MotionState.OffTable, sim.Balls[five].State);
        Assert.Contains(sim.Events.AsSpan().ToArray(), e => e.Kind == EventKind.BallOffTable && e.A == B(5));
        var ruling = run.Ruling!;
        Assert.False(ruling.Legal);
        Assert.Contains(Foul.BallOffTable, ruling.Fouls);
        Assert.Equal([B(5)], ruling.Spot);
        Assert.Equal(1, ruling.Next.Shooter);
        // The result file names it as the scene format does.
        string json = System.Text.Encoding.UTF8.GetString(ResultWriter.ToUtf8(run));
        Assert.Contains("\"ball-off-table\"", json);
        Assert.Contains("\"off-table\"", json);
    }
}
