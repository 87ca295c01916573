using Billiards.App.Hud;
using Billiards.App.Rendering;
using Billiards.Core.Rules;

namespace Billiards.App.Tests.Hud;

/// <summary>
/// Every ruling reaches the player whole: the scoreboard wraps its message and never cuts it ("..."),
/// at 1280 x 720 and at 900 x 560, for the longest message of every ruling code (rules.md's codes:
/// the referee's sentence at its longest, two fouls joined, the longest names, the options and the
/// warning) and for the longest rulings of the shipped snooker record.
/// </summary>
public class RulingWrapTests
{
    private const string LongName = "Computer L5 (2) Alexandra";

    public static TheoryData<string, int, int> Codes()
    {
        var data = new TheoryData<string, int, int>();
        foreach (var foul in Enum.GetValues<Foul>())
        {
            foreach (var (w, h) in new[] { (1280, 720), (900, 560) })
            {
                data.Add(foul.ToName(), w, h);
            }
        }
        return data;
    }

    // The referee's sentence for a foul at its longest: its reason with the longest ball names, a
    // second foul joined by "and", ball in hand behind the head string, every option and a warning.
    private static string LongestMessage(string code)
    {
        string reason = $"{code.Replace('-', ' ')}: the cue ball first struck the fifteen-ball, not the lowest numbered ball on the table, and pocketed the eleven-ball and the fourteen-ball";
        return $"Foul by {LongName}: {reason} and the cue ball was pocketed in the foot-right corner pocket. {LongName} has ball in hand behind the head string. "
            + $"{LongName} chooses: play or put-back or replace or pass-back or re-rack. Warning: a third miss in a row with a full ball view loses {LongName} the frame; 7 points to {LongName}.";
    }

    private static Scoreboard Board(string message) => new(
        "Snooker  shot 123  remaining 147  frames 10-10",
        "H help  no sound",
        [new PlayerCard(LongName, true, "71, free ball: black", [1, 2, 3], "break 12"), new PlayerCard(LongName, false, "on a red", [], "needs snookers")],
        "FREE BALL: nominate pink (B, click a ball);  ball in hand (the D): M, drag;  Space shoots, G hint",
        message,
        ["Foul by Ben: the cue ball struck no ball. Anna is at the table.", "Anna pots the red: 1 point."]);

    private static void AssertWhole(string message, int width, int height)
    {
        int scale = HudRenderer.Scale(height);
        float columnWidth = HudRenderer.BoardCentreUnits(width, scale);
        var rows = HudRenderer.CentreRows(Board(message), columnWidth, HudFont.Width);
        Assert.DoesNotContain(rows, r => r.Text.Contains("...", StringComparison.Ordinal));
        Assert.All(rows, r => Assert.True(HudFont.Width(r.Text) <= columnWidth, $"'{r.Text}' is wider than {columnWidth}"));
        // The message's rows, joined, are the message: no word lost.
        var messageRows = rows.Where(r => r.Colour == 0).Skip(1).Select(r => r.Text.Trim());
        Assert.Equal(message.Split(' ', StringSplitOptions.RemoveEmptyEntries), string.Join(' ', messageRows).Split(' ', StringSplitOptions.RemoveEmptyEntries));
    }

    [Theory]
    [MemberData(nameof(Codes))]
    public void TheLongestMessageOfEveryRulingCodeIsWrappedWhole(string code, int width, int height) => AssertWhole(LongestMessage(code), width, height);

    [Theory]
    [InlineData(1280, 720)]
    [InlineData(900, 560)]
    public void TheShippedRecordsLongestRulingsAreWrappedWhole(int width, int height)
    {
        string text = File.ReadAllText(Path.Combine(Billiards.Core.Scenes.AssetFolder.Assets, "records", "snooker-opening.json"));
        var messages = System.Text.RegularExpressions.Regex.Matches(text, "\"message\": \"([^\"]*)\"").Select(m => m.Groups[1].Value).Distinct().OrderByDescending(m => m.Length).Take(5).ToList();
        Assert.NotEmpty(messages);
        foreach (string m in messages)
        {
            AssertWhole(m, width, height);
        }
    }

    [Fact]
    public void AWordWiderThanTheLineBreaksBetweenCharactersAndNothingIsLost()
    {
        var rows = HudRenderer.Wrap(["a " + new string('x', 50) + " b"], 12, s => s.Length);
        Assert.Equal("a" + new string('x', 50) + "b", string.Concat(rows.Select(r => r.Replace(" ", "", StringComparison.Ordinal))));
        Assert.All(rows, r => Assert.True(r.Length <= 12, r));
    }
}
