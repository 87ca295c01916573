using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.RulesKit;

namespace Billiards.Core.Tests.Rules.Games;

/// <summary>rules.md, "10-ball": 9-ball's rules with calls and the 10.</summary>
public class TenBallRefereeTests
{
    private static readonly GameRules Game = GameRules.TenBall;
    private static readonly GameState Later = At(Game, shot: 4);

    private static ShotBuilder Shot() => ShotBuilder.Of(Game);

    [Fact]
    public void TheCalledBallInItsPocketContinues()
    {
        var r = Judge(Later with { Call = Calls(1, PoolPockets.FootLeft) }, Shot().Hit(1).Pocket(1, PoolPockets.FootLeft));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
    }

    [Fact]
    public void ACalledBallInAnotherPocketEndsTheTurnWithoutAFoul()
    {
        var r = Judge(Later with { Call = Calls(1, PoolPockets.FootLeft) }, Shot().Hit(1).Pocket(1, PoolPockets.FootRight));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Empty(r.Spot);
    }

    [Fact]
    public void AnUncalledBallPocketedEndsTheTurnAndStaysDown()
    {
        var r = Judge(Later with { Call = Calls(1, PoolPockets.FootLeft) }, Shot().Hit(1).Collide(1, 6).Pocket(6, PoolPockets.SideLeft));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal(Ids(6), r.Pocketed);
        Assert.Empty(r.Spot);
    }

    [Fact]
    public void AnUncalledTenIsSpotted()
    {
        var r = Judge(Later with { Call = Calls(1, PoolPockets.FootLeft) }, Shot().Hit(1).Collide(1, 10).Pocket(10, PoolPockets.SideLeft));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal(Ids(10), r.Spot);
    }

    [Fact]
    public void TheTenOnTheBreakIsSpottedAndDoesNotWin()
    {
        var r = Judge(Start(Game), Shot().Hit(1).Pocket(10, PoolPockets.FootRight));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
        Assert.Equal(Ids(10), r.Spot);
    }

    [Fact]
    public void TheTenLegallyInItsCalledPocketWins()
    {
        var r = Judge(Later with { Call = Calls(10, PoolPockets.HeadLeft) }, Shot().Off(1, 2, 3, 4, 5, 6).Hit(7).Collide(7, 10).Pocket(10, PoolPockets.HeadLeft));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 0, gameOver: true, winner: 0);
    }

    [Fact]
    public void TheLowestBallIsStillTheFirstTarget()
    {
        var r = Judge(Later with { Call = Calls(10, PoolPockets.HeadLeft) }, Shot().Hit(10).Pocket(10, PoolPockets.HeadLeft));
        Expect(r, [Foul.WrongBallFirst], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(Ids(10), r.Spot);
    }

    [Fact]
    public void APushOutNeedsNoCall()
    {
        var r = Judge(At(Game, shot: 1) with { PushOut = true }, Shot().Hit(5).Pocket(5, PoolPockets.SideRight));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Equal([RefereeOption.Shoot, RefereeOption.PassBack], r.Options);
    }

    [Fact]
    public void ThreeFoulsLoseTenBallToo()
    {
        var r = Judge(Later with { FoulsInRow = new(2, 0) }, Shot().Rail(0));
        Expect(r, [Foul.NoContact, Foul.ThreeFouls], cont: false, BallInHand.None, nextShooter: 1, gameOver: true, winner: 1);
    }
}
