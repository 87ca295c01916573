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
/// <c>selfplay --rules R --games N --levels A,B --seed S [--target P] [--out FILE.jsonl]</c>: the
/// computer against itself on a 9 ft table; prints one summary JSON, writes one game record per line
/// with <c>--out</c> (<see cref="GameRecordFile"/>'s record on one line, so each replays ruling for
/// ruling), and reports progress on stderr.
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
        var rules = new Option<string>("--rules") { Description = "The game: eight-ball, nine-ball, ten-ball or straight-pool.", Required = true };
        var games = new Option<int>("--games") { Description = "Number of games.", Required = true };
        var levels = new Option<string>("--levels") { Description = "The two players' levels, 1-5, e.g. 5,3 (the first is player 0).", Required = true };
        var seed = new Option<long>("--seed") { Description = "Seed of every rack and every error.", Required = true };
        var target = new Option<int?>("--target") { Description = "Straight pool: the score that wins (default 100)." };
        var output = new Option<string?>("--out") { Description = "Write the game records (billiards-game/1, one per line) to FILE.jsonl." };
        var command = new Command("selfplay", "Play the computer against itself and print a summary JSON.")
        {
            rules, games, levels, seed, target, output,
        };
        command.SetAction(parse =>
        {
            string rulesName = parse.GetValue(rules)!;
            if (!RuleNames.TryParseGame(rulesName, out var game))
            {
                throw new CliException($"--rules {rulesName}: expected one of {string.Join(", ", RuleNames.GameNames)}");
            }
            int points = parse.GetValue(target) ?? GameState.DefaultTarget;
            if (points < 1 || points > MaxTarget)
            {
                throw new CliException($"--target {points}: expected 1 to {MaxTarget}");
            }
            int count = parse.GetValue(games);
            if (count < 1 || count > MaxGames)
            {
                throw new CliException($"--games {count}: expected 1 to {MaxGames}");
            }
            var pair = ParseLevels(parse.GetValue(levels)!);
            long seedValue = parse.GetValue(seed);
            string? outPath = parse.GetValue(output) is { } o ? OutputFiles.Check("--out", o) : null;

            var table = TableSpec.FromPreset("pool-9ft");
            var physics = PhysicsParams.Default;
            var selfPlay = new SelfPlay(table, physics);
            var played = new List<PlayedGame>(count);
            var clock = Stopwatch.StartNew();
            var lastReport = TimeSpan.Zero;
            for (int g = 0; g < count; g++)
            {
                played.Add(selfPlay.Play(game, pair, g % 2, PlannerRandom.Derive((ulong)seedValue, g), Budget, points));
                if (clock.Elapsed - lastReport > TimeSpan.FromSeconds(5) || g == count - 1)
                {
                    lastReport = clock.Elapsed;
                    int wins0 = played.Count(p => p.Winner == 0);
                    stderr.WriteLine(string.Create(CultureInfo.InvariantCulture,
                        $"selfplay: {g + 1}/{count} games, level {pair.First} won {wins0}, level {pair.Second} won {played.Count(p => p.Winner == 1)}, {clock.Elapsed.TotalSeconds:F0} s"));
                }
            }
            if (outPath is not null)
            {
                using var lines = new MemoryStream();
                foreach (var p in played)
                {
                    OneLine(GameRecordFile.ToUtf8(p.Record), lines);
                }
                OutputFiles.Write(outPath, lines.ToArray());
            }
            stdout.WriteLine(Encoding.UTF8.GetString(Summary(game, seedValue, pair, played, clock.Elapsed.TotalMilliseconds)));
            return 0;
        });
        return command;
    }

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

    private static byte[] Summary(GameRules game, long seed, PerPlayer<int> levels, List<PlayedGame> played, double ms)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("rules", game.ToName());
            w.WriteNumber("games", played.Count);
            w.WriteNumber("seed", seed);
            w.WriteStartArray("levels");
            w.WriteNumberValue(levels.First);
            w.WriteNumberValue(levels.Second);
            w.WriteEndArray();
            w.WriteNumber("unfinished", played.Count(p => p.Winner is null));
            w.WriteStartArray("players");
            for (int player = 0; player < 2; player++)
            {
                var s = SelfPlayStats.Of(played, player);
                w.WriteStartObject();
                w.WriteNumber("player", player);
                w.WriteNumber("level", levels[player]);
                w.WriteNumber("games_won", s.GamesWon);
                w.WriteNumber("shots", s.Shots);
                w.WriteNumber("pots", s.Pots);
                w.WriteNumber("pot_attempts", s.PotAttempts);
                w.WriteNumber("pot_rate", Round(s.PotAttempts > 0 ? (double)s.Pots / s.PotAttempts : 0));
                w.WriteNumber("expected_pot_rate", Round(s.ExpectedPotRate));
                w.WriteNumber("fouls", s.Fouls);
                w.WriteNumber("breaks", s.Breaks);
                w.WriteNumber("potting_breaks", s.PottingBreaks);
                w.WriteNumber("break_and_runs", s.BreakAndRuns);
                w.WriteNumber("run_outs", s.RunOuts);
                w.WriteStartObject("decision_ms");
                w.WriteNumber("median", Round(s.DecisionMedianMs));
                w.WriteNumber("p95", Round(s.DecisionP95Ms));
                w.WriteEndObject();
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteNumber("ms", Round(ms));
            w.WriteEndObject();
        }
        return stream.ToArray();
    }

    // The record as GameRecordFile writes it, on one line (numbers keep their text).
    private static void OneLine(byte[] record, Stream output)
    {
        using var doc = JsonDocument.Parse(record);
        using (var w = new Utf8JsonWriter(output))
        {
            doc.RootElement.WriteTo(w);
        }
        output.WriteByte((byte)'\n');
    }

    private static double Round(double x) => Math.Round(x, 4);
}
