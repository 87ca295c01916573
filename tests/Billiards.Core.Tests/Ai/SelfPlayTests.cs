using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
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
    public void TheGameRecordReplaysRulingForRuling()
    {
        var selfPlay = new SelfPlay(Pool, Params);
        var game = selfPlay.Play(GameRules.EightBall, new PerPlayer<int>(3, 1), 1, 5, new PlannerBudget(600_000, 2));

        // The record is the game player's: the same shots, struck as executed, judged the same way.
        Assert.Equal(game.Shots.Count, game.Record.Shots.Count);
        for (int i = 0; i < game.Shots.Count; i++)
        {
            Assert.Equal(game.Shots[i].Executed, game.Record.Shots[i].Input.Shot);
            Assert.Equal(game.Shots[i].Ruling, game.Record.Shots[i].Ruling);
        }
        Assert.Equal(1, game.Shots[0].Before.Shooter);
        byte[] written = GameRecordFile.ToUtf8(game.Record);
        var record = GameRecordFile.Parse(System.Text.Encoding.UTF8.GetString(written), "game.json");
        Assert.Equal(-1, GameRecordFile.Replay(record, out var replayed));
        Assert.Equal(written, GameRecordFile.ToUtf8(replayed));
    }

    [Fact]
    public void StraightPoolIsPlayedToItsTarget()
    {
        var selfPlay = new SelfPlay(Pool, Params);
        var game = selfPlay.Play(GameRules.StraightPool, new PerPlayer<int>(4, 4), 0, 3, new PlannerBudget(600_000, 2), target: 8);

        var w = Assert.NotNull(game.Winner);
        var last = game.Shots[^1];
        Assert.True(last.Ruling.GameOver);
        Assert.Equal(w, last.Before.Shooter);
        // A point per ball legally pocketed: the winning shot brings the winner to the target.
        int points = last.Before.Score[w] + last.Ruling.Pocketed.Count(b => !PoolBalls.IsCue(b));
        Assert.True(last.Ruling.Legal);
        Assert.True(last.Before.Score[w] < 8 && points >= 8, $"winner's score {last.Before.Score[w]} + {points - last.Before.Score[w]}");
        // Every shot after the break is called (14.1 is call-shot).
        Assert.All(game.Shots.Skip(1), s => Assert.NotNull(s.Before.Call));
    }
}
