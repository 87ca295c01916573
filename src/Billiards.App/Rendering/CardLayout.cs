namespace Billiards.App.Rendering;

/// <summary>
/// A card of the start menu's gallery (a drill): its picture of the table above, its title, and its
/// goal in text one scale smaller, each wrapped to the card. The menu sizes the cards by it and the
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

    /// <summary>The title and goal of a card <paramref name="width"/> pixels wide at text scale <paramref name="scale"/>, wrapped at spaces.</summary>
    public static Lines Text(string title, string? note, float width, int scale)
    {
        ArgumentNullException.ThrowIfNull(title);
        float inner = width - (2 * Pad(scale));
        int small = Math.Max(1, scale - 1);
        var titleLines = HudRenderer.Wrap([title], inner / scale, HudFont.Width);
        var noteLines = note is null ? [] : HudRenderer.Wrap([note], inner / small, HudFont.Width);
        return new Lines(titleLines, scale, noteLines, small);
    }

    /// <summary>The height (pixels) a card <paramref name="width"/> pixels wide needs for its picture, title and goal.</summary>
    public static float Height(string title, string? note, float width, int scale) =>
        Pad(scale) + PictureHeight(width, scale) + (2 * scale) + Text(title, note, width, scale).Height + Pad(scale);

    /// <summary>True when every word of the title fits the card's width whole (no word broken between letters).</summary>
    public static bool TitleWordsFit(string title, float width, int scale)
    {
        ArgumentNullException.ThrowIfNull(title);
        float inner = (width - (2 * Pad(scale))) / scale;
        return title.Split(' ', StringSplitOptions.RemoveEmptyEntries).All(w => HudFont.Width(w) <= inner);
    }
}
