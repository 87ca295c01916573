using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.RulesKit;

namespace Billiards.Core.Tests.Rules.Games;

/// <summary>rules.md, "14.1 continuous": points, the opening break, foul penalties, reracks of 14.</summary>
public class StraightPoolRefereeTests
{
    private static readonly GameRules Game = GameRules.StraightPool;
    private static readonly GameState Later = At(Game, shot: 7) with { Score = new(20, 11) };

    private static ShotBuilder Shot() => ShotBuilder.Of(Game);

    [Fact]
    public void ALegallyPocketedCalledBallScoresAPointAndContinues()
    {
        var r = Judge(Later with { Call = Calls(6, PoolPockets.SideLeft) }, Shot().Hit(6).Pocket(6, PoolPockets.SideLeft));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(new PerPlayer<int>(21, 11), r.Next.Score);
    }

    [Fact]
    public void EveryBallPocketedWithTheCalledOneScores()
    {
        var r = Judge(Later with { Call = Calls(6, PoolPockets.SideLeft) }, Shot().Hit(6).Collide(6, 2).Pocket(6, PoolPockets.SideLeft).Pocket(2, PoolPockets.FootRight));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(new PerPlayer<int>(22, 11), r.Next.Score);
    }

    [Fact]
    public void AnUncalledBallScoresNothingAndIsSpotted()
    {
        var r = Judge(Later with { Call = Calls(6, PoolPockets.SideLeft) }, Shot().Hit(6).Collide(6, 2).Pocket(2, PoolPockets.FootRight));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(20, 11), r.Next.Score);
        Assert.Equal(Ids(2), r.Spot);
    }

    [Fact]
    public void ReachingTheTargetWins()
    {
        var before = Later with { Score = new(20, 49), Shooter = 1, Target = 50, Call = Calls(3, PoolPockets.HeadLeft) };
        var r = Judge(before, Shot().Hit(3).Pocket(3, PoolPockets.HeadLeft));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1, gameOver: true, winner: 1);
        // The final score is the ruling's; its next state starts the next game.
        Assert.Equal(new PerPlayer<int>(20, 50), r.Score);
        Assert.Equal(new PerPlayer<int>(0, 0), r.Next.Score);
    }

    [Fact]
    public void AnOpeningBreakWithTwoObjectBallsAndTheCueBallAtACushionIsLegal()
    {
        var r = Judge(Start(Game) with { Call = Call.Safety }, Shot().Hit(15).Rail(3, 11, 0));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(0, 0), r.Next.Score);
    }

    [Fact]
    public void AnOpeningBreakThatPocketsItsCalledBallIsLegalAndScores()
    {
        var r = Judge(Start(Game) with { Call = Calls(5, PoolPockets.FootRight) }, Shot().Hit(1).Pocket(5, PoolPockets.FootRight));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(new PerPlayer<int>(1, 0), r.Next.Score);
    }

    [Fact]
    public void AMissedOpeningBreakCostsTwoAndOffersAcceptOrRerackWithTheOffenderBreaking()
    {
        // Two object balls at a cushion, but not the cue ball.
        var r = Judge(Start(Game), Shot().Hit(15).Rail(3, 11));
        Expect(r, [Foul.BadBreak], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(-2, 0), r.Next.Score);
        Assert.Equal([RefereeOption.Accept, RefereeOption.Rerack], r.Options);
        var rerack = r.Choose(RefereeOption.Rerack);
        Assert.True(rerack.Rerack);
        Assert.Equal((0, 0), (rerack.Next.Shooter, rerack.Next.Shot));
        Assert.Equal(-2, rerack.Next.Score[0]);
    }

    [Fact]
    public void AFoulCostsAPoint()
    {
        var r = Judge(Later, Shot().Hit(4));
        Expect(r, [Foul.NoRail], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(19, 11), r.Next.Score);
        Assert.Equal(1, r.Next.FoulsInRow[0]);
    }

    [Fact]
    public void AScratchGivesBallInHandInTheKitchen()
    {
        var r = Judge(Later, Shot().Hit(4).Rail(4).Pocket(0, PoolPockets.FootLeft));
        Expect(r, [Foul.CueBallPocketed], cont: false, BallInHand.Kitchen, nextShooter: 1);
        Assert.Equal(BallInHand.Kitchen, r.Next.BallInHand);
    }

    [Fact]
    public void ACalledBallPocketedOnAFoulIsSpottedAndScoresNothing()
    {
        var r = Judge(Later with { Call = Calls(4, PoolPockets.FootLeft) }, Shot().Hit(4).Pocket(4, PoolPockets.FootLeft).Pocket(0, PoolPockets.FootRight));
        Expect(r, [Foul.CueBallPocketed], cont: false, BallInHand.Kitchen, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(19, 11), r.Next.Score);
        Assert.Equal(Ids(4), r.Spot);
    }

    [Fact]
    public void TheThirdFoulInARowCostsFifteenMoreAndStartsTheCountAgain()
    {
        var r = Judge(Later with { FoulsInRow = new(2, 0) }, Shot().Rail(0));
        Expect(r, [Foul.NoContact, Foul.ThreeFouls], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(20 - 1 - 15, 11), r.Next.Score);
        Assert.Equal(new PerPlayer<int>(0, 0), r.Next.FoulsInRow);
    }

    [Fact]
    public void TheSecondFoulInARowIsWarned()
    {
        var r = Judge(Later with { FoulsInRow = new(1, 0) }, Shot().Rail(0));
        Assert.Contains("Warning", r.Message, StringComparison.Ordinal);
        Assert.Equal(2, r.Next.FoulsInRow[0]);
    }

    [Fact]
    public void PocketingTheFourteenthBallReracksFourteenAndTheShooterGoesOn()
    {
        // Balls 1-13 are down; the 14 is called and pocketed; the 15 is left.
        var before = Later with { Call = Calls(14, PoolPockets.SideRight) };
        var r = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13).Hit(14).Pocket(14, PoolPockets.SideRight));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(Ids(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14), r.Rerack);
        Assert.Equal(21, r.Next.Score[0]);
        Assert.Equal(8, r.Next.Shot); // play goes on; the next shot is no break
    }

    [Fact]
    public void WithTwoBallsLeftNothingIsReracked()
    {
        var before = Later with { Call = Calls(14, PoolPockets.SideRight) };
        var r = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12).Hit(14).Pocket(14, PoolPockets.SideRight));
        Assert.Empty(r.Rerack);
    }
}
