using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.RulesKit;

namespace Billiards.Core.Tests.Rules;

/// <summary>rules.md, "Fouls common to all four games", judged on 9-ball shots after the break.</summary>
public class CommonFoulTests
{
    private static readonly GameState NineBall = At(GameRules.NineBall, shot: 3);

    [Fact]
    public void ALegalShotHitsTheTargetAndSendsABallToACushion()
    {
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1));
        // Legal, but nothing pocketed: the turn passes without ball in hand.
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
        Assert.Empty(r.Pocketed);
        Assert.Equal(4, r.Next.Shot);
    }

    [Fact]
    public void ScratchIsCueBallPocketedAndGivesBallInHandOnTheTable()
    {
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1).Pocket(0, PoolPockets.SideLeft));
        Expect(r, [Foul.CueBallPocketed], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(new PerPlayer<int>(1, 0), r.Next.FoulsInRow);
        Assert.Equal(BallInHand.Table, r.Next.BallInHand);
    }

    [Fact]
    public void TouchingNoObjectBallIsNoContact()
    {
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Rail(0, 0));
        Expect(r, [Foul.NoContact], cont: false, BallInHand.Table, nextShooter: 1);
    }

    [Fact]
    public void HittingAnotherBallThanTheLowestFirstIsWrongBallFirstEvenIfItPockets()
    {
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Hit(2).Collide(2, 1).Pocket(1, PoolPockets.FootLeft));
        Expect(r, [Foul.WrongBallFirst], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(Ids(1), r.Pocketed);
        Assert.Empty(r.Spot); // only the 9 is spotted after a foul
    }

    [Fact]
    public void NoCushionAfterALegalContactAndNothingPocketedIsNoRail()
    {
        // The cue ball touched a cushion before the contact: that does not count.
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Rail(0).Hit(1));
        Expect(r, [Foul.NoRail], cont: false, BallInHand.Table, nextShooter: 1);
    }

    [Fact]
    public void APocketedObjectBallCountsAsTheRailAfterContact()
    {
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Hit(1).Pocket(1, PoolPockets.FootRight));
        Expect(r, [], cont: true, BallInHand.None, nextShooter: 0);
    }

    [Fact]
    public void TheCueBallReachingACushionAfterContactCountsAsTheRail()
    {
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(0));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
    }

    [Fact]
    public void BallInHandPlacedOnABallIsBadPlacement()
    {
        // Ball 5 rests at (0.2, 0.1); the cue ball was placed 3 cm from its centre (less than 2R).
        var before = NineBall with { BallInHand = BallInHand.Table, Placement = new Vec3(0.23, 0.1, ShotBuilder.R) };
        var r = Judge(before, ShotBuilder.Of(GameRules.NineBall).At(5, 0.2, 0.1).Hit(1).Rail(1));
        Expect(r, [Foul.BadPlacement], cont: false, BallInHand.Table, nextShooter: 1);
    }

    [Fact]
    public void BallInHandPlacedFreelyIsLegal()
    {
        var before = NineBall with { BallInHand = BallInHand.Table, Placement = new Vec3(0.3, 0.1, ShotBuilder.R) };
        var r = Judge(before, ShotBuilder.Of(GameRules.NineBall).At(5, 0.2, 0.1).Hit(1).Rail(1));
        Expect(r, [], cont: false, BallInHand.None, nextShooter: 1);
    }

    [Fact]
    public void BallInHandInTheKitchenPlacedPastTheHeadStringIsBadPlacement()
    {
        // The head string is at x = -L/4 = -0.635 m on the 9 ft table.
        var before = NineBall with { BallInHand = BallInHand.Kitchen, Placement = new Vec3(-0.6, -0.3, ShotBuilder.R) };
        var r = Judge(before, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1));
        Expect(r, [Foul.BadPlacement], cont: false, BallInHand.Table, nextShooter: 1);

        var inside = Judge(before with { Placement = new Vec3(-0.7, -0.3, ShotBuilder.R) }, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1));
        Assert.True(inside.Legal);
    }

    [Fact]
    public void ABallPlacedOffTheBedIsBadPlacement()
    {
        // Half the width is 0.635 m; a centre at y = 0.62 leaves less than R to the cushion nose.
        var before = NineBall with { BallInHand = BallInHand.Table, Placement = new Vec3(0.0, 0.62, ShotBuilder.R) };
        var r = Judge(before, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1));
        Assert.Equal([Foul.BadPlacement], r.Fouls);
    }

    [Fact]
    public void ABallPlacedOverAPocketIsBadPlacementAsThePlacementTestSays()
    {
        // In the foot-right corner, R from both cushion noses: on the bed, but in the pocket's mouth.
        var table = Billiards.Core.Table.TableSpec.FromPreset("pool-9ft");
        var corner = new Vec3(table.HalfLength - ShotBuilder.R, table.HalfWidth - ShotBuilder.R, ShotBuilder.R);
        Assert.Contains("pocket", Billiards.Core.Setup.Placement.OnTable(table, ShotBuilder.R, PoolBalls.Cue, corner), StringComparison.Ordinal);
        var before = NineBall with { BallInHand = BallInHand.Table, Placement = corner };
        var r = Judge(before, ShotBuilder.Of(GameRules.NineBall).Hit(1).Rail(1));
        Assert.Equal([Foul.BadPlacement], r.Fouls);
    }

    [Fact]
    public void SeveralFoulsAreAllListedAndCountAsOne()
    {
        var r = Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Hit(3).Rail(3).Pocket(0, PoolPockets.HeadLeft));
        Expect(r, [Foul.CueBallPocketed, Foul.WrongBallFirst], cont: false, BallInHand.Table, nextShooter: 1);
        Assert.Equal(1, r.Next.FoulsInRow[0]);
    }

    [Fact]
    public void TheRefereeIsAPureFunction()
    {
        var shot = ShotBuilder.Of(GameRules.NineBall).Hit(2).Pocket(0, PoolPockets.SideLeft).Record();
        var referee = RefereeOf(GameRules.NineBall);
        var first = referee.Judge(NineBall, shot);
        var second = referee.Judge(NineBall, shot);
        Assert.Equal(first.Message, second.Message);
        Assert.Equal(first.Fouls, second.Fouls);
        Assert.Equal(first.Next, second.Next);
    }

    [Fact]
    public void AStateOfAnotherGameIsRefused() =>
        Assert.Throws<ArgumentException>(() => RefereeOf(GameRules.EightBall).Judge(NineBall, ShotBuilder.Of(GameRules.NineBall).Record()));
}
