namespace Billiards.App.Rendering;

/// <summary>
/// A card of the start menu's gallery (a drill): its picture of the table above, its title, and its
/// goal in text of its own scale (the title's or smaller), each wrapped to the card; a title's
/// hyphenated word may break after a hyphen, no word between letters. The menu sizes the cards by it and the
/// HUD draws them by it, so that what is drawn is what was measured: every word inside its card.
/// </summary>
public static class CardLayout
{
    /// <summary>The card's inner margin, in units of its text scale.</summary>
    public const int PadUnits = 4;

    /// <summary>The picture's height over its width (a table is twice as long as wide).</summary>
    public const float PictureAspect = 0.5f;

    /// <summary>The lines of a card's title and goal, and the scales they are drawn at.</summary>
    public sealed record Lines(IReadOnlyList<string> Title, int TitleScale, IReadOnlyList<string> Note, int NoteScale)
    {
        /// <summary>The height of the text under the picture (pixels).</summary>
        public float Height => (Title.Count * HudFont.LineHeight * TitleScale) + (Note.Count * HudFont.LineHeight * NoteScale);
    }

    /// <summary>The inner margin (pixels) of a card drawn at <paramref name="scale"/>.</summary>
    public static float Pad(int scale) => PadUnits * scale;

    /// <summary>The picture's height (pixels) in a card <paramref name="width"/> pixels wide.</summary>
    public static float PictureHeight(float width, int scale) => (width - (2 * Pad(scale))) * PictureAspect;

    /// <summary>The title and goal of a card <paramref name="width"/> pixels wide, the title at <paramref name="scale"/>, the goal at <paramref name="noteScale"/>, wrapped at spaces (the title also after hyphens).</summary>
    public static Lines Text(string title, string? note, float width, int scale, int noteScale)
    {
        ArgumentNullException.ThrowIfNull(title);
        float inner = width - (2 * Pad(scale));
        var titleLines = TitleLines(title, inner / scale);
        var noteLines = note is null ? [] : HudRenderer.Wrap([note], inner / noteScale, HudFont.Width);
        return new Lines(titleLines, scale, noteLines, noteScale);
    }

    /// <summary>The height (pixels) a card <paramref name="width"/> pixels wide needs for its picture, title and goal.</summary>
    public static float Height(string title, string? note, float width, int scale, int noteScale) =>
        Pad(scale) + PictureHeight(width, scale) + (2 * scale) + Text(title, note, width, scale, noteScale).Height + Pad(scale);

    /// <summary>True when every word of the title, or each part of a hyphenated one, fits the card's width whole.</summary>
    public static bool TitleWordsFit(string title, float width, int scale)
    {
        ArgumentNullException.ThrowIfNull(title);
        float inner = (width - (2 * Pad(scale))) / scale;
        return Pieces(title, inner).All(p => HudFont.Width(p.Text) <= inner);
    }

    // The title's words, a word too wide for the line cut after its hyphens ("Long-short-" "long").
    private static IEnumerable<(string Text, bool Space)> Pieces(string title, float inner)
    {
        foreach (string word in title.Split(' ', StringSplitOptions.RemoveEmptyEntries))
        {
            if (HudFont.Width(word) <= inner || !word.Contains('-', StringComparison.Ordinal))
            {
                yield return (word, true);
                continue;
            }
            int start = 0;
            for (int i = word.IndexOf('-', StringComparison.Ordinal); i >= 0 && i < word.Length - 1; i = word.IndexOf('-', i + 1))
            {
                yield return (word[start..(i + 1)], start == 0);
                start = i + 1;
            }
            yield return (word[start..], start == 0);
        }
    }

    // The title in lines no wider than inner (units), filled greedily with its pieces.
    private static List<string> TitleLines(string title, float inner)
    {
        var lines = new List<string>();
        string line = "";
        foreach (var (text, space) in Pieces(title, inner))
        {
            string joined = line.Length == 0 ? text : line + (space ? " " : "") + text;
            if (line.Length == 0 || HudFont.Width(joined) <= inner)
            {
                line = joined;
                continue;
            }
            lines.Add(line);
            line = text;
        }
        if (line.Length > 0)
        {
            lines.Add(line);
        }
        return lines;
    }
}
