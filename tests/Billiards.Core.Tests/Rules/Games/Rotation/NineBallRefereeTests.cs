using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.RulesKit;

namespace Billiards.Core.Tests.Rules.Games;

/// <summary>rules.md, "9-ball": each rule, a hand-made shot and the ruling written from the rule.</summary>
public class NineBallRefereeTests
{
    private static readonly GameRules Game = GameRules.NineBall;
    private static readonly GameState Break = Start(Game);
    private static readonly GameState Later = At(Game, shot: 4);

    private static ShotBuilder Shot() => ShotBuilder.Of(Game);

    [Fact]
    public void TheLowestBallIsTheTargetAndAnyBallLegallyPocketedContinuesWithoutACall()
    {
        // 1 and 2 are down: the 3 is the lowest. It caroms the 6 in.
        var r = Judge(Later, Shot().Off(1, 2).Hit(3).Collide(3, 6).Pocket(6, PoolPockets.HeadLeft));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(Ids(6), r.Pocketed);
    }

    [Fact]
    public void HittingAHigherBallThanTheLowestFirstIsAFoul()
    {
        var r = Judge(Later, Shot().Off(1, 2).Hit(4).Rail(4));
        Expect(r, [Foul.WrongBallFirst], cont: false, BallInHand.Table, nextShooter: 1);
    }

    [Fact]
    public void ABreakOnTheOneThatPocketsABallIsLegal()
    {
        var r = Judge(Break, Shot().Hit(1).Pocket(5, PoolPockets.SideLeft));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
    }

    [Fact]
    public void ABreakOnTheOneWithFourObjectBallsAtACushionIsLegal()
    {
        var r = Judge(Break, Shot().Hit(1).Rail(2, 3, 4, 5));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
    }

    [Fact]
    public void ABreakThatMissesTheOneIsABadBreakWithBallInHand()
    {
        var r = Judge(Break, Shot().Hit(2).Rail(2, 3, 4, 5).Pocket(6, PoolPockets.FootLeft));
        Expect(r, [Foul.BadBreak], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Empty(r.Options);
        Assert.Equal(1, r.Next.FoulsInRow[0]);
    }

    [Fact]
    public void ABreakWithThreeObjectBallsAtACushionIsABadBreak()
    {
        var r = Judge(Break, Shot().Hit(1).Rail(2, 3, 4));
        Expect(r, [Foul.BadBreak], cont: false, BallInHand.Table, nextShooter: 1);
    }

    [Fact]
    public void TheNineOnALegalBreakWins()
    {
        var r = Judge(Break, Shot().Hit(1).Collide(1, 9).Pocket(9, PoolPockets.FootRight));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 0, gameOver: true, winner: 0);
    }

    [Fact]
    public void TheNineOnAScratchedBreakIsSpotted()
    {
        var r = Judge(Break, Shot().Hit(1).Pocket(9, PoolPockets.FootRight).Pocket(0, PoolPockets.SideLeft));
        Expect(r, [Foul.CueBallPocketed], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(Ids(9), r.Spot);
    }

    [Fact]
    public void TheNineByACombinationOnALegalShotWins()
    {
        var r = Judge(Later, Shot().Off(1, 2, 3).Hit(4).Collide(4, 9).Pocket(9, PoolPockets.SideRight));
        // The next state is a new rack, broken by the winner (ours).
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 0, gameOver: true, winner: 0);
    }

    [Fact]
    public void TheNineOnAFoulIsSpottedAndDoesNotWin()
    {
        var r = Judge(Later, Shot().Off(1, 2, 3).Hit(9).Pocket(9, PoolPockets.SideRight));
        Expect(r, [Foul.WrongBallFirst], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(Ids(9), r.Spot);
    }

    [Fact]
    public void APushOutIgnoresFirstContactAndRailAndOffersShootOrPassBack()
    {
        // Anna pushes out on shot 1, touching nothing; the 9 drops off a kiss and is spotted.
        var before = At(Game, shot: 1) with { PushOut = true, FoulsInRow = new(1, 0) };
        var r = Judge(before, Shot().Collide(3, 9).Pocket(9, PoolPockets.FootLeft).Pocket(4, PoolPockets.SideLeft));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal([RefereeOption.Shoot, RefereeOption.PassBack], r.Options);
        Assert.Equal(Ids(9), r.Spot); // the 4 stays down
        Assert.Equal(new PerPlayer<int>(0, 0), r.Next.FoulsInRow);
        Assert.False(r.Next.PushOut);

        var shoot = r.Choose(RefereeOption.Shoot);
        Assert.Equal((1, 2), (shoot.Next.Shooter, shoot.Next.Shot));
        var back = r.Choose(RefereeOption.PassBack);
        Assert.Equal((0, 2), (back.Next.Shooter, back.Next.Shot));
        Assert.Equal(Ids(9), back.Spot);
    }

    [Fact]
    public void AScratchOnAPushOutIsStillAFoul()
    {
        var before = At(Game, shot: 1) with { PushOut = true };
        var r = Judge(before, Shot().Rail(0).Pocket(0, PoolPockets.HeadLeft));
        Expect(r, [Foul.CueBallPocketed], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Empty(r.Options);
    }

    [Fact]
    public void APushOutIsOnlyJudgedAsOneOnTheShotAfterTheBreak()
    {
        var before = At(Game, shot: 3) with { PushOut = true };
        var r = Judge(before, Shot().Rail(0));
        Assert.Equal([Foul.NoContact], r.Fouls);
    }

    [Fact]
    public void TheSecondFoulInARowIsWarned()
    {
        var before = Later with { FoulsInRow = new(1, 0) };
        var r = Judge(before, Shot().Rail(0));
        Expect(r, [Foul.NoContact], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(2, 0), r.Next.FoulsInRow);
        Assert.Contains("Warning", r.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void TheThirdFoulInARowLosesTheGame()
    {
        var before = Later with { Shooter = 1, FoulsInRow = new(0, 2) };
        var r = Judge(before, Shot().Hit(1).Rail(1).Pocket(0, PoolPockets.SideLeft));
        Expect(r, [Foul.CueBallPocketed, Foul.ThreeFouls], cont: false, BallInHand.None, nextShooter: 0, gameOver: true, winner: 0);
    }

    [Fact]
    public void ALegalShotStartsTheCountAgain()
    {
        var before = Later with { FoulsInRow = new(2, 1) };
        var r = Judge(before, Shot().Hit(1).Rail(1));
        Assert.Equal(new PerPlayer<int>(0, 1), r.Next.FoulsInRow);
        Assert.DoesNotContain("Warning", r.Message, StringComparison.Ordinal);
    }
}
