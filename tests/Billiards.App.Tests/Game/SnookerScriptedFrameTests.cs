using System.Text.Json;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Scenes;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The shipped whole snooker frame, <c>assets/scripts/snooker-frame.json</c> (made by
/// <c>tools/game-script --snooker</c>): Anna and Ben play it through real input from the
/// break-off in the D to the last black (the cue ball dragged in move mode with ball in hand,
/// colours nominated by B and by a click on the ball from the view above the table, the aim on
/// the keys and a drag of the view, the power on W/Q, Space; after a foul the incoming player's
/// option clicked on its button). The winner and the score are checked against the rulings' own
/// points, the record replays, and the frame is the same at any frame rate.
/// </summary>
public class SnookerScriptedFrameTests
{
    public static string Script => Path.Combine(AssetFolder.Assets, "scripts", "snooker-frame.json");

    internal static readonly string[] Players = ["Anna", "Ben"];

    internal static string PlayHeadless(Func<int, double> frameSeconds) => ScriptedGames.PlayHeadless(Script, "snooker", string.Join(',', Players), frameSeconds);

    internal static string Shots(string record) => JsonDocument.Parse(record).RootElement.GetProperty("shots").GetRawText();

    [Fact]
    public void TheScriptedFrameIsTheSameFrameAt60FpsAt3FpsAndWithStalledFrames()
    {
        string fast = PlayHeadless(_ => 1.0 / 60);
        AssertWholeFrame(fast);
        // 0.3 s frames at speed 64: some 19 s of play a frame. Then frames as a loaded machine
        // gives them, a stall of up to 1.5 s now and then, so that a choice and the next shot's
        // keys, or a view switched and a click, fall into one frame.
        Assert.Equal(Shots(fast), Shots(PlayHeadless(_ => 0.3)));
        Assert.Equal(Shots(fast), Shots(PlayHeadless(ScriptedGames.Jitter(7, 1.5))));
    }

    /// <summary>
    /// Checks a record of the scripted frame and returns the final score: the frame runs from the
    /// break-off in the D to the black potted at the end, the turns pass as the rulings say, and the
    /// score is the sum of the rulings' points (to the striker) and penalties (to the other), shot
    /// by shot as each game block has it, at the end as the referee's last message and winner say.
    /// </summary>
    internal static PerPlayer<int> AssertWholeFrame(string record)
    {
        using var doc = JsonDocument.Parse(record);
        var shots = doc.RootElement.GetProperty("shots").EnumerateArray().ToList();
        var rulings = shots.Select(s => s.GetProperty("ruling")).ToList();
        var games = shots.Select(s => s.GetProperty("game")).ToList();

        // The break-off: shot 0, Anna, from in hand in the D.
        Assert.Equal(0, games[0].GetProperty("shot").GetInt32());
        Assert.Equal(0, games[0].GetProperty("shooter").GetInt32());
        Assert.True(SnookerTable.InD(SnookerTable.Spec, Place(shots[0])));

        var score = new int[2];
        for (int i = 0; i < shots.Count; i++)
        {
            var game = games[i];
            var ruling = rulings[i];
            Assert.Equal(i, game.GetProperty("shot").GetInt32());
            // The running score each shot starts from is the sum of the rulings before it.
            Assert.Equal(score, game.GetProperty("score").EnumerateArray().Select(v => v.GetInt32()));
            int striker = game.GetProperty("shooter").GetInt32();
            score[striker] += ruling.GetProperty("points").GetInt32();
            score[1 - striker] += ruling.GetProperty("penalty").GetInt32();
            if (i + 1 < shots.Count)
            {
                // The striker stays after a pot, or when the other makes them play again.
                string? choice = shots[i].TryGetProperty("choice", out var c) ? c.GetString() : null;
                bool again = ruling.GetProperty("continue").GetBoolean() || choice is "put-back" or "replace";
                Assert.Equal(again ? striker : 1 - striker, games[i + 1].GetProperty("shooter").GetInt32());
            }
        }

        // The whole frame: every red down, then the colours in order to the black, potted last.
        int reds = rulings.Sum(r => r.GetProperty("pocketed").EnumerateArray().Count(b => b.GetString()!.StartsWith("red-", StringComparison.Ordinal)));
        Assert.Equal(15, reds);
        var last = rulings[^1];
        Assert.All(rulings.Take(rulings.Count - 1), r => Assert.False(r.GetProperty("game_over").GetBoolean()));
        Assert.True(last.GetProperty("game_over").GetBoolean());
        Assert.True(last.GetProperty("legal").GetBoolean());
        Assert.Equal("black", games[^1].GetProperty("ball_on").GetString());
        Assert.Equal(["black"], last.GetProperty("pocketed").EnumerateArray().Select(b => b.GetString()));

        // The winner: the higher score, as the referee declares it.
        Assert.NotEqual(score[0], score[1]);
        int winner = score[0] > score[1] ? 0 : 1;
        Assert.Equal(winner, last.GetProperty("winner").GetInt32());
        Assert.Contains($"{Players[winner]} wins the frame {score[winner]}-{score[1 - winner]}", last.GetProperty("message").GetString(), StringComparison.Ordinal);

        // Along the way: colours nominated after reds, a foul with the incoming player's choice,
        // and the cue ball in hand in the D after an in-off, placed by the player.
        Assert.Contains(shots, s => s.GetProperty("game").GetProperty("ball_on").GetString() == "colour" && s.GetProperty("call").ValueKind == JsonValueKind.Object);
        Assert.Contains(shots, s => s.TryGetProperty("choice", out var c) && c.ValueKind == JsonValueKind.String);
        int inOff = rulings.FindIndex(r => r.GetProperty("fouls").EnumerateArray().Any(f => f.GetString() == "cue-ball-pocketed"));
        Assert.True(inOff >= 0, "no in-off in the frame");
        Assert.Equal("d", rulings[inOff].GetProperty("ball_in_hand").GetString());
        Assert.True(SnookerTable.InD(SnookerTable.Spec, Place(shots[inOff + 1])));
        return new PerPlayer<int>(score[0], score[1]);
    }

    private static Vec3 Place(JsonElement shot)
    {
        var place = shot.GetProperty("place");
        return new Vec3(place[0].GetDouble(), place[1].GetDouble(), 0);
    }
}

/// <summary>The shipped snooker frame in a real GLFW window (under Xvfb when there is no display).</summary>
[Collection("GL")]
public class SnookerScriptedFrameWindowTests
{
    [Fact]
    public void TheScriptedFramePlaysInAWindowToTheBlackWithTheWinnerAndScoreTheRulingsAddUpTo()
    {
        HudInfo? last = null;
        string record = ScriptedGames.PlayInWindow(SnookerScriptedFrameTests.Script, "snooker", string.Join(',', SnookerScriptedFrameTests.Players), frame => last = frame.Hud);
        var score = SnookerScriptedFrameTests.AssertWholeFrame(record);
        ScriptedGames.AssertReplays(record);
        // The window played the frame a slow headless run plays.
        Assert.Equal(SnookerScriptedFrameTests.Shots(record), SnookerScriptedFrameTests.Shots(SnookerScriptedFrameTests.PlayHeadless(_ => 0.3)));

        // The end of the frame on the screen: the winner and the final score, on the panel and the cards.
        int winner = score[0] > score[1] ? 0 : 1;
        var panel = Assert.IsType<ResultPanel>(last!.Result);
        Assert.Contains($"{SnookerScriptedFrameTests.Players[winner]} wins the frame {score[winner]}-{score[1 - winner]}", panel.Title, StringComparison.Ordinal);
        Assert.Equal([$"{score[0]}", $"{score[1]}"], last.Board!.Players.Select(p => p.Target));
        Assert.DoesNotContain(last.Board.Players, p => p.Detail.Contains("needs snookers", StringComparison.Ordinal));
        // Snooker's figures: each player's highest break, the most points of one visit in the record.
        var breaks = new int[2];
        int visit = 0;
        foreach (var shot in JsonDocument.Parse(record).RootElement.GetProperty("shots").EnumerateArray())
        {
            var ruling = shot.GetProperty("ruling");
            int striker = shot.GetProperty("game").GetProperty("shooter").GetInt32();
            visit += ruling.GetProperty("legal").GetBoolean() ? ruling.GetProperty("points").GetInt32() : 0;
            breaks[striker] = Math.Max(breaks[striker], visit);
            visit = ruling.GetProperty("continue").GetBoolean() ? visit : 0;
        }
        Assert.Contains(("Highest break", $"{breaks[0]}", $"{breaks[1]}"), panel.Rows);
        Assert.Contains(("Frames won", winner == 0 ? "1" : "0", winner == 1 ? "1" : "0"), panel.Rows);
    }
}
