using Billiards.App.Hud;
using Billiards.App.Rendering;

namespace Billiards.App.Tests.Rendering;

/// <summary>
/// The help overlay reads as two columns in the HUD's proportional font: every key's text starts
/// at one x, whatever the key's letters, at any width the overlay gets; nothing is dropped when
/// texts wrap; and every line of the help keeps the fixed form the layout reads.
/// </summary>
public sealed class HelpLayoutTests
{
    private static IEnumerable<string> Words(IEnumerable<string> texts) =>
        texts.SelectMany(t => t.Split(' ', StringSplitOptions.RemoveEmptyEntries));

    [Fact]
    public void EveryLineOfTheHelpIsASectionAKeyItsContinuationOrTheOneNote()
    {
        var kinds = HelpText.Lines.Select(HelpLayout.Parse).ToList();
        // A key that ran into the text's column would read as a note: the help has one note only.
        var note = Assert.Single(kinds, k => k.Kind == HelpLayout.Kind.Note);
        Assert.StartsWith("While balls roll", note.Text, StringComparison.Ordinal);
        Assert.Equal(["Modes", "Cue", "Match (the referee's rulings pass the turn)", "Practice and drills (play --practice, play --drill NAME, or the start menu)", "Replay and take-back", "Game"],
            kinds.Where(k => k.Kind == HelpLayout.Kind.Section).Select(k => k.Text));
        Assert.Contains(kinds, k => k.Kind == HelpLayout.Kind.Key && k.Key == "PageUp/Down" && k.Text.StartsWith("replay GAME.json", StringComparison.Ordinal));
        Assert.Contains(kinds, k => k.Kind == HelpLayout.Kind.Key && k.Key == "Left / Right" && k.Text.StartsWith("aim 1 deg", StringComparison.Ordinal));
        Assert.All(kinds.Where(k => k.Kind == HelpLayout.Kind.Key), k => Assert.DoesNotContain("  ", k.Key, StringComparison.Ordinal));
    }

    [Theory]
    [InlineData(float.MaxValue)]
    [InlineData(400f)]
    [InlineData(250f)]
    public void TheKeysTextsStartInOneColumnAndNoWordIsLost(float fit)
    {
        var lines = HelpText.Lines;
        var (runs, width, rows) = HelpLayout.Layout(lines, fit, HudFont.Width);
        var parsed = lines.Select(HelpLayout.Parse).ToList();
        var keys = parsed.Where(p => p.Kind == HelpLayout.Kind.Key).Select(p => p.Key).ToHashSet();
        // The keys at one indent; every other run of a key's line or its continuation at one column right of every key.
        float indent = HudFont.Width("  ");
        var keyRuns = runs.Where(r => !r.Title && r.X == indent && keys.Contains(r.Text)).ToList();
        Assert.Equal(parsed.Count(p => p.Kind == HelpLayout.Kind.Key), keyRuns.Count);
        var textRuns = runs.Where(r => r.X > indent).ToList();
        float column = Assert.Single(textRuns.Select(r => r.X).Distinct());
        Assert.True(column > keys.Max(HudFont.Width) + indent, $"the text column {column} is not right of every key");
        // Each key's text starts on its key's row.
        Assert.All(keyRuns, k => Assert.Contains(textRuns, t => t.Row == k.Row));
        // Nothing dropped, nothing wider than the room (a row of the layout is one run per column).
        Assert.Equal(Words(parsed.Select(p => p.Key)).Concat(Words(parsed.Select(p => p.Text))).Order(), Words(runs.Select(r => r.Text)).Order());
        Assert.All(runs, r => Assert.True(r.X + HudFont.Width(r.Text) <= MathF.Max(fit, column + 60) + 0.01f, $"\"{r.Text}\" runs past {fit}"));
        Assert.Equal(runs.Max(r => r.X + HudFont.Width(r.Text)), width, 3);
        Assert.Equal(runs.Max(r => r.Row) + 1, rows);
        if (fit < float.MaxValue)
        {
            Assert.True(rows > lines.Count, "a narrow overlay wraps texts onto more rows");
        }
        else
        {
            Assert.Equal(lines.Count, rows);
        }
    }
}
