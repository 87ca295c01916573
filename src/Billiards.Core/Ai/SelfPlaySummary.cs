using System.Globalization;
using System.Text.Json;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.Core.Ai;

/// <summary>
/// Shard <see cref="Index"/> of <see cref="Count"/> of a self-play run: the games whose index g
/// (0-based, in the unsharded run's order) has g mod <see cref="Count"/> = <see cref="Index"/>,
/// each with the unsharded run's seed and breaker, so the shards together play exactly its games.
/// </summary>
/// <param name="Index">K, from 0 to <see cref="Count"/> - 1.</param>
/// <param name="Count">N, at least 1.</param>
public readonly record struct SelfPlayShard(int Index, int Count)
{
    /// <summary>The whole run as one shard (0 of 1).</summary>
    public static SelfPlayShard Whole => new(0, 1);

    /// <summary>True for the whole run.</summary>
    public bool IsWhole => Count == 1;

    /// <summary>The indexes of this shard's games in a run of <paramref name="runGames"/> games, in order.</summary>
    public IEnumerable<int> Games(int runGames)
    {
        for (int g = Index; g < runGames; g += Count)
        {
            yield return g;
        }
    }

    /// <summary>How many games of a run of <paramref name="runGames"/> this shard plays.</summary>
    public int GameCount(int runGames) => runGames > Index ? (runGames - Index + Count - 1) / Count : 0;

    /// <summary>
    /// Parses "K/N" (0 &lt;= K &lt; N); returns null and a reason when the text is not one.
    /// </summary>
    public static SelfPlayShard? TryParse(string text, out string problem)
    {
        ArgumentNullException.ThrowIfNull(text);
        var parts = text.Split('/');
        if (parts.Length != 2
            || !int.TryParse(parts[0], NumberStyles.None, CultureInfo.InvariantCulture, out int k)
            || !int.TryParse(parts[1], NumberStyles.None, CultureInfo.InvariantCulture, out int n))
        {
            problem = "expected K/N, two whole numbers, e.g. 0/4";
            return null;
        }
        if (n < 1)
        {
            problem = "expected N >= 1 shards";
            return null;
        }
        if (k >= n)
        {
            problem = $"expected K from 0 to N - 1 = {n - 1}";
            return null;
        }
        problem = "";
        return new SelfPlayShard(k, n);
    }
}

/// <summary>
/// The summary of a self-play run or of one shard of it ("billiards-selfplay/1"): what the run
/// was (rules, levels, seed, target, games), the shard, and per player counts that add up
/// (<see cref="PlayerStats"/>: sums, and the highest break, a maximum); every rate and mean in it
/// (pot rate, mean break, <see cref="MeanGameShots"/>) is derived from those counts. <see cref="Merge"/>
/// turns the summaries of every shard of a run into the summary the unsharded run prints: every
/// count equal, so every rate and mean, the decision-time quantiles from the summed histograms;
/// only <see cref="Milliseconds"/> (wall clock) is a sum of the shards'.
/// </summary>
/// <param name="Rules">The game.</param>
/// <param name="Seed">The run's seed.</param>
/// <param name="Levels">The two players' levels.</param>
/// <param name="Target">14.1's score to win (written for straight pool only).</param>
/// <param name="RunGames">The games of the whole run.</param>
/// <param name="Shard">Which shard this summary counts (<see cref="SelfPlayShard.Whole"/> for a whole run).</param>
/// <param name="Games">The games this summary counts.</param>
/// <param name="Unfinished">Of those, the games that hit the shot limit unfinished (a drawn three-cushion game is finished).</param>
/// <param name="Players">The two players' figures, player 0 first.</param>
/// <param name="Milliseconds">Wall-clock time of the run (ms); of a merged run, the sum of its shards'.</param>
public sealed record SelfPlaySummary(GameRules Rules, long Seed, PerPlayer<int> Levels, int Target, int RunGames, SelfPlayShard Shard, int Games, int Unfinished, PerPlayer<PlayerStats> Players, double Milliseconds)
{
    /// <summary>The format tag of a summary.</summary>
    public const string Format = "billiards-selfplay/1";

