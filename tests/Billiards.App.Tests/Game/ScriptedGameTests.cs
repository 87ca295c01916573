using System.Text.Json;
using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Rendering;
using Billiards.App.Platform;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The shipped whole 8-ball game, <c>assets/scripts/eight-ball-game.json</c>: two people play it
/// through real input (keys, and a mouse drag to place the cue ball in hand) from the break to a
/// winner the referee declares. Checked headless at very different frame rates (the same game bit
/// for bit) and in a real window under Xvfb; the window's game record replays shot for shot.
/// </summary>
public class ScriptedGameTests
{
    public static string Script => Path.Combine(AssetFolder.Assets, "scripts", "eight-ball-game.json");

    private static readonly string[] Players = ["Anna", "Ben"];

    /// <summary>Plays the script through <c>play</c> on a fake window at a fixed frame time; returns the game record's JSON.</summary>
    internal static JsonDocument PlayHeadless(double frameSeconds) => JsonDocument.Parse(PlayHeadlessText(frameSeconds));

    /// <summary>Plays the script headless; returns the game record as written.</summary>
    internal static string PlayHeadlessText(double frameSeconds) => ScriptedGames.PlayHeadless(Script, "eight-ball", string.Join(',', Players), frameSeconds);

    [Fact]
    public void TheScriptedGameIsTheSameGameAt60FpsAndAt3Fps()
    {
        using var fast = PlayHeadless(1.0 / 60);
        using var slow = PlayHeadless(0.3); // 0.3 s frames at speed 16: up to 8 s of play per frame
        var a = fast.RootElement;
        var b = slow.RootElement;
        // Every shot (state, call, placement, strike to the last bit, ruling, balls at rest) agrees.
        Assert.Equal(a.GetProperty("shots").GetRawText(), b.GetProperty("shots").GetRawText());
        AssertGame(a);
    }

    [Fact]
    public void TheScriptedGameSRecordReplaysShotForShot()
    {
        string text = PlayHeadlessText(1.0 / 60);
        ScriptedGames.AssertReplays(text);
        Assert.True(GameRecordFile.Parse(text, "w.json").Shots.Count >= 4);
    }

    [Fact]
    public void TheScriptedGamePlaysBackInTheWindowFromItsRecordWithEveryRuling()
    {
        string text = PlayHeadlessText(1.0 / 60);
        var record = GameRecordFile.Parse(text, "w.json");
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var rulings = new List<(int Shot, string Ruling)>();
        const int first = 2;
        int code = ReplayCommand.Play(record, "w.json", first, 16, _ => new GamePlatform(window, new UntilClosedLoop(clock, window, 1.0 / 30), new NullFrameRenderer()), clock,
            (k, ruling) => rulings.Add((k, System.Text.Encoding.UTF8.GetString(GameBlockWriter.RulingToUtf8(ruling)))), closeAtEnd: true);
        Assert.Equal(0, code);
        Assert.True(window.Closed, "the playback never ended");
        // Shot by shot from the one asked for, each judged as recorded.
        Assert.Equal(Enumerable.Range(first, record.Shots.Count - first), rulings.Select(r => r.Shot));
        Assert.All(rulings, r => Assert.Equal(record.Rulings[r.Shot], r.Ruling));
    }

    // Internal so that the window test below can share it.
    internal static void AssertGame(JsonElement root) => AssertWholeGame(root, TableSpec.FromPreset("pool-9ft"));

    // A whole game from the record: the break, a pot, a scratch with the cue ball back in hand and
    // placed by the player, turns passed as the referee ruled, and a winner shown on the HUD.
    private static void AssertWholeGame(JsonElement root, TableSpec table)
    {
        Assert.Equal(GameRecordFile.Format, root.GetProperty("format").GetString());
        var shots = root.GetProperty("shots").EnumerateArray().ToList();
        var rulings = shots.Select(s => s.GetProperty("ruling")).ToList();
        Assert.True(rulings.Count >= 4);

        // The break: shot 0, from the kitchen, at the break's speed.
        var first = shots[0].GetProperty("game");
        Assert.Equal(0, first.GetProperty("shot").GetInt32());
        Assert.True(shots[0].GetProperty("shot").GetProperty("speed").GetDouble() >= 6);
        Assert.True(shots[0].GetProperty("place")[0].GetDouble() <= (-table.Length / 4) + 1e-9, "the break is played from the kitchen (behind the head string)");

        // Turns: the shooter stays after a ruling that continues, else the other player shoots.
        for (int i = 0; i + 1 < shots.Count; i++)
        {
            int shooter = shots[i].GetProperty("game").GetProperty("shooter").GetInt32();
            int next = shots[i + 1].GetProperty("game").GetProperty("shooter").GetInt32();
            Assert.Equal(rulings[i].GetProperty("continue").GetBoolean() ? shooter : 1 - shooter, next);
            Assert.Equal(i + 1, shots[i + 1].GetProperty("game").GetProperty("shot").GetInt32());
        }

        // A legal pot that keeps the shooter at the table, after the break.
        Assert.Contains(rulings.Skip(1), r => r.GetProperty("legal").GetBoolean() && r.GetProperty("continue").GetBoolean() && r.GetProperty("pocketed").GetArrayLength() > 0);

        // A scratch: a foul, the cue ball in hand anywhere for the other player, who places it by
        // hand away from where it came back (the head spot, free in this game) before shooting.
        int scratch = rulings.FindIndex(r => r.GetProperty("fouls").EnumerateArray().Any(f => f.GetString() == "cue-ball-pocketed"));
        Assert.True(scratch >= 0, "no scratch in the game");
        Assert.False(rulings[scratch].GetProperty("legal").GetBoolean());
        Assert.Equal("table", rulings[scratch].GetProperty("ball_in_hand").GetString());
        Assert.True(scratch + 1 < shots.Count);
        var place = shots[scratch + 1].GetProperty("place");
        Assert.Equal(JsonValueKind.Array, place.ValueKind);
        double dx = place[0].GetDouble() + (table.Length / 4), dy = place[1].GetDouble();
        Assert.True(Math.Sqrt((dx * dx) + (dy * dy)) > 0.05, "the cue ball was not moved from where it came back");

        // The end: the referee's last ruling ends the game with a winner.
        var last = rulings[^1];
        Assert.True(last.GetProperty("game_over").GetBoolean());
        Assert.All(rulings.Take(rulings.Count - 1), r => Assert.False(r.GetProperty("game_over").GetBoolean()));
        int winner = last.GetProperty("winner").GetInt32();
        Assert.Contains(Players[winner], last.GetProperty("message").GetString(), StringComparison.Ordinal);
    }

}

