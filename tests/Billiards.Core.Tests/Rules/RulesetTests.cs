using Billiards.Core.Balls;
using Billiards.Core.Rules;

namespace Billiards.Core.Tests.Rules;

/// <summary>Each game's ruleset answers the next shot's questions as rules.md has them.</summary>
public class RulesetTests
{
    private static readonly BallId[] Some = [new(2), new(3), new(8), new(9), new(12)];

    [Fact]
    public void EveryGameHasItsRulesetByNameTheShippedSixFirst()
    {
        Assert.Equal(["eight-ball", "nine-ball", "ten-ball", "straight-pool", "snooker", "three-cushion"], Ruleset.All.Take(6).Select(r => r.Name));
        Assert.All(Ruleset.All, r => Assert.Same(r, Ruleset.Find(r.Name)));
        Assert.All(Ruleset.All, r => Assert.Same(r, Ruleset.For(r.Game)));
        Assert.Equal(16, Ruleset.For(GameRules.EightBall).Balls.Count);
        Assert.Equal(10, Ruleset.For(GameRules.NineBall).Balls.Count);
        Assert.Equal(11, Ruleset.For(GameRules.TenBall).Balls.Count);
        Assert.All(Ruleset.All, r => Assert.Equal(r.CueBall(new GameState(r.Game)), r.Balls[0]));
    }

    [Theory]
    [InlineData("eight-ball", true)]
    [InlineData("nine-ball", false)]
    [InlineData("ten-ball", true)]
    [InlineData("straight-pool", true)]
    public void CalledGamesCallEveryShotAfterTheBreak(GameRules game, bool called)
    {
        var rules = Ruleset.For(game);
        Assert.False(rules.NeedsCall(new GameState(game)));
        Assert.Equal(called, rules.NeedsCall(new GameState(game) { Shot = 4 }));
    }

    [Theory]
    [InlineData("eight-ball", false)]
    [InlineData("nine-ball", true)]
    [InlineData("ten-ball", true)]
    [InlineData("straight-pool", false)]
    public void APushOutIsOnlyTheRotationGamesShotAfterTheBreak(GameRules game, bool pushOut)
    {
        var rules = Ruleset.For(game);
        Assert.Equal(pushOut, rules.MayPushOut(new GameState(game) { Shot = 1 }));
        Assert.False(rules.MayPushOut(new GameState(game) { Shot = 2 }));
    }

    [Fact]
    public void LegalTargetsFollowEachGame()
    {
        Assert.Equal([new BallId(2)], Ruleset.For(GameRules.NineBall).LegalTargets(new GameState(GameRules.NineBall), Some));
        Assert.Equal(Some, Ruleset.For(GameRules.StraightPool).LegalTargets(new GameState(GameRules.StraightPool), Some.Reverse()));
        var eight = Ruleset.For(GameRules.EightBall);
        Assert.Equal([new BallId(2), new BallId(3), new BallId(9), new BallId(12)], eight.LegalTargets(new GameState(GameRules.EightBall), Some));
        var stripes = new GameState(GameRules.EightBall) { Part = new EightBallPart { Groups = new(BallGroup.Stripes, BallGroup.Solids) } };
        Assert.Equal([new BallId(9), new BallId(12)], eight.LegalTargets(stripes, Some));
        Assert.Equal([new BallId(9), new BallId(12), new BallId(8)], eight.StillToPot(stripes, Some));
        Assert.Equal([new BallId(8)], eight.LegalTargets(stripes, [new BallId(2), new BallId(8)]));
        Assert.False(eight.MayCall(stripes, new BallId(2)));
        Assert.False(eight.MayCall(stripes, new BallId(8)));
        Assert.True(eight.MayCall(stripes, new BallId(9)));
    }

