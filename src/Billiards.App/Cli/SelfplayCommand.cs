using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.Text;
using System.Text.Json;
using Billiards.Core.Ai;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Cli;

/// <summary>
/// <c>selfplay --rules R --games N --levels A,B --seed S [--target P] [--shard K/N] [--threads N] [--noise NAME[:K]] [--planners A,B] [--out FILE.jsonl] [--summary FILE.json]</c>:
/// the computer against itself on its game's table (a 9 ft pool table, snooker's 12 ft); prints one summary JSON (<see cref="SelfPlaySummary"/>)
/// or writes it to <c>--summary</c>, writes one game record per line with <c>--out</c>
/// (<see cref="GameRecordFile"/>'s record on one line, so each replays ruling for ruling), and
/// reports progress on stderr. <c>--shard K/N</c> plays the games g of the run with g mod N = K
/// (<see cref="SelfPlayShard"/>); <c>selfplay --merge A.json B.json ...</c> merges the shards'
/// summaries into the whole run's.
/// </summary>
public static class SelfplayCommand
{
    /// <summary>The most games one run plays.</summary>
    public const int MaxGames = 100_000;

    /// <summary>
    /// The decisions' time cap: far above any level's own search, so that a loaded machine slows
    /// the games down but never cuts a search short, and a seed gives the same games bit for bit.
    /// </summary>
    public static readonly PlannerBudget Budget = new(60_000);