/// <summary>The shipped game in a real GLFW window (under Xvfb when there is no display).</summary>
[Collection("GL")]
public class ScriptedGameWindowTests
{
    [Fact]
    public void TheScriptedGamePlaysInAWindowToAWinnerTheRefereeDeclares()
    {
        string stats = Path.Combine(Path.GetTempPath(), $"stats-{Guid.NewGuid():N}.json");
        try
        {
            string text = ScriptedGames.PlayInWindow(ScriptedGameTests.Script, "eight-ball", "Anna,Ben", stats: stats);
            using var doc = JsonDocument.Parse(text);
            ScriptedGameTests.AssertGame(doc.RootElement);
            // The window played the same game as the headless run, and its record replays.
            using var headless = ScriptedGameTests.PlayHeadless(1.0 / 30);
            Assert.Equal(headless.RootElement.GetProperty("shots").GetRawText(), doc.RootElement.GetProperty("shots").GetRawText());
            ScriptedGames.AssertReplays(text);

            // Every input reached the screen on the frame after it was due, waits and all.
            using var s = JsonDocument.Parse(File.ReadAllText(stats));
            var inputs = s.RootElement.GetProperty("inputs").EnumerateArray().ToList();
            Assert.NotEmpty(inputs);
            Assert.All(inputs, i => Assert.Equal(1, i.GetProperty("delay_frames").GetInt32()));
        }
        finally
        {
            File.Delete(stats);
        }
    }
}

/// <summary>
/// A whole 8-ball game against the computer in a real GLFW window (under Xvfb when there is no
/// display), from the shipped script that asks for a hint on each of the person's turns, waits for
/// it and shoots it: the game ends with a winner and the result panel is on the screen, with the
/// record's shots and Rematch and Menu under it.
/// </summary>
[Collection("GL")]
public class GameAgainstTheComputerWindowTests
{
    public static string Script => Path.Combine(AssetFolder.Assets, "scripts", "game-against-the-computer.json");

    [Fact]
    public void AWholeGameAgainstTheComputerPlaysInAWindowAndEndsWithTheResultPanel()
    {
        HudInfo? last = null;
        string text = ScriptedGames.PlayInWindow(Script, "eight-ball", "Anna,cpu:3", frame => last = frame.Hud);
        using var doc = JsonDocument.Parse(text);
        var shots = doc.RootElement.GetProperty("shots").EnumerateArray().ToList();
        var rulings = shots.Select(s => s.GetProperty("ruling")).ToList();
        Assert.True(rulings[^1].GetProperty("game_over").GetBoolean(), "the script ended before the game");
        Assert.Contains(shots, s => s.GetProperty("game").GetProperty("shooter").GetInt32() == 1); // the computer played
        ScriptedGames.AssertReplays(text);

        // The last frame on the screen: the result panel, its shots those of the record, and its buttons.
        Assert.NotNull(last);
        var panel = Assert.IsType<ResultPanel>(last!.Result);
        Assert.Equal(shots.Count, panel.Stats.First.Shots + panel.Stats.Second.Shots);
        int winner = rulings[^1].GetProperty("winner").GetInt32();
        Assert.Contains(winner == 0 ? "Anna" : "Computer", panel.Title, StringComparison.Ordinal);
        Assert.Contains(last.Buttons!, b => b.Label.StartsWith("Rematch", StringComparison.Ordinal));
        Assert.Contains(last.Buttons!, b => b.Label.StartsWith("Menu", StringComparison.Ordinal));
    }
}