    [Fact]
    public void ARerackIsBrokenByTheChooserInEightBallAndByTheOffenderInStraightPool()
    {
        foreach (var (game, breaker) in new[] { (GameRules.EightBall, 1), (GameRules.StraightPool, 0) })
        {
            var next = new GameState(game) { Shooter = 1, Shot = 1, BallInHand = BallInHand.Table };
            var ruling = new Ruling(false, [Foul.BadBreak], [], false, BallInHand.Table, [], [RefereeOption.Accept, RefereeOption.Rerack], false, null, "", next);
            var outcome = Ruleset.For(game).Choose(ruling, RefereeOption.Rerack);
            Assert.True(outcome.Rerack);
            Assert.Equal(breaker, outcome.Next.Shooter);
            Assert.Equal(0, outcome.Next.Shot);
            Assert.Equal(BallInHand.None, outcome.Next.BallInHand);
            Assert.False(Ruleset.For(game).Choose(ruling, RefereeOption.Accept).Rerack);
            Assert.Throws<ArgumentException>(() => Ruleset.For(game).Choose(ruling, RefereeOption.PassBack));
        }
    }

    [Fact]
    public void TheHudShowsWhatEachPlayerStillNeeds()
    {
        var stripes = new GameState(GameRules.EightBall) { Part = new EightBallPart { Groups = new(BallGroup.Stripes, BallGroup.Solids) } };
        var eight = Ruleset.For(GameRules.EightBall);
        Assert.Equal("stripes: 9 12", eight.Target(stripes, 0, Some).Text);
        Assert.Equal([new BallId(2), new BallId(3)], eight.Target(stripes, 1, Some).Balls);
        Assert.Equal("solids, on the 8", eight.Target(stripes, 1, [new BallId(8), new BallId(9)]).Text);
        Assert.Equal("open table", eight.Target(new GameState(GameRules.EightBall), 0, Some).Text);
        Assert.Equal("on the 2", Ruleset.For(GameRules.NineBall).Target(new GameState(GameRules.NineBall), 0, Some).Text);
        Assert.Equal("5 balls on the table", Ruleset.For(GameRules.StraightPool).Target(new GameState(GameRules.StraightPool), 0, Some).Text);
    }

    [Fact]
    public void AVisitEndsWithAShotThatDoesNotKeepTheShooterAtTheTableAndItsBreakIsTheBallsThatStayedDown()
    {
        var state = new GameState(GameRules.StraightPool);
        (int, Ruling) Shot(int shooter, bool legal, bool go, int[] pocketed, int[] spotted) =>
            (shooter, new Ruling(legal, [], [.. pocketed.Select(b => new BallId(b))], go, BallInHand.None, [.. spotted.Select(b => new BallId(b))], [], false, null, "", state));
        var shots = new[]
        {
            // Anna: two balls, then a miss (2).
            Shot(0, true, true, [3, 5], []), Shot(0, true, false, [], []),
            // Ben: a ball, then a ball pocketed with the one he called spotted (1), then a foul (no ball counts).
            Shot(1, true, true, [7], []), Shot(1, true, true, [9, 10], [10]), Shot(1, false, false, [11], []),
            // Anna put back in after the foul: a new visit, still at the table when the shots end.
            Shot(0, true, true, [12], []),
        };
        var visits = Ruleset.For(GameRules.StraightPool).Visits(shots).ToList();
        Assert.Equal([new Visit(0, 2, 2, false), new Visit(1, 3, 2, false), new Visit(0, 1, 1, true)], visits);
        // Snooker counts points, not balls: the same shots' rulings have no points.
        Assert.All(Ruleset.For(GameRules.Snooker).Visits(shots), v => Assert.Equal(0, v.Break));
        Assert.Equal("the 14.1 game", Ruleset.For(GameRules.StraightPool).TheGame);
        Assert.Equal(("break", "frame", "the frame"), (Ruleset.For(GameRules.Snooker).BreakWord, Ruleset.For(GameRules.Snooker).GameWord, Ruleset.For(GameRules.Snooker).TheGame));
        Assert.Null(Ruleset.For(GameRules.EightBall).PointsRemaining(new GameState(GameRules.EightBall), Some));
    }
}
