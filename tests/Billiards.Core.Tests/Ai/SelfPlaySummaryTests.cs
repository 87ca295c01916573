using System.Text;
using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
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

        // The breaks and game lengths merge too: sums add, the highest break is the shards' highest.
        Assert.Equal(whole.Shots, merged.Shots);
        Assert.Equal(whole.MeanGameShots, merged.MeanGameShots);
        Assert.Equal((double)played.Sum(p => p.Shots.Count) / games, merged.MeanGameShots, 12);
        for (int p = 0; p < 2; p++)
        {
            var w = whole.Players[p];
            Assert.Equal(w, merged.Players[p] with { Decisions = w.Decisions });
            Assert.Equal(read.Max(s => s.Players[p].HighestBreak), w.HighestBreak);
            Assert.Equal(read.Sum(s => s.Players[p].BreakSum), w.BreakSum);
            Assert.Equal(read.Sum(s => s.Players[p].Visits), w.Visits);
            // Every shot lies in one visit: in pool the breaks add up to the balls that stayed down on legal shots.
            Assert.Equal(played.SelectMany(g => g.Shots).Where(s => s.Before.Shooter == p && s.Ruling.Legal)
                .Sum(s => s.Ruling.Pocketed.Except(s.Ruling.Spot).Count()), w.BreakSum);
            Assert.True(w.Visits >= w.ScoringVisits && w.ScoringVisits > 0 && w.HighestBreak > 0);
        }
    }

    [Fact]
    public void SnookerBreaksArePointsPerVisitAndTheMeanIsOverScoringVisits()
    {
        // P0 breaks off (0); P1 red, black, red, then misses (9); P0 fouls (0: the penalty is
        // P1's), is put back in, pots a red and the pink and plays safe (7); P1 pots a red when the
        // game is cut off (1, a visit all the same).
        var game = Game(GameRules.Snooker, "snooker-12ft",
            [.. Visit(0, 0), .. Visit(1, 1, 7, 1, 0), Fouled(0), .. Visit(0, 1, 6, 0), Shot(1, true, true, 1)]);
        var p0 = SelfPlayStats.Of([game], 0, 5);
        var p1 = SelfPlayStats.Of([game], 1, 5);

        Assert.Equal([0, 0, 7], SelfPlayStats.Visits(game, 0));
        Assert.Equal([9, 1], SelfPlayStats.Visits(game, 1));
        Assert.Equal((3, 1, 7, 7), (p0.Visits, p0.ScoringVisits, p0.BreakSum, p0.HighestBreak));
        Assert.Equal((2, 2, 10, 9), (p1.Visits, p1.ScoringVisits, p1.BreakSum, p1.HighestBreak));
        // Snooker's mean break: the visits that scored nothing are left out (7 / 1, not 7 / 3).
        Assert.Equal(7, p0.MeanBreak);
        Assert.Equal(5, p1.MeanBreak);

        var summary = SelfPlaySummary.Of(GameRules.Snooker, 3, new PerPlayer<int>(5, 5), GameState.DefaultTarget, 1, SelfPlayShard.Whole, [game], 0);
        string json = Encoding.UTF8.GetString(summary.ToUtf8());
        Assert.Contains("\"shots\": 10,", json, StringComparison.Ordinal);
        Assert.Contains("\"mean_game_shots\": 10,", json, StringComparison.Ordinal);
        Assert.Contains("\"break_unit\": \"points\"", json, StringComparison.Ordinal);
        Assert.Contains("\"mean_break\": 5,", json, StringComparison.Ordinal);
        Assert.Contains("\"highest_break\": 9", json, StringComparison.Ordinal);
        Assert.Equal(json, Encoding.UTF8.GetString(SelfPlaySummary.Parse(json, "s.json").ToUtf8()));
    }

    [Fact]
    public void PoolBreaksAreTheBallsPocketedOnLegalShotsOfAVisitThatStayDown()
    {
        // P0 pockets 2 on the break and 1 more, then scratches with the 5 (not counted): 3.
        // P1 pockets one, then misses the call with the 10, which is spotted (not counted): 1.
        // P0 pockets 1 and plays safe: 1.
        var game = Game(GameRules.StraightPool, "pool-9ft",
            [Shot(0, true, true, 0, 1, 2), Shot(0, true, true, 0, 3), Shot(0, false, false, 0, 5),
            Shot(1, true, true, 0, 9), Respotted(Shot(1, true, false, 0, 10)),
            Shot(0, true, true, 0, 4), Shot(0, true, false, 0)]);

        Assert.Equal([3, 1], SelfPlayStats.Visits(game, 0));
        Assert.Equal([1], SelfPlayStats.Visits(game, 1));
        var p0 = SelfPlayStats.Of([game], 0, 3);
        Assert.Equal((2, 2, 4, 3, 2.0), (p0.Visits, p0.ScoringVisits, p0.BreakSum, p0.HighestBreak, p0.MeanBreak));
        var summary = SelfPlaySummary.Of(GameRules.StraightPool, 3, new PerPlayer<int>(3, 3), GameState.DefaultTarget, 1, SelfPlayShard.Whole, [game], 0);
        Assert.Contains("\"break_unit\": \"balls\"", Encoding.UTF8.GetString(summary.ToUtf8()), StringComparison.Ordinal);
    }

    private static readonly ShotSpec Strike = new(2, 0);

    // A visit whose shots score each of points; the last ends it.
    private static SelfPlayShot[] Visit(int shooter, params int[] points) =>
        [.. points.Select((p, i) => Shot(shooter, true, i < points.Length - 1, p))];

    private static SelfPlayShot Shot(int shooter, bool legal, bool stays, int points, params int[] pocketed)
    {
        var before = new GameState(GameRules.Snooker) { Shooter = shooter };
        var ruling = new Ruling(legal, legal ? [] : [Foul.WrongBallFirst], [.. pocketed.Select(n => new BallId(n))], stays, BallInHand.None, [], [],
            false, null, "", before with { Shooter = stays ? shooter : 1 - shooter })
        {
            Points = points,
            Penalty = legal ? 0 : 4,
        };
        return new SelfPlayShot(before, null, Strike, Strike, ShotKind.Direct, ruling, null, 1, 1);
    }

    // The shot with the balls it pocketed spotted again.
    private static SelfPlayShot Respotted(SelfPlayShot shot) => shot with { Ruling = shot.Ruling with { Spot = shot.Ruling.Pocketed } };

    // A foul that scores nothing for the shooter.
    private static SelfPlayShot Fouled(int shooter) => Shot(shooter, false, false, 0);

    // Only the shooter and the ruling of each shot count for the breaks; the first shot is the break-off.
    private static PlayedGame Game(GameRules rules, string table, IEnumerable<SelfPlayShot> shots)
    {
        var setup = new GameSetup(TableSpec.FromPreset(table), Planner.PhysicsConfig, 1, new GameState(rules));
        return new PlayedGame(rules, new PerPlayer<int>(5, 5), 0, [.. shots.Select((s, i) => s with { Before = s.Before with { Rules = rules, Shot = i } })], null, new Match(setup));
    }

    [Fact]
    public void SummariesOfDifferentRunsOrAMissingShardDoNotMerge()
    {
        var stats = new PlayerStats(3, 1, 10, 8, 5, 1, 1, 1, 0, 1, 4, 3, 21, 12, 4_000_000_000, new DecisionHistogram(new long[DecisionHistogram.BinCount]));
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
        var stats = new PlayerStats(1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, new DecisionHistogram(new long[DecisionHistogram.BinCount]));
        var s = new SelfPlaySummary(GameRules.NineBall, 1, new PerPlayer<int>(1, 1), GameState.DefaultTarget, 5, new SelfPlayShard(0, 2), 3, 0, new PerPlayer<PlayerStats>(stats, stats), 0);
        string text = Encoding.UTF8.GetString(s.ToUtf8());
        Assert.Equal(text, Encoding.UTF8.GetString(SelfPlaySummary.Parse(text, "x.json").ToUtf8()));
        var e = Assert.Throws<SceneException>(() => SelfPlaySummary.Parse(text.Replace("\"games\": 3", "\"games\": 2", StringComparison.Ordinal), "x.json"));
        Assert.Equal("x.json: $.games: 2 games, but shard 0 of 2 of a run of 5 plays 3", e.Message);
        Assert.StartsWith("x.json: $.format", Assert.Throws<SceneException>(() => SelfPlaySummary.Parse("{}", "x.json")).Message, StringComparison.Ordinal);
        Assert.StartsWith("x.json: $: not a billiards-selfplay/1 summary", Assert.Throws<SceneException>(() => SelfPlaySummary.Parse("{\"format\":\"billiards-selfplay/1\"}", "x.json")).Message, StringComparison.Ordinal);
    }
}