    /// <summary>The run's execution noise (<c>fastfiz:K</c>, the JSON's "noise"), or null for a run without.</summary>
    public ExecutionNoise? Noise { get; init; }

    /// <summary>What each player's search took the stroke's error to be (the JSON's "planners", written when one is not <see cref="SearchError.Own"/>).</summary>
    public PerPlayer<SearchError> Planners { get; init; }

    /// <summary>The shots of every game counted, both players' (breaks included).</summary>
    public int Shots => Players.First.Shots + Players.Second.Shots;

    /// <summary>
    /// The mean length of a game (a frame in snooker) in shots: <see cref="Shots"/> / <see cref="Games"/>,
    /// over every game counted (an unfinished one with the shots it had), 0 without a game.
    /// </summary>
    public double MeanGameShots => Games > 0 ? (double)Shots / Games : 0;

    /// <summary>The summary of <paramref name="games"/>, the games shard <paramref name="shard"/> of the run played.</summary>
    public static SelfPlaySummary Of(GameRules rules, long seed, PerPlayer<int> levels, int target, int runGames, SelfPlayShard shard, IReadOnlyList<PlayedGame> games, double milliseconds)
    {
        ArgumentNullException.ThrowIfNull(games);
        return new SelfPlaySummary(rules, seed, levels, target, runGames, shard, games.Count, games.Count(g => !g.Record.IsOver),
            new PerPlayer<PlayerStats>(SelfPlayStats.Of(games, 0, levels.First), SelfPlayStats.Of(games, 1, levels.Second)), milliseconds);
    }

    /// <summary>
    /// Merges the summaries of all shards of one run, each once, into the whole run's summary.
    /// <paramref name="files"/> names each summary in errors.
    /// </summary>
    /// <exception cref="SceneException">When the summaries are not the shards of one run (different rules, levels, seed, target or game count; a shard missing or twice).</exception>
    public static SelfPlaySummary Merge(IReadOnlyList<SelfPlaySummary> summaries, IReadOnlyList<string> files)
    {
        ArgumentNullException.ThrowIfNull(summaries);
        ArgumentNullException.ThrowIfNull(files);
        if (summaries.Count == 0 || files.Count != summaries.Count)
        {
            throw new ArgumentException("expected one file name per summary, and at least one summary", nameof(files));
        }
        var first = summaries[0];
        var seen = new string?[first.Shard.Count];
        for (int i = 0; i < summaries.Count; i++)
        {
            var s = summaries[i];
            string file = files[i];
            Same(file, "$.rules", s.Rules.ToName(), first.Rules.ToName(), files[0]);
            Same(file, "$.seed", s.Seed, first.Seed, files[0]);
            Same(file, "$.levels", $"{s.Levels.First},{s.Levels.Second}", $"{first.Levels.First},{first.Levels.Second}", files[0]);
            Same(file, "$.target", s.Target, first.Target, files[0]);
            Same(file, "$.noise", s.Noise?.ToString(), first.Noise?.ToString(), files[0]);
            Same(file, "$.planners", s.Planners, first.Planners, files[0]);
            Same(file, "$.shard.run_games", s.RunGames, first.RunGames, files[0]);
            Same(file, "$.shard.count", s.Shard.Count, first.Shard.Count, files[0]);
            if (seen[s.Shard.Index] is { } other)
            {
                throw new SceneException(file, "$.shard.index", $"shard {s.Shard.Index} of {s.Shard.Count} is also {other}");
            }
            seen[s.Shard.Index] = file;
        }
        int missing = Array.IndexOf(seen, null);
        if (missing >= 0)
        {
            throw new SceneException(files[0], "$.shard", $"shard {missing} of {first.Shard.Count} is missing (given: {summaries.Count} of {first.Shard.Count})");
        }
        var players = first.Players;
        int games = first.Games, unfinished = first.Unfinished;
        double ms = first.Milliseconds;
        foreach (var s in summaries.Skip(1))
        {
            players = new PerPlayer<PlayerStats>(players.First.Plus(s.Players.First), players.Second.Plus(s.Players.Second));
            games += s.Games;
            unfinished += s.Unfinished;
            ms += s.Milliseconds;
        }
        return first with { Shard = SelfPlayShard.Whole, Games = games, Unfinished = unfinished, Players = players, Milliseconds = ms };
    }

