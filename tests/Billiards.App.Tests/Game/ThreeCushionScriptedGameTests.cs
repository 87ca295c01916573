using System.Globalization;
using System.Text.Json;
using Billiards.App.Hud;
using Billiards.App.Rendering;
using Billiards.Core.Scenes;
using Billiards.Core.Rules;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The shipped three-cushion game against the computer, <c>assets/scripts/three-cushion-game.json</c>
/// (made by <c>tools/game-script --three-cushion</c>) on <c>assets/scenes/three-cushion-race.json</c>
/// (a race to 3): on each of Anna's turns a hint (G), waited for, then Space; the computer (level 4)
/// plays its own innings. The score, the innings and the turns are checked against the rulings,
/// the record replays, and the game is the same at any frame rate.
/// </summary>
public class ThreeCushionScriptedGameTests
{
    public static string Script => Path.Combine(AssetFolder.Assets, "scripts", "three-cushion-game.json");

    public static string Scene => Path.Combine(AssetFolder.Assets, "scenes", "three-cushion-race.json");

    internal const string Players = "Anna,computer:4";

    internal static readonly string[] Names = ["Anna", "Computer L4"];

    internal static string PlayHeadless(Func<int, double> frameSeconds) => ScriptedGames.PlayHeadless(Script, "three-cushion", Players, frameSeconds, Scene);

    [Fact]
    public void TheScriptedGameIsTheSameGameAt60FpsAt3FpsAndWithStalledFrames()
    {
        string fast = PlayHeadless(_ => 1.0 / 60);
        AssertWholeGame(fast);
        ScriptedGames.AssertReplays(fast);
        Assert.Equal(SnookerScriptedFrameTests.Shots(fast), SnookerScriptedFrameTests.Shots(PlayHeadless(_ => 0.3)));
        Assert.Equal(SnookerScriptedFrameTests.Shots(fast), SnookerScriptedFrameTests.Shots(PlayHeadless(ScriptedGames.Jitter(11, 1.5))));
    }

    /// <summary>
    /// Checks a record of the scripted game and returns each player's points, innings and highest
    /// run: the game runs from Anna's break to the race's end; a point (three cushions or more)
    /// keeps the shooter at the table and anything else hands it over; every game block's score and
    /// innings are those the rulings before it made; Anna reaches the target first and the computer
    /// has its equalizing inning; the last ruling names the winner the score says.
    /// </summary>
    internal static (int[] Points, int[] Innings, int[] HighestRun) AssertWholeGame(string record)
    {
        using var doc = JsonDocument.Parse(record);
        var shots = doc.RootElement.GetProperty("shots").EnumerateArray().ToList();
        var games = shots.Select(s => s.GetProperty("game")).ToList();
        var rulings = shots.Select(s => s.GetProperty("ruling")).ToList();
        Assert.Equal("three-cushion", games[0].GetProperty("rules").GetString());
        Assert.Equal(3, games[0].GetProperty("target").GetInt32());
        Assert.Equal(0, games[0].GetProperty("shot").GetInt32());
        Assert.Equal(0, games[0].GetProperty("shooter").GetInt32());

        var points = new int[2];
        var innings = new int[2];
        var highest = new int[2];
        int run = 0, previous = -1;
        for (int i = 0; i < shots.Count; i++)
        {
            var ruling = rulings[i];
            int shooter = games[i].GetProperty("shooter").GetInt32();
            Assert.Equal(points, games[i].GetProperty("score").EnumerateArray().Select(v => v.GetInt32()));
            if (shooter != previous)
            {
                innings[shooter]++;
                run = 0;
            }
            previous = shooter;
            bool point = ruling.GetProperty("point").GetBoolean();
            Assert.True(ruling.GetProperty("legal").GetBoolean(), ruling.GetProperty("message").GetString());
            if (point)
            {
                Assert.True(ruling.GetProperty("cushions").GetInt32() >= 3);
                points[shooter]++;
                run++;
                highest[shooter] = Math.Max(highest[shooter], run);
            }
            Assert.Equal(points, ruling.GetProperty("score").EnumerateArray().Select(v => v.GetInt32()));
            Assert.Equal(innings, ruling.GetProperty("innings").EnumerateArray().Select(v => v.GetInt32()));
            Assert.Equal(run, ruling.GetProperty("run").GetInt32());
            bool over = ruling.GetProperty("game_over").GetBoolean();
            Assert.Equal(i == shots.Count - 1, over);
            if (!over)
            {
                // A point keeps the shooter at the table, except the one that reaches the target first.
                bool keeps = point && points[shooter] < 3;
                Assert.Equal(keeps, ruling.GetProperty("continue").GetBoolean());
                Assert.Equal(keeps ? shooter : 1 - shooter, games[i + 1].GetProperty("shooter").GetInt32());
            }
        }

        // Anna reached the target; the computer's equalizing inning came after it, and it missed.
        Assert.Equal(3, points[0]);
        Assert.InRange(points[1], 1, 2);
        int reached = rulings.FindIndex(r => r.GetProperty("score")[0].GetInt32() == 3);
        Assert.Contains("equalizing inning", rulings[reached].GetProperty("message").GetString(), StringComparison.Ordinal);
        Assert.All(games.Skip(reached + 1), g => Assert.Equal(1, g.GetProperty("shooter").GetInt32()));
        Assert.Equal(innings[0], innings[1]);
        var last = rulings[^1];
        Assert.Equal(0, last.GetProperty("winner").GetInt32());
        Assert.EndsWith($"{Names[0]} wins {points[0]}-{points[1]}.", last.GetProperty("message").GetString(), StringComparison.Ordinal);
        return (points, innings, highest);
    }
}

/// <summary>The shipped three-cushion game in a real GLFW window (under Xvfb when there is no display), to the result panel with the score sheet.</summary>
[Collection("GL")]
public class ThreeCushionScriptedGameWindowTests
{
    [Fact]
    public void TheScriptedGamePlaysInAWindowToTheResultPanelWithTheScoreSheetOfTheRecord()
    {
        HudInfo? last = null;
        string record = ScriptedGames.PlayInWindow(ThreeCushionScriptedGameTests.Script, "three-cushion", ThreeCushionScriptedGameTests.Players, frame => last = frame.Hud, scene: ThreeCushionScriptedGameTests.Scene);
        var (points, innings, highest) = ThreeCushionScriptedGameTests.AssertWholeGame(record);
        ScriptedGames.AssertReplays(record);
        Assert.Equal(SnookerScriptedFrameTests.Shots(record), SnookerScriptedFrameTests.Shots(ThreeCushionScriptedGameTests.PlayHeadless(_ => 0.3)));

        // The last frame on the screen: the result panel is the score sheet of the record.
        var panel = Assert.IsType<ResultPanel>(last!.Result);
        Assert.True(panel.ScoreSheet);
        Assert.Contains(ThreeCushionScriptedGameTests.Names[0], panel.Title, StringComparison.Ordinal);
        string Text(int n) => n.ToString(CultureInfo.InvariantCulture);
        Assert.Equal(
            [
                ("Points", Text(points[0]), Text(points[1])),
                ("Innings", Text(innings[0]), Text(innings[1])),
                ("Average", ThreeCushionRuleset.Average(points[0], innings[0]), ThreeCushionRuleset.Average(points[1], innings[1])),
                ("Highest run", Text(highest[0]), Text(highest[1])),
                ("Games won", "1", "0"),
            ],
            panel.Rows);
        Assert.Contains(last.Buttons!, b => b.Label.StartsWith("Rematch", StringComparison.Ordinal));
    }
}
