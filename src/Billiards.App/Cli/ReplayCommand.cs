using System.CommandLine;
using System.Globalization;
using System.Text;
using System.Text.Json;
using Billiards.App.Audio;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>replay GAME.json --verify</c>: re-simulates every shot of a game record (billiards-game/1)
/// and compares each ruling and the balls at rest with the recorded ones (scene-format.md); a
/// file of several records, one per line, is verified record by record. <c>replay GAME.json
/// [--shot K] [--speed X] [--game N]</c>: plays the record back in the window (game N of a file
/// of several, the first by default), with the next and previous shot keys and each ruling shown.
/// </summary>
public static class ReplayCommand
{
    /// <summary>Exit code when a replayed shot differs from its record.</summary>
    public const int Differs = 1;

    /// <summary>Builds the verb.</summary>
    /// <param name="stdout">Where the reports go.</param>
    /// <param name="openPlatform">Opens the window for playback.</param>
    public static Command Create(TextWriter stdout, Func<string, GamePlatform>? openPlatform = null)
    {
        var file = new Argument<string>("game") { Description = $"The game record ({GameRecordFile.Format} JSON, or JSON lines of several)." };
        var verify = new Option<bool>("--verify") { Description = "Re-simulate every shot headless and compare with the record; prints the comparison." };
        var shot = new Option<int?>("--shot") { Description = "Playback: the first shot to show (0 the break; earlier shots are played at once)." };
        var speed = new Option<double?>("--speed") { Description = "Playback: how fast time runs (1 real time, default 1)." };
        var game = new Option<int?>("--game") { Description = "Playback of a file of several records (selfplay --out): the game to show, 1 the first (default 1)." };
        var command = new Command("replay", VerbHelp.Verb("Verify a recorded game headless, or play it back in the window shot by shot.", "replay")) { file, verify, shot, speed, game };
        command.SetAction(parse =>
        {
            string path = parse.GetValue(file)!;
            var records = Load(path);
            if (parse.GetValue(verify))
            {
                if (parse.GetValue(shot) is not null || parse.GetValue(speed) is not null || parse.GetValue(game) is not null)
                {
                    throw new CliException("--verify replays every shot of every game headless: --shot, --speed and --game are for playback");
                }
                return Verify(records, stdout);
            }
            int chosen = parse.GetValue(game) ?? 1;
            var record = Pick(records, chosen, path);
            int first = parse.GetValue(shot) ?? 0;
            if (first < 0 || first >= record.Shots.Count)
            {
                throw new CliException($"--shot {first}: the record has shots 0 to {record.Shots.Count - 1}");
            }
            double timeScale = parse.GetValue(speed) ?? 1;
            if (!double.IsFinite(timeScale) || timeScale <= 0 || timeScale > 100)
            {
                throw new CliException($"--speed {timeScale.ToString(CultureInfo.InvariantCulture)}: expected a number above 0, at most 100");
            }
            PlayCommand.RequireDisplay();
            return Play(record, records.Count > 1 ? $"{path} game {chosen}" : path, first, timeScale, openPlatform ?? PlatformWiring.Open,
                openAudio: openPlatform is null ? PlayCommand.OpenAudio : null);
        });
        return command;
    }