    private static void Same<T>(string file, string path, T value, T expected, string firstFile)
    {
        if (!EqualityComparer<T>.Default.Equals(value, expected))
        {
            throw new SceneException(file, path, $"{value} differs from {expected} in {firstFile}: not a shard of the same run");
        }
    }

    /// <summary>The summary as indented UTF-8 JSON.</summary>
    public byte[] ToUtf8()
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("format", Format);
            w.WriteString("rules", Rules.ToName());
            w.WriteNumber("games", Games);
            w.WriteNumber("seed", Seed);
            w.WriteStartArray("levels");
            w.WriteNumberValue(Levels.First);
            w.WriteNumberValue(Levels.Second);
            w.WriteEndArray();
            if (Ruleset.For(Rules).HasScore)
            {
                w.WriteNumber("target", Target);
            }
            if (Noise is { } noise)
            {
                w.WriteString("noise", noise.ToString());
            }
            if (Planners != default)
            {
                w.WriteStartArray("planners");
                w.WriteStringValue(PlannerName(Planners.First));
                w.WriteStringValue(PlannerName(Planners.Second));
                w.WriteEndArray();
            }
            if (!Shard.IsWhole)
            {
                w.WriteStartObject("shard");
                w.WriteNumber("index", Shard.Index);
                w.WriteNumber("count", Shard.Count);
                w.WriteNumber("run_games", RunGames);
                w.WriteEndObject();
            }
            w.WriteNumber("unfinished", Unfinished);
            w.WriteNumber("shots", Shots);
            w.WriteNumber("mean_game_shots", Round(MeanGameShots));
            w.WriteString("break_unit", Ruleset.For(Rules).BreakUnit);
            w.WriteStartArray("players");
            for (int player = 0; player < 2; player++)
            {
                WritePlayer(w, player, Players[player], Ruleset.For(Rules).HasInnings);
            }
            w.WriteEndArray();
            w.WriteNumber("ms", Round(Milliseconds));
            w.WriteEndObject();
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }

    private static void WritePlayer(Utf8JsonWriter w, int player, PlayerStats s, bool innings)
    {
        w.WriteStartObject();
        w.WriteNumber("player", player);
        w.WriteNumber("level", s.Level);
        w.WriteNumber("games_won", s.GamesWon);
        if (innings)
        {
            // Three-cushion's score sheet: a visit is an inning, its break the run of points.
            w.WriteNumber("points", s.BreakSum);
            w.WriteNumber("innings", s.Visits);
            w.WriteNumber("average", ThreeCushionRuleset.AverageValue(s.BreakSum, s.Visits));
            w.WriteNumber("highest_run", s.HighestBreak);
        }
        w.WriteNumber("shots", s.Shots);
        w.WriteNumber("pots", s.Pots);
        w.WriteNumber("pot_attempts", s.PotAttempts);
        w.WriteNumber("pot_rate", Round(s.PotRate));
        w.WriteNumber("expected_pot_rate", Round(s.ExpectedPotRate));
        w.WriteNumber("expected_pot_sum_e9", s.ExpectedPotSumE9);
        w.WriteNumber("fouls", s.Fouls);
        w.WriteNumber("breaks", s.Breaks);
        w.WriteNumber("potting_breaks", s.PottingBreaks);
        w.WriteNumber("break_and_runs", s.BreakAndRuns);
        w.WriteNumber("run_outs", s.RunOuts);
        w.WriteNumber("visits", s.Visits);
        w.WriteNumber("scoring_visits", s.ScoringVisits);
        w.WriteNumber("break_sum", s.BreakSum);
        w.WriteNumber("mean_break", Round(s.MeanBreak));
        w.WriteNumber("highest_break", s.HighestBreak);
        w.WriteStartObject("decision_ms");
        w.WriteNumber("median", Round(s.DecisionMedianMs));
        w.WriteNumber("p95", Round(s.DecisionP95Ms));
        w.WriteStartObject("histogram");
        w.WriteNumber("first_edge_ms", DecisionHistogram.FirstEdgeMs);
        w.WriteNumber("bins_per_decade", DecisionHistogram.BinsPerDecade);
        w.WriteNumber("bins", DecisionHistogram.BinCount);
        // Only the bins that hold a time, as [bin, count] pairs: most of the 160 are empty.
        w.WriteStartArray("counts");
        for (int i = 0; i < DecisionHistogram.BinCount; i++)
        {
            if (s.Decisions.Counts[i] > 0)
            {
                w.WriteStartArray();
                w.WriteNumberValue(i);
                w.WriteNumberValue(s.Decisions.Counts[i]);
                w.WriteEndArray();
            }
        }
        w.WriteEndArray();
        w.WriteEndObject();
        w.WriteEndObject();
        w.WriteEndObject();
    }

    /// <summary>Parses a summary; <paramref name="file"/> names it in errors.</summary>
    /// <exception cref="SceneException">When the text is not a summary this program writes.</exception>
    public static SelfPlaySummary Parse(string json, string file)
    {
        using (var doc = SceneLoader.ParseJson(json, file))
        {
            try
            {
                return Read(doc.RootElement, file);
            }
            catch (Exception e) when (e is InvalidOperationException or KeyNotFoundException or FormatException or ArgumentException or IndexOutOfRangeException)
            {
                throw new SceneException(file, "$", $"not a {Format} summary ({e.Message})");
            }
        }
    }

    private static SelfPlaySummary Read(JsonElement root, string file)
    {
        string format = root.TryGetProperty("format", out var f) ? f.GetString() ?? "" : "";
        if (format != Format)
        {
            throw new SceneException(file, "$.format", $"expected \"{Format}\", found \"{format}\"");
        }
        string rulesName = root.GetProperty("rules").GetString() ?? "";
        if (!RuleNames.TryParseGame(rulesName, out var rules))
        {
            throw new SceneException(file, "$.rules", $"unknown game \"{rulesName}\"");
        }
        var levels = root.GetProperty("levels");
        var pair = new PerPlayer<int>(levels[0].GetInt32(), levels[1].GetInt32());
        int games = root.GetProperty("games").GetInt32();
        int target = root.TryGetProperty("target", out var t) ? t.GetInt32() : GameState.DefaultTarget;
        var shard = SelfPlayShard.Whole;
        int runGames = games;
        if (root.TryGetProperty("shard", out var sh))
        {
            int index = sh.GetProperty("index").GetInt32(), count = sh.GetProperty("count").GetInt32();
            runGames = sh.GetProperty("run_games").GetInt32();
            if (SelfPlayShard.TryParse($"{index}/{count}", out string problem) is not { } parsed)
            {
                throw new SceneException(file, "$.shard", problem);
            }
            shard = parsed;
            if (shard.GameCount(runGames) != games)
            {
                throw new SceneException(file, "$.games", $"{games} games, but shard {index} of {count} of a run of {runGames} plays {shard.GameCount(runGames)}");
            }
        }
        ExecutionNoise? noise = null;
        if (root.TryGetProperty("noise", out var n))
        {
            string text = n.GetString() ?? "";
            noise = ExecutionNoise.TryParse(text, out string problem) ?? throw new SceneException(file, "$.noise", problem);
        }
        var planners = default(PerPlayer<SearchError>);
        if (root.TryGetProperty("planners", out var pl))
        {
            planners = new PerPlayer<SearchError>(ParsePlanner(pl[0].GetString(), file), ParsePlanner(pl[1].GetString(), file));
        }
        var players = root.GetProperty("players");
        var stats = new PlayerStats[2];
        for (int p = 0; p < 2; p++)
        {
            stats[p] = ReadPlayer(players[p], file, p, p == 0 ? pair.First : pair.Second);
        }
        return new SelfPlaySummary(rules, root.GetProperty("seed").GetInt64(), pair, target, runGames, shard, games,
            root.GetProperty("unfinished").GetInt32(), new PerPlayer<PlayerStats>(stats[0], stats[1]), root.GetProperty("ms").GetDouble())
        {
            Noise = noise,
            Planners = planners,
        };
    }

    /// <summary>A planner's name on the command line and in the summary: <c>own</c>, <c>noise</c> or <c>blind</c>.</summary>
    public static string PlannerName(SearchError error) => error switch
    {
        SearchError.Noise => "noise",
        SearchError.Exact => "blind",
        _ => "own",
    };

    /// <summary>The planner named <paramref name="name"/> (<see cref="PlannerName"/>), or null.</summary>
    public static SearchError? TryParsePlanner(string? name) => name switch
    {
        "own" => SearchError.Own,
        "noise" => SearchError.Noise,
        "blind" => SearchError.Exact,
        _ => null,
    };

    private static SearchError ParsePlanner(string? name, string file) =>
        TryParsePlanner(name) ?? throw new SceneException(file, "$.planners", $"unknown planner \"{name}\" (expected own, noise or blind)");

    private static PlayerStats ReadPlayer(JsonElement p, string file, int player, int level)
    {
        string path = $"$.players[{player}]";
        if (p.GetProperty("level").GetInt32() != level)
        {
            throw new SceneException(file, path + ".level", $"differs from $.levels[{player}] = {level}");
        }
        var h = p.GetProperty("decision_ms").GetProperty("histogram");
        if (h.GetProperty("first_edge_ms").GetDouble() != DecisionHistogram.FirstEdgeMs
            || h.GetProperty("bins_per_decade").GetInt32() != DecisionHistogram.BinsPerDecade
            || h.GetProperty("bins").GetInt32() != DecisionHistogram.BinCount)
        {
            throw new SceneException(file, path + ".decision_ms.histogram", $"other bins than this program's ({DecisionHistogram.BinCount} from {DecisionHistogram.FirstEdgeMs} ms, {DecisionHistogram.BinsPerDecade} a decade)");
        }
        var counts = new long[DecisionHistogram.BinCount];
        foreach (var pair in h.GetProperty("counts").EnumerateArray())
        {
            int bin = pair[0].GetInt32();
            if (bin < 0 || bin >= counts.Length || pair[1].GetInt64() < 0)
            {
                throw new SceneException(file, path + ".decision_ms.histogram.counts", $"bin {bin} or its count is out of range");
            }
            counts[bin] += pair[1].GetInt64();
        }
        return new PlayerStats(level, p.GetProperty("games_won").GetInt32(), p.GetProperty("shots").GetInt32(), p.GetProperty("pot_attempts").GetInt32(),
            p.GetProperty("pots").GetInt32(), p.GetProperty("fouls").GetInt32(), p.GetProperty("breaks").GetInt32(), p.GetProperty("potting_breaks").GetInt32(),
            p.GetProperty("break_and_runs").GetInt32(), p.GetProperty("run_outs").GetInt32(), p.GetProperty("visits").GetInt32(),
            p.GetProperty("scoring_visits").GetInt32(), p.GetProperty("break_sum").GetInt32(), p.GetProperty("highest_break").GetInt32(), p.GetProperty("expected_pot_sum_e9").GetInt64(), new DecisionHistogram(counts));
    }

    private static double Round(double x) => Math.Round(x, 4);
}
