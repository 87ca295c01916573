using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.RulesKit;

using Billiards.Core.Tests.Rules.Games;

namespace Billiards.Core.Tests.Rules;

/// <summary>
/// A ruling says what happened in a player's words: which balls went down, what the break made,
/// which of a break's two conditions failed, and snooker's points.
/// </summary>
public class RulingWordsTests
{
    [Fact]
    public void APotOnTheBreakSaysWhichBallsTheBreakMade()
    {
        var r = Judge(Start(GameRules.NineBall), ShotBuilder.Of(GameRules.NineBall).Hit(1).Pocket(5, PoolPockets.SideLeft).Pocket(3, PoolPockets.FootLeft));
        Assert.StartsWith("The break pots the 5 and the 3.", r.Message, StringComparison.Ordinal);
        Assert.Contains("shoots again", r.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ANineBallBreakFoulSaysWhichConditionItFailed()
    {
        var missed = Judge(Start(GameRules.NineBall), ShotBuilder.Of(GameRules.NineBall).Hit(2).Rail(2, 3, 4, 5));
        Assert.Contains("the break hit the 2 first, not the 1", missed.Message, StringComparison.Ordinal);
        Assert.DoesNotContain(", or ", missed.Message, StringComparison.Ordinal);
        var weak = Judge(Start(GameRules.NineBall), ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(2, 3, 4));
        Assert.Contains("the break pocketed no ball and sent 3 object balls to a cushion, not four", weak.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void PottingAnOwnBallThatWasNotCalledSaysWhichWentDownAndWhatWasCalled()
    {
        var assigned = At(GameRules.EightBall, shot: 5) with { Call = Calls(3, PoolPockets.FootLeft), Part = EightBallPart.Of(At(GameRules.EightBall, shot: 5)) with { Groups = new PerPlayer<BallGroup>(BallGroup.Solids, BallGroup.Stripes) } };
        var r = Judge(assigned, ShotBuilder.Of(GameRules.EightBall).Hit(4).Pocket(4, PoolPockets.FootRight));
        Assert.True(r.Legal);
        Assert.False(r.Continue);
        Assert.Contains("pots the 4 (the 3 was called).", r.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ASnookerFoulGivesItsPointsAndAPotItsScore()
    {
        var frame = SnookerShot.Frame with { Call = Call.Nominate(SnookerShot.Id("blue")), Part = SnookerPart.Of(SnookerShot.Frame) with { BallOn = "colour" } };
        var foul = new SnookerShot().Hit("pink").Judge(frame);
        Assert.Contains($"6 points to {frame.Players[1]}.", foul.Message, StringComparison.Ordinal);
        var pot = new SnookerShot().Hit("red-3").Pot("red-3").Pot("red-7").Judge(SnookerShot.Frame);
        Assert.Contains($"{SnookerShot.Frame.Players[0]} pots 2 reds: 2 points.", pot.Message, StringComparison.Ordinal);
        Assert.DoesNotContain("red-", pot.Message, StringComparison.Ordinal);
    }
}