    /// <summary>The largest straight-pool target accepted.</summary>
    public const int MaxTarget = 1000;

    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        // Not Required: --merge needs none of them (checked in the action).
        var rules = new Option<string?>("--rules") { Description = $"The game: {VerbHelp.Games}." };
        var games = new Option<int?>("--games") { Description = "Number of games of the whole run." };
        var levels = new Option<string?>("--levels") { Description = "The two players' levels, 1-5, e.g. 5,3 (the first is player 0)." };
        var seed = new Option<long?>("--seed") { Description = "Seed of every rack and every error." };
        var target = new Option<int?>("--target") { Description = "Straight pool and three-cushion: the score that wins (default 100; three-cushion 40)." };
        var shard = new Option<string?>("--shard") { Description = "K/N: play only the games g of the run with g mod N = K (0 <= K < N), with the run's seeds." };
        var output = new Option<string?>("--out") { Description = "Write the game records (billiards-game/1, one per line) to FILE.jsonl." };
        var summary = new Option<string?>("--summary") { Description = "Write the summary JSON to FILE instead of standard output." };
        var threads = new Option<int?>("--threads") { Description = "The threads each decision's search runs on (default: every core); the games are the same at any count." };
        var noise = new Option<string?>("--noise") { Description = "NAME[:K]: strike every stroke with execution noise, fastfiz (the computational-pool tournaments') scaled by K (default 1)." };
        var planners = new Option<string?>("--planners") { Description = "A,B: each player's planner, own (its level's error), noise (plays for the noise) or blind (one exact outcome per candidate); default noise,noise with --noise, else own,own." };
        var merge = new Option<string[]>("--merge") { Description = "Merge the summaries of every shard of one run into the run's summary.", AllowMultipleArgumentsPerToken = true, Arity = ArgumentArity.OneOrMore };
        var command = new Command("selfplay", VerbHelp.Verb("Play the computer against itself and print a summary JSON.", "selfplay"))
        {
            rules, games, levels, seed, target, shard, output, summary, threads, noise, planners, merge,
        };
        command.SetAction(parse =>
        {
            string? summaryPath = parse.GetValue(summary) is { } sp ? OutputFiles.Check("--summary", sp) : null;
            if (parse.GetValue(merge) is { Length: > 0 } summaries)
            {
                foreach (var (name, given) in new[] { ("--rules", parse.GetValue(rules) is not null), ("--games", parse.GetValue(games) is not null), ("--levels", parse.GetValue(levels) is not null),
                    ("--seed", parse.GetValue(seed) is not null), ("--target", parse.GetValue(target) is not null), ("--shard", parse.GetValue(shard) is not null), ("--out", parse.GetValue(output) is not null), ("--threads", parse.GetValue(threads) is not null),
                    ("--noise", parse.GetValue(noise) is not null), ("--planners", parse.GetValue(planners) is not null) })
                {
                    if (given)
                    {
                        throw new CliException($"--merge: {name} does not go with it (the summaries say what the run was; --summary FILE is the only option)");
                    }
                }
                Emit(stdout, summaryPath, Merge(summaries).ToUtf8(), []);
                return 0;
            }
            string rulesName = parse.GetValue(rules) ?? throw Missing("--rules");
            if (!RuleNames.TryParseGame(rulesName, out var game))
            {
                throw new CliException($"--rules {rulesName}: expected one of {string.Join(", ", RuleNames.GameNames)}");
            }
            if (!Ruleset.For(game).HasComputerPlayer)
            {
                throw new CliException($"--rules {rulesName}: the computer player does not play {rulesName} yet");
            }
            int points = parse.GetValue(target) ?? Ruleset.For(game).DefaultTarget;
            if (points < 1 || points > MaxTarget)
            {
                throw new CliException($"--target {points}: expected 1 to {MaxTarget}");
            }
            int count = parse.GetValue(games) ?? throw Missing("--games");
            if (count < 1 || count > MaxGames)
            {
                throw new CliException($"--games {count}: expected 1 to {MaxGames}");
            }
            var pair = ParseLevels(parse.GetValue(levels) ?? throw Missing("--levels"));
            long seedValue = parse.GetValue(seed) ?? throw Missing("--seed");
            var part = SelfPlayShard.Whole;
            if (parse.GetValue(shard) is { } shardText)
            {
                part = SelfPlayShard.TryParse(shardText, out string problem) ?? throw new CliException($"--shard {shardText}: {problem}");
            }
            // A search reduces its samples in their order, whichever thread ran them, and the time
            // cap is never reached: the thread count changes the speed only. One thread a shard
            // fits shards that run side by side on the same cores.
            int searchThreads = parse.GetValue(threads) ?? Environment.ProcessorCount;
            if (searchThreads < 1 || searchThreads > BatchSimulation.MaxThreads)
            {
                throw new CliException($"--threads {searchThreads}: expected 1 to {BatchSimulation.MaxThreads}");
            }
            var budget = Budget with { Threads = searchThreads };
            var executionNoise = parse.GetValue(noise) is { } noiseText ? ParseNoise(noiseText) : null;
            var searches = ParsePlanners(parse.GetValue(planners), executionNoise);
            string? outPath = parse.GetValue(output) is { } o ? OutputFiles.Check("--out", o) : null;

            var ruleset = Ruleset.For(game);
            var table = TableSpec.FromPreset(ruleset.TablePreset);
            var physics = ruleset.BallSet.DefaultParams;
            var selfPlay = new SelfPlay(table, physics);
            var skills = new PerPlayer<SkillLevel>(Planner(SkillLevel.Of(pair.First), searches.First, executionNoise), Planner(SkillLevel.Of(pair.Second), searches.Second, executionNoise));
            int mine = part.GameCount(count);
            var played = new List<PlayedGame>(mine);
            var clock = Stopwatch.StartNew();
            var lastReport = TimeSpan.Zero;
            string label = part.IsWhole ? "selfplay" : $"selfplay {part.Index}/{part.Count}";
            foreach (int g in part.Games(count))
            {
                // Game g has the same seed and breaker in every shard count: the shards play the run's games.
                played.Add(selfPlay.Play(game, skills, g % 2, PlannerRandom.Derive((ulong)seedValue, g), budget, points, executionNoise));
                if (clock.Elapsed - lastReport > TimeSpan.FromSeconds(5) || played.Count == mine)
                {
                    lastReport = clock.Elapsed;
                    stderr.WriteLine(string.Create(CultureInfo.InvariantCulture,
                        $"{label}: {played.Count}/{mine} games, level {pair.First} won {played.Count(p => p.Winner == 0)}, level {pair.Second} won {played.Count(p => p.Winner == 1)}, {clock.Elapsed.TotalSeconds:F0} s"));
                }
            }
            var files = new List<(string Path, byte[] Bytes)>();
            if (outPath is not null)
            {
                files.Add((outPath, GameRecordFile.ToJsonLines(played.Select(p => p.Record))));
            }
            var result = SelfPlaySummary.Of(game, seedValue, pair, points, count, part, played, clock.Elapsed.TotalMilliseconds) with { Noise = executionNoise, Planners = searches };
            Emit(stdout, summaryPath, result.ToUtf8(), files);
            return 0;
        });
        return command;
    }

    /// <summary>Reads and merges the shard summaries named by <paramref name="files"/>.</summary>
    public static SelfPlaySummary Merge(IReadOnlyList<string> files)
    {
        ArgumentNullException.ThrowIfNull(files);
        var summaries = new List<SelfPlaySummary>(files.Count);
        foreach (string file in files)
        {
            string text;
            try
            {
                text = File.ReadAllText(file);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
            {
                throw new CliException($"--merge {file}: cannot read the file ({e.Message})");
            }
            summaries.Add(SelfPlaySummary.Parse(text, file));
        }
        return SelfPlaySummary.Merge(summaries, files);
    }

    // The summary to stdout or, with the records, atomically to its file.
    private static void Emit(TextWriter stdout, string? summaryPath, byte[] summary, List<(string Path, byte[] Bytes)> files)
    {
        if (summaryPath is not null)
        {
            files.Add((summaryPath, summary));
        }
        if (files.Count > 0)
        {
            OutputFiles.WriteAll(files);
        }
        if (summaryPath is null)
        {
            stdout.Write(Encoding.UTF8.GetString(summary));
        }
    }

    private static CliException Missing(string option) => new($"selfplay: {option} is required (or --merge SUMMARY.json ...)");

    /// <summary>Parses "A,B" with both levels in 1-5.</summary>
    public static PerPlayer<int> ParseLevels(string text)
    {
        var parts = text.Split(',');
        if (parts.Length != 2
            || !int.TryParse(parts[0], NumberStyles.None, CultureInfo.InvariantCulture, out int a)
            || !int.TryParse(parts[1], NumberStyles.None, CultureInfo.InvariantCulture, out int b)
            || a < SkillLevel.Min || a > SkillLevel.Max || b < SkillLevel.Min || b > SkillLevel.Max)
        {
            throw new CliException($"--levels {text}: expected two levels from {SkillLevel.Min} to {SkillLevel.Max}, e.g. 5,3");
        }
        return new PerPlayer<int>(a, b);
    }

    /// <summary>Parses <c>--noise NAME[:K]</c> (<see cref="ExecutionNoise.TryParse"/>).</summary>
    public static ExecutionNoise ParseNoise(string text) =>
        ExecutionNoise.TryParse(text, out string problem) ?? throw new CliException($"--noise {text}: {problem}");

    /// <summary>
    /// Parses <c>--planners A,B</c> (own, noise or blind each); without it, both play for the
    /// noise when there is one, else with their level's own error.
    /// </summary>
    public static PerPlayer<SearchError> ParsePlanners(string? text, ExecutionNoise? noise)
    {
        if (text is null)
        {
            return noise is null ? default : new PerPlayer<SearchError>(SearchError.Noise, SearchError.Noise);
        }
        var parts = text.Split(',');
        if (parts.Length != 2 || SelfPlaySummary.TryParsePlanner(parts[0]) is not { } a || SelfPlaySummary.TryParsePlanner(parts[1]) is not { } b)
        {
            throw new CliException($"--planners {text}: expected two of own, noise and blind, e.g. noise,blind");
        }
        if (noise is null && (a == SearchError.Noise || b == SearchError.Noise))
        {
            throw new CliException($"--planners {text}: a planner that plays for the noise needs --noise");
        }
        return new PerPlayer<SearchError>(a, b);
    }

    /// <summary>The level's planner for <paramref name="error"/>: as it is, playing for <paramref name="noise"/>, or blind.</summary>
    public static SkillLevel Planner(SkillLevel level, SearchError error, ExecutionNoise? noise)
    {
        ArgumentNullException.ThrowIfNull(level);
        return error switch
        {
            SearchError.Noise => level.PlayingFor(noise ?? throw new ArgumentNullException(nameof(noise))),
            SearchError.Exact => level.NoiseBlind(),
            _ => level,
        };
    }
}
