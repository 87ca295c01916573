using System.Text;
using Billiards.Core.Ai;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Ai.PlannerKit;

namespace Billiards.Core.Tests.Ai;

/// <summary>Shards of a self-play run, and summaries that merge into the whole run's.</summary>
public class SelfPlaySummaryTests
{
    [Theory]
    [InlineData("0/1", 0, 1)]
    [InlineData("3/4", 3, 4)]
    public void AShardIsKOfN(string text, int k, int n)
    {
        Assert.Equal(new SelfPlayShard(k, n), SelfPlayShard.TryParse(text, out _));
    }

    [Theory]
    [InlineData("4/4", "K from 0 to N - 1 = 3")]
    [InlineData("0/0", "N >= 1")]
    [InlineData("-1/2", "K/N")]
    [InlineData("1", "K/N")]
    [InlineData("a/b", "K/N")]
    public void ABadShardIsRefusedWithItsReason(string text, string reason)
    {
        Assert.Null(SelfPlayShard.TryParse(text, out string problem));
        Assert.Contains(reason, problem, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(10, 3)]
    [InlineData(2, 4)]
    [InlineData(40, 2)]
    public void TheShardsPlayEveryGameOfTheRunOnce(int games, int n)
    {
        var all = Enumerable.Range(0, n).SelectMany(k => new SelfPlayShard(k, n).Games(games)).Order();
        Assert.Equal(Enumerable.Range(0, games), all);
        for (int k = 0; k < n; k++)
        {
            var shard = new SelfPlayShard(k, n);
            Assert.All(shard.Games(games), g => Assert.Equal(k, g % n));
            Assert.Equal(shard.Games(games).Count(), shard.GameCount(games));
        }
    }

    [Fact]
    public void HistogramBinsAreFixedAndTheirQuantilesLieWithinTheBin()
    {
        for (int bin = 0; bin < DecisionHistogram.BinCount; bin++)
        {
            // The middle of a bin falls into it (a bin is 10^(1/20), about 12 %, wide).
            Assert.Equal(bin, DecisionHistogram.Bin(Math.Sqrt(DecisionHistogram.Edge(bin) * DecisionHistogram.Edge(bin + 1))));
        }
        Assert.Equal(0, DecisionHistogram.Bin(0));
        Assert.Equal(DecisionHistogram.BinCount - 1, DecisionHistogram.Bin(1e12));
        var counts = new long[DecisionHistogram.BinCount];
        counts[DecisionHistogram.Bin(3.7)] = 19;
        counts[DecisionHistogram.Bin(250)] = 1;
        var h = new DecisionHistogram(counts);
        Assert.Equal(3.7, h.Quantile(0.5), 3.7 * 0.06);
        Assert.Equal(3.7, h.Quantile(0.95), 3.7 * 0.06);
        Assert.Equal(250, h.Quantile(0.96), 250 * 0.06);
        Assert.Equal(40, h.Plus(h).Total);
        Assert.Equal(0, new DecisionHistogram(new long[DecisionHistogram.BinCount]).Quantile(0.5));
    }

    [Fact]
    public void MergedShardSummariesAreTheWholeRunsSummaryByteForByte()
    {
        const int games = 4;
        const long seed = 9;
        var levels = new PerPlayer<int>(1, 2);
        var selfPlay = new SelfPlay(Pool, Params);
        var played = Enumerable.Range(0, games)
            .Select(g => selfPlay.Play(GameRules.EightBall, levels, g % 2, PlannerRandom.Derive(seed, g), new PlannerBudget(600_000, 2)))
            .ToList();
        var whole = SelfPlaySummary.Of(GameRules.EightBall, seed, levels, GameState.DefaultTarget, games, SelfPlayShard.Whole, played, 0);

        var shards = new[] { new SelfPlayShard(1, 2), new SelfPlayShard(0, 2) }
            .Select(s => SelfPlaySummary.Of(GameRules.EightBall, seed, levels, GameState.DefaultTarget, games, s, [.. s.Games(games).Select(g => played[g])], 0))
            .ToList();
        // Through their JSON, as the files of the shards go.
        var read = shards.Select((s, i) => SelfPlaySummary.Parse(Encoding.UTF8.GetString(s.ToUtf8()), $"s{i}.json")).ToList();
        var merged = SelfPlaySummary.Merge(read, ["s0.json", "s1.json"]);

        Assert.Equal(Encoding.UTF8.GetString(whole.ToUtf8()), Encoding.UTF8.GetString(merged.ToUtf8()));
        Assert.True(whole.Players.First.Shots > 0 && whole.Players.Second.Shots > 0);
        Assert.Equal(whole.Players.First.Shots + whole.Players.Second.Shots, played.Sum(p => p.Shots.Count));
        Assert.Equal(whole.Players.First.Shots, whole.Players.First.Decisions.Total);
        Assert.Contains("\"shard\"", Encoding.UTF8.GetString(shards[0].ToUtf8()), StringComparison.Ordinal);
        Assert.DoesNotContain("\"shard\"", Encoding.UTF8.GetString(merged.ToUtf8()), StringComparison.Ordinal);
    }

    [Fact]
    public void SummariesOfDifferentRunsOrAMissingShardDoNotMerge()
    {
        var stats = new PlayerStats(3, 1, 10, 8, 5, 1, 1, 1, 0, 1, 4_000_000_000, new DecisionHistogram(new long[DecisionHistogram.BinCount]));
        SelfPlaySummary Shard(int k, long seed = 9, int levelB = 3) => new(GameRules.EightBall, seed, new PerPlayer<int>(3, levelB), GameState.DefaultTarget, 4,
            new SelfPlayShard(k, 2), 2, 0, new PerPlayer<PlayerStats>(stats, stats with { Level = levelB }), 10);

        Assert.Contains("$.seed: 8 differs from 9", Refused(Shard(0), Shard(1, seed: 8)), StringComparison.Ordinal);
        Assert.Contains("$.levels: 3,4 differs from 3,3", Refused(Shard(0), Shard(1, levelB: 4)), StringComparison.Ordinal);
        Assert.Contains("shard 0 of 2 is also a.json", Refused(Shard(0), Shard(0)), StringComparison.Ordinal);
        Assert.Contains("shard 1 of 2 is missing", Refused(Shard(0)), StringComparison.Ordinal);
        var ok = SelfPlaySummary.Merge([Shard(0), Shard(1)], ["a.json", "b.json"]);
        Assert.Equal(4, ok.Games);
        Assert.Equal(20, ok.Players.First.Shots);
        Assert.Equal(0.5, ok.Players.First.ExpectedPotRate, 12);
        Assert.Equal(20, ok.Milliseconds);
    }

    private static string Refused(params SelfPlaySummary[] summaries) =>
        Assert.Throws<SceneException>(() => SelfPlaySummary.Merge(summaries, [.. summaries.Select((_, i) => i == 0 ? "a.json" : "b.json")])).Message;

    [Fact]
    public void AShardSummaryWhoseGameCountDoesNotFitItsShardIsRefused()
    {
        var stats = new PlayerStats(1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, new DecisionHistogram(new long[DecisionHistogram.BinCount]));
        var s = new SelfPlaySummary(GameRules.NineBall, 1, new PerPlayer<int>(1, 1), GameState.DefaultTarget, 5, new SelfPlayShard(0, 2), 3, 0, new PerPlayer<PlayerStats>(stats, stats), 0);
        string text = Encoding.UTF8.GetString(s.ToUtf8());
        Assert.Equal(text, Encoding.UTF8.GetString(SelfPlaySummary.Parse(text, "x.json").ToUtf8()));
        var e = Assert.Throws<SceneException>(() => SelfPlaySummary.Parse(text.Replace("\"games\": 3", "\"games\": 2", StringComparison.Ordinal), "x.json"));
        Assert.Equal("x.json: $.games: 2 games, but shard 0 of 2 of a run of 5 plays 3", e.Message);
        Assert.StartsWith("x.json: $.format", Assert.Throws<SceneException>(() => SelfPlaySummary.Parse("{}", "x.json")).Message, StringComparison.Ordinal);
        Assert.StartsWith("x.json: $: not a billiards-selfplay/1 summary", Assert.Throws<SceneException>(() => SelfPlaySummary.Parse("{\"format\":\"billiards-selfplay/1\"}", "x.json")).Message, StringComparison.Ordinal);
    }
}
