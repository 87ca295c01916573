using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using static Billiards.Core.Tests.Ai.PlannerKit;

namespace Billiards.Core.Tests.Ai;

/// <summary>Whole games of the computer against itself, and the figures drawn from them.</summary>
public class SelfPlayTests
{
    [Fact]
    public void AGameEndsWithTheRefereesWinnerAndReplaysBitForBit()
    {
        var selfPlay = new SelfPlay(Pool, Params);
        var game = selfPlay.Play(GameRules.NineBall, new PerPlayer<int>(2, 2), 0, 17, new PlannerBudget(600_000, 2));

        Assert.NotEmpty(game.Shots);
        Assert.Equal(0, game.Shots[0].Before.Shooter);
        Assert.Equal(0, game.Shots[0].Before.Shot);
        if (game.Winner is { } w)
        {
            Assert.True(game.Shots[^1].Ruling.GameOver);
            Assert.Equal(w, game.Shots[^1].Ruling.Winner);
        }
        // Each shot's state is the previous ruling's next state (or the option's) with the shooter's call.
        for (int i = 1; i < game.Shots.Count; i++)
        {
            var previous = game.Shots[i - 1];
            var expected = previous.Option is { } o ? previous.Ruling.Choose(o).Next : previous.Ruling.Next;
            Assert.Equal(expected.Shooter, game.Shots[i].Before.Shooter);
            Assert.Equal(expected.FoulsInRow, game.Shots[i].Before.FoulsInRow);
        }
        var again = selfPlay.Play(GameRules.NineBall, new PerPlayer<int>(2, 2), 0, 17, new PlannerBudget(600_000, 1));
        Assert.Equal(game.Shots.Count, again.Shots.Count);
        Assert.Equal(game.Shots.Select(s => s.Executed), again.Shots.Select(s => s.Executed));
        Assert.Equal(game.Winner, again.Winner);
    }

    [Fact]
    public void StatsCountWinsBreakAndRunsAndPercentiles()
    {
        Assert.Equal(2, SelfPlayStats.Percentile([1, 2, 3, 4], 0.5));
        Assert.Equal(4, SelfPlayStats.Percentile([1, 2, 3, 4], 0.95));
        Assert.Equal(0, SelfPlayStats.Percentile([], 0.5));
        Assert.Equal(7, SelfPlayStats.Percentile([7], 0.95));
    }

    [Fact]
    public void SpottedBallsGoOnTheFootSpotOrBehindIt()
    {
        var spot = Billiards.Core.Setup.Initializer.FootSpot(Pool, Params.R);
        var position = new TablePosition([(BallId.Cue, new Vec3(-0.5, 0, Params.R))]);
        var one = position.Spotted([new BallId(9)], Pool, Params.R);
        Assert.Equal(spot, one.Positions[one.IndexOf(new BallId(9))]);

        var occupied = new TablePosition([(BallId.Cue, spot)]);
        var behind = occupied.Spotted([new BallId(9)], Pool, Params.R);
        var p = behind.Positions[behind.IndexOf(new BallId(9))];
        Assert.Equal(0, p.Y);
        Assert.InRange(p.X - spot.X, 2 * Params.R, 2 * Params.R + Params.R / 8 + 1e-12);
    }
}
