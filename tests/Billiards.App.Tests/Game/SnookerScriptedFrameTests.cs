using System.Text.Json;
using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The shipped whole snooker frame, <c>assets/scripts/snooker-frame.json</c> (made by
/// <c>tools/game-script --snooker</c>): two people play it through real input from the break-off
/// in the D (B picks and nominates a ball, X aims at its ghost ball, W/Q the power, Space strikes,
/// 3 takes the offered replace) to the end of the frame the referee declares: Anna's four pots
/// (a red, a colour, a red, a colour: 13 points), then her three fouls and misses with a full view
/// of a red, 4 points each to Ben, the first two replaced by him; the third loses her the frame,
/// and Ben wins it though behind 12-13 on points.
/// </summary>
public class SnookerScriptedFrameTests
{
    public static string Script => Path.Combine(AssetFolder.Assets, "scripts", "snooker-frame.json");

    private static string PlayHeadless(double frameSeconds)
    {
        string record = Path.Combine(Path.GetTempPath(), $"snooker-{Guid.NewGuid():N}.json");
        try
        {
            var clock = new ManualClock();
            var window = new FakeWindow { FramebufferSize = (1280, 720) };
            var loop = new UntilClosedLoop(clock, window, frameSeconds);
            int code = PlayCommand.Play(null, _ => new GamePlatform(window, loop, new NullFrameRenderer()), SimulationFactory.Create, clock,
                new PlayCommand.PlayOptions(Script, null) { Rules = "snooker", Players = "Anna,Ben", Record = record });
            Assert.Equal(0, code);
            Assert.True(window.Closed, "the script never ended");
            return File.ReadAllText(record);
        }
        finally
        {
            File.Delete(record);
        }
    }

    [Fact]
    public void TheScriptedFrameEndsWithBenWinningOnTheThreeMissRuleBehind1213AndReplays()
    {
        string text = PlayHeadless(1.0 / 60);
        using var doc = JsonDocument.Parse(text);
        var shots = doc.RootElement.GetProperty("shots").EnumerateArray().ToList();
        var rulings = shots.Select(s => s.GetProperty("ruling")).ToList();
        Assert.Equal(7, shots.Count);

        // The break-off from the D, the first shot of the frame.
        Assert.Equal(0, shots[0].GetProperty("game").GetProperty("shot").GetInt32());
        var place = shots[0].GetProperty("place");
        Assert.True(Core.Table.SnookerTable.InD(Core.Table.SnookerTable.Spec, new Core.Mathematics.Vec3(place[0].GetDouble(), place[1].GetDouble(), 0)));

        // The score as the rulings add it up: each shot's points to its striker, each penalty to the other.
        var score = new int[2];
        foreach (var (shot, ruling) in shots.Zip(rulings))
        {
            int striker = shot.GetProperty("game").GetProperty("shooter").GetInt32();
            score[striker] += ruling.GetProperty("points").GetInt32();
            score[1 - striker] += ruling.GetProperty("penalty").GetInt32();
        }
        Assert.Equal([13, 12], score);
        // Anna's four pots keep her at the table, a colour nominated after each red.
        Assert.All(rulings.Take(4), r => Assert.True(r.GetProperty("legal").GetBoolean() && r.GetProperty("continue").GetBoolean()));
        Assert.Equal("colour", shots[1].GetProperty("game").GetProperty("ball_on").GetString());
        Assert.Equal(JsonValueKind.Object, shots[1].GetProperty("call").ValueKind);

        // Three fouls and misses, the first two replaced by Ben, the third loses Anna the frame.
        Assert.All(rulings.Skip(4), r => Assert.True(r.GetProperty("foul_and_miss").GetBoolean()));
        Assert.All(shots.Skip(4).Take(2), s => Assert.Equal("replace", s.GetProperty("choice").GetString()));
        var last = rulings[^1];
        Assert.True(last.GetProperty("game_over").GetBoolean());
        Assert.Equal(1, last.GetProperty("winner").GetInt32());
        Assert.Contains("three-misses", last.GetProperty("fouls").EnumerateArray().Select(f => f.GetString()));
        Assert.Contains("Ben wins the frame", last.GetProperty("message").GetString(), StringComparison.Ordinal);

        // The same frame at 3 frames a second, and its record replays shot for shot.
        Assert.Equal(doc.RootElement.GetProperty("shots").GetRawText(), JsonDocument.Parse(PlayHeadless(0.3)).RootElement.GetProperty("shots").GetRawText());
        var report = GameRecordFile.Verify(GameRecordFile.Parse(text, "frame.json"), out _);
        Assert.Null(report.FirstDifference);
        Assert.Equal(shots.Count, report.Same);
    }

    private sealed class NullFrameRenderer : IFrameRenderer
    {
        public void Draw(Billiards.App.Rendering.RenderFrame frame)
        {
        }
    }
}
