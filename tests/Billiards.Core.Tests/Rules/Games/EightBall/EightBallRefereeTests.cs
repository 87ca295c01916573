using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.RulesKit;

namespace Billiards.Core.Tests.Rules.Games;

/// <summary>rules.md, "8-ball": each rule, a hand-made shot and the ruling written from the rule.</summary>
public class EightBallRefereeTests
{
    private static readonly GameRules Game = GameRules.EightBall;
    private static readonly GameState Break = Start(Game);
    private static readonly GameState Open = At(Game, shot: 2);
    // Anna (0) has the solids, Ben (1) the stripes.
    private static readonly GameState Assigned = At(Game, shot: 5) with { Part = EightBallPart.Of(At(Game, shot: 5)) with { Groups = new PerPlayer<BallGroup>(BallGroup.Solids, BallGroup.Stripes) } };

    private static ShotBuilder Shot() => ShotBuilder.Of(Game);

    [Fact]
    public void ABreakThatPocketsABallIsLegalAndTheBreakerContinuesWithTheTableOpen()
    {
        var r = Judge(Break, Shot().Hit(1).Rail(2).Pocket(3, PoolPockets.FootLeft).Pocket(12, PoolPockets.SideRight));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(Ids(3, 12), r.Pocketed);
        Assert.Null(EightBallPart.Of(r.Next).Groups);
        Assert.Equal(1, r.Next.Shot);
        Assert.Empty(r.Options);
    }

    [Fact]
    public void ABreakThatSendsFourObjectBallsToACushionIsLegal()
    {
        var r = Judge(Break, Shot().Hit(1).Rail(1, 2, 3, 4));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
    }