    /// <summary>Reads one record, or several on lines of their own.</summary>
    /// <exception cref="CliException">When the file cannot be read.</exception>
    /// <exception cref="SceneException">When a record is malformed.</exception>
    public static IReadOnlyList<GameRecord> Load(string path)
    {
        string text;
        try
        {
            text = File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"{path}: cannot read the game record: {e.Message}");
        }
        var lines = text.Split('\n').Select(l => l.Trim()).Where(l => l.Length > 0).ToList();
        bool oneObject = lines.Count <= 1 || !lines.All(l => l.StartsWith('{') && l.EndsWith('}') && IsJson(l));
        if (oneObject)
        {
            return [GameRecordFile.Parse(text, path)];
        }
        return [.. lines.Select((l, i) => GameRecordFile.Parse(l, string.Create(CultureInfo.InvariantCulture, $"{path} line {i + 1}")))];
    }

    /// <summary>Game <paramref name="game"/> (1 the first) of a file's records, for playback.</summary>
    /// <exception cref="CliException">When the file has no such game, or it has no shots.</exception>
    public static GameRecord Pick(IReadOnlyList<GameRecord> records, int game, string path)
    {
        ArgumentNullException.ThrowIfNull(records);
        if (game < 1 || game > records.Count)
        {
            throw new CliException(records.Count == 1
                ? $"--game {game}: {path} holds one game (--game 1)"
                : $"--game {game}: {path} holds games 1 to {records.Count}");
        }
        var record = records[game - 1];
        return record.Shots.Count > 0 ? record : throw new CliException($"{path}: game {game} has no shots to play back");
    }

    private static bool IsJson(string line)
    {
        try
        {
            using var doc = JsonDocument.Parse(line);
            return true;
        }
        catch (JsonException)
        {
            return false;
        }
    }

    /// <summary>Verifies every record and prints one comparison per record; 0 when all replay the same, else <see cref="Differs"/>.</summary>
    public static int Verify(IReadOnlyList<GameRecord> records, TextWriter stdout)
    {
        ArgumentNullException.ThrowIfNull(records);
        ArgumentNullException.ThrowIfNull(stdout);
        int code = 0;
        foreach (var record in records)
        {
            var report = GameRecordFile.Verify(record, out _);
            stdout.WriteLine(Encoding.UTF8.GetString(ToJson(report)));
            if (report.FirstDifference is not null)
            {
                code = Differs;
            }
        }
        return code;
    }

    /// <summary>The comparison as scene-format.md prints it.</summary>
    public static byte[] ToJson(ReplayReport report)
    {
        ArgumentNullException.ThrowIfNull(report);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            w.WriteStartObject();
            w.WriteNumber("shots", report.Shots);
            w.WriteNumber("same", report.Same);
            if (report.FirstDifference is { } d)
            {
                w.WriteStartObject("first_difference");
                w.WriteNumber("shot", d.Shot);
                w.WriteString("field", d.Field);
                w.WritePropertyName("recorded");
                w.WriteRawValue(d.Recorded);
                w.WritePropertyName("replayed");
                w.WriteRawValue(d.Replayed);
                w.WriteEndObject();
            }
            else
            {
                w.WriteNull("first_difference");
            }
            w.WriteEndObject();
        }
        return stream.ToArray();
    }

    /// <summary>Plays a record back in a window from shot <paramref name="first"/>; the window closes a moment after the last shot.</summary>
    /// <param name="record">The record.</param>
    /// <param name="path">Its file, for the window's title.</param>
    /// <param name="first">The first shot shown.</param>
    /// <param name="timeScale">How fast time runs (1 real time).</param>
    /// <param name="openPlatform">Opens the window.</param>
    /// <param name="clock">The clock; the real one by default.</param>
    /// <param name="ruled">Told each shot's index and ruling as the window judges it.</param>
    /// <param name="started">Told the game once it is built (tests watch it).</param>
    /// <param name="openAudio">Opens the sound output (the shots are heard as they are shown); silence by default (tests).</param>
    /// <param name="closeAtEnd">Closes the window 2 s after the last shot (tests); the player's window stays open at the end until they leave.</param>
    public static int Play(GameRecord record, string path, int first, double timeScale, Func<string, GamePlatform> openPlatform, IClock? clock = null, Action<int, Ruling>? ruled = null, Action<GameHost>? started = null, Func<IAudioOutput>? openAudio = null, bool closeAtEnd = false)
    {
        ArgumentNullException.ThrowIfNull(record);
        ArgumentNullException.ThrowIfNull(openPlatform);
        var setup = record.Setup;
        var balls = (setup.Position ?? setup.Racked(0)).Select(b => new BallSetup(b.Id, b.Position, Core.Mathematics.Vec3.Zero, Core.Mathematics.Vec3.Zero)).ToList();
        // No rules in the scene: the replay, not a match, drives the game.
        var scene = new Scene(path, "replay", setup.Table, setup.Physics, null, balls, null, null);
        using var platform = openPlatform($"{PlatformWiring.WindowTitle}: replay of {Path.GetFileName(path)}");
        using var host = new GameHost(scene, SimulationFactory.Create, platform.Window, clock ?? new StopwatchClock()) { TimeScale = timeScale };
        var replay = host.Tree.Root.AddChild(new ReplayNode(record, first, timeScale));
        using var audio = openAudio?.Invoke() ?? new SilentAudio();
        host.Tree.Root.AddChild(new AudioNode(audio));
        if (ruled is not null)
        {
            replay.Ruled += ruled;
        }
        started?.Invoke(host);
        double? closeAt = null;
        host.FrameStarting += now =>
        {
            if (replay.Finished && closeAtEnd)
            {
                closeAt ??= now + (2 / timeScale);
                if (now >= closeAt)
                {
                    platform.Window.Close();
                }
            }
            else
            {
                closeAt = null; // gone back to an earlier shot
            }
        };
        host.Run(platform.Loop, platform.Renderer);
        return 0;
    }
}