    [Fact]
    public void ABreakWithThreeObjectBallsAtACushionIsABadBreakWithAcceptOrRerack()
    {
        // The cue ball's own cushion contacts and a ball's second contact do not count.
        var r = Judge(Break, Shot().Hit(1).Rail(1, 2, 3, 3, 0, 0));
        Expect(r, [Foul.BadBreak], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal([RefereeOption.Accept, RefereeOption.Rerack], r.Options);

        var accept = r.Choose(RefereeOption.Accept);
        Assert.False(accept.Rerack);
        Assert.Equal((1, 1), (accept.Next.Shooter, accept.Next.Shot));

        var rerack = r.Choose(RefereeOption.Rerack);
        Assert.True(rerack.Rerack);
        Assert.Equal((1, 0), (rerack.Next.Shooter, rerack.Next.Shot)); // the incoming player breaks
        Assert.Throws<ArgumentException>(() => r.Choose(RefereeOption.PassBack));
    }

    [Fact]
    public void AScratchOnTheBreakIsAFoulTheBallsStayDownAndTheTableStaysOpen()
    {
        var r = Judge(Break, Shot().Hit(1).Rail(2).Pocket(4, PoolPockets.FootRight).Pocket(0, PoolPockets.SideLeft));
        Expect(r, [Foul.CueBallPocketed], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(Ids(4), r.Pocketed);
        Assert.Empty(r.Spot);
        Assert.Null(EightBallPart.Of(r.Next).Groups);
    }

    [Fact]
    public void TheEightOnTheBreakIsSpottedOrReracksAtTheBreakersChoice()
    {
        var r = Judge(Break, Shot().Hit(1).Pocket(8, PoolPockets.FootLeft));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(Ids(8), r.Spot);
        Assert.Equal([RefereeOption.SpotEight, RefereeOption.Rerack], r.Options);
        var rerack = r.Choose(RefereeOption.Rerack);
        Assert.True(rerack.Rerack);
        Assert.Equal(0, rerack.Next.Shooter); // the breaker chose, and breaks again
    }

    [Fact]
    public void TheEightOnTheBreakWithAScratchGivesTheChoiceAndBallInHandToTheIncomingPlayer()
    {
        var r = Judge(Break, Shot().Hit(1).Pocket(8, PoolPockets.FootLeft).Pocket(0, PoolPockets.HeadRight));
        Expect(r, [Foul.CueBallPocketed], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(Ids(8), r.Spot);
        Assert.Equal([RefereeOption.SpotEight, RefereeOption.Rerack], r.Options);
        Assert.Equal(Ids(8), r.Choose(RefereeOption.SpotEight).Spot);
    }

    [Fact]
    public void OnAnOpenTableAStripeMayBeHitFirst()
    {
        var r = Judge(Open with { Call = Calls(11, PoolPockets.SideLeft) }, Shot().Hit(11).Rail(11));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
    }

    [Fact]
    public void OnAnOpenTableTheEightFirstIsWrongBallFirst()
    {
        var r = Judge(Open, Shot().Hit(8).Rail(8));
        Expect(r, [Foul.WrongBallFirst], cont: false, BallInHand.Table, nextShooter: 1);
    }

    [Fact]
    public void ACalledStripeLegallyPocketedAssignsTheStripesToTheShooter()
    {
        // Ben (1) shoots; he gets the stripes, Anna the solids. A solid also dropped: it stays down.
        var before = Open with { Shooter = 1, Call = Calls(10, PoolPockets.FootRight) };
        var r = Judge(before, Shot().Hit(10).Collide(10, 3).Pocket(10, PoolPockets.FootRight).Pocket(3, PoolPockets.SideLeft));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 1);
        Assert.Equal(new PerPlayer<BallGroup>(BallGroup.Solids, BallGroup.Stripes), EightBallPart.Of(r.Next).Groups);
        Assert.Equal(Ids(10, 3), r.Pocketed);
        Assert.Empty(r.Spot);
    }

    [Fact]
    public void AnUncalledBallPocketedOnAnOpenTableAssignsNothing()
    {
        var before = Open with { Call = Calls(2, PoolPockets.FootLeft) };
        var r = Judge(before, Shot().Hit(2).Collide(2, 13).Pocket(13, PoolPockets.FootLeft));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Null(EightBallPart.Of(r.Next).Groups);
    }

    [Fact]
    public void ACalledBallInAnotherPocketIsNoFoulButEndsTheTurn()
    {
        var before = Assigned with { Call = Calls(2, PoolPockets.FootLeft) };
        var r = Judge(before, Shot().Hit(2).Pocket(2, PoolPockets.FootRight));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal(Ids(2), r.Pocketed);
        Assert.Empty(r.Spot);
    }

    [Fact]
    public void ASafetyEndsTheTurnEvenWhenABallDrops()
    {
        var before = Assigned with { Call = Call.Safety };
        var r = Judge(before, Shot().Hit(2).Pocket(2, PoolPockets.FootRight));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
    }

    [Fact]
    public void TheCalledBallOfTheShootersGroupKeepsTheShooterAtTheTable()
    {
        var before = Assigned with { Call = Calls(5, PoolPockets.SideRight) };
        var r = Judge(before, Shot().Hit(5).Pocket(5, PoolPockets.SideRight));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
    }

    [Fact]
    public void HittingTheOpponentsGroupFirstIsWrongBallFirst()
    {
        var before = Assigned with { Call = Calls(5, PoolPockets.SideRight) };
        var r = Judge(before, Shot().Hit(9).Collide(9, 5).Pocket(5, PoolPockets.SideRight));
        Expect(r, [Foul.WrongBallFirst], cont: false, BallInHand.Table, nextShooter: 1);
    }

    [Fact]
    public void WithTheGroupClearedTheEightIsTheLegalTarget()
    {
        // Anna's solids are all down; hitting a stripe first is a foul, the 8 first is legal.
        var before = Assigned with { Call = Calls(8, PoolPockets.FootLeft) };
        var wrong = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7).Hit(9).Rail(9));
        Assert.Equal([Foul.WrongBallFirst], wrong.Fouls);
        var right = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7).Hit(8).Rail(8));
        Expect(right, [], cont: false, BallInHand.None, nextShooter: 1);
    }

    [Fact]
    public void TheEightLegallyPocketedInTheCalledPocketAfterTheGroupWins()
    {
        var before = Assigned with { Call = Calls(8, PoolPockets.FootLeft) };
        var r = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7).Hit(8).Pocket(8, PoolPockets.FootLeft));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 0, gameOver: true, winner: 0);
        Assert.Empty(r.Options);
    }

    [Fact]
    public void TheEightWhileTheGroupIsOnTheTableLosesEightBallEarly()
    {
        // The last solid and the 8 on one shot: the group was on the table when the shot began.
        var before = Assigned with { Call = Calls(8, PoolPockets.FootLeft) };
        var r = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6).Hit(7).Collide(7, 8).Pocket(7, PoolPockets.SideLeft).Pocket(8, PoolPockets.FootLeft));
        Expect(r, [Foul.EightBallEarly], cont: false, BallInHand.None, nextShooter: 1, gameOver: true, winner: 1);
    }

    [Fact]
    public void TheEightWithAScratchLosesEightBallFoul()
    {
        var before = Assigned with { Call = Calls(8, PoolPockets.FootLeft) };
        var r = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7).Hit(8).Pocket(8, PoolPockets.FootLeft).Pocket(0, PoolPockets.FootRight));
        Expect(r, [Foul.CueBallPocketed, Foul.EightBallFoul], cont: false, BallInHand.None, nextShooter: 1, gameOver: true, winner: 1);
    }

    [Fact]
    public void TheEightInAnotherPocketLosesEightBallUncalled()
    {
        var before = Assigned with { Call = Calls(8, PoolPockets.FootLeft) };
        var r = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7).Hit(8).Pocket(8, PoolPockets.SideRight));
        Expect(r, [Foul.EightBallUncalled], cont: false, BallInHand.None, nextShooter: 1, gameOver: true, winner: 1);
    }

    [Fact]
    public void EveryLossCodeOfOneShotIsListed()
    {
        // Ben (stripes, 9-15 all on the table) hits the 8 first, it drops uncalled and he scratches.
        var before = Assigned with { Shooter = 1, Call = Calls(9, PoolPockets.FootLeft) };
        var r = Judge(before, Shot().Hit(8).Pocket(8, PoolPockets.HeadLeft).Pocket(0, PoolPockets.HeadRight));
        Expect(r, [Foul.CueBallPocketed, Foul.WrongBallFirst, Foul.EightBallEarly, Foul.EightBallFoul, Foul.EightBallUncalled],
            cont: false, BallInHand.None, nextShooter: 0, gameOver: true, winner: 0);
    }

    [Fact]
    public void AfterTheGameTheNextStateIsANewRackBrokenByTheWinner()
    {
        var before = Assigned with { Call = Calls(8, PoolPockets.FootLeft), FoulsInRow = new(1, 1) };
        var r = Judge(before, Shot().Off(1, 2, 3, 4, 5, 6, 7).Hit(8).Pocket(8, PoolPockets.FootLeft));
        Assert.Equal(Start(Game), r.Next);
    }
}
