namespace Billiards.App.Rendering;

/// <summary>
/// The help overlay's lines (<see cref="Hud.HelpText"/>) laid out in two columns for the HUD's
/// proportional font: the keys, then their text, every text starting at one x, so that the column
/// reads straight however wide the keys' letters are. The lines keep a fixed-width form: a section
/// starts at column 0; a key's line has two spaces, the key, and its text from
/// <see cref="TextColumn"/>; a line of only spaces up to <see cref="TextColumn"/> continues the
/// text above; any other line indented by two is a note under its section.
/// </summary>
public static class HelpLayout
{
    /// <summary>The character column a key's text starts at in <see cref="Hud.HelpText.Lines"/>.</summary>
    public const int TextColumn = 15;

    /// <summary>A piece of text at <see cref="X"/> (HUD units from the overlay's left) on row <see cref="Row"/>; <see cref="Title"/> for a section's title.</summary>
    public readonly record struct Run(string Text, float X, int Row, bool Title = false);

    /// <summary>A line's role, and its key and text.</summary>
    public enum Kind
    {
        /// <summary>A section's title, at the left.</summary>
        Section,
        /// <summary>A key and its text.</summary>
        Key,
        /// <summary>More text of the key above.</summary>
        Continued,
        /// <summary>A note under a section, indented as the keys are.</summary>
        Note,
    }

    /// <summary>The role of one help line, its key (empty but for <see cref="Kind.Key"/>) and its text.</summary>
    public static (Kind Kind, string Key, string Text) Parse(string line)
    {
        ArgumentNullException.ThrowIfNull(line);
        if (line.Length == 0 || line[0] != ' ')
        {
            return (Kind.Section, "", line);
        }
        if (line.Length > TextColumn && line.AsSpan(0, TextColumn).IsWhiteSpace())
        {
            return (Kind.Continued, "", line[TextColumn..].Trim());
        }
        if (line.Length > TextColumn && line.StartsWith("  ", StringComparison.Ordinal) && line[2] != ' '
            && line[TextColumn - 1] == ' ' && line[TextColumn] != ' ')
        {
            return (Kind.Key, line[2..TextColumn].Trim(), line[TextColumn..].Trim());
        }
        return (Kind.Note, "", line.Trim());
    }

    /// <summary>
    /// Lays the lines out within <paramref name="fit"/> HUD units (as <paramref name="measure"/>
    /// measures text): keys after an indent, their texts from one column, texts too long for the
    /// room wrapped at spaces under themselves (<see cref="HudRenderer.Wrap(IReadOnlyList{string}, float, Func{string, float})"/>;
    /// no text dropped). Returns the runs, the widest row's width and the number of rows.
    /// </summary>
    public static (List<Run> Runs, float Width, int Rows) Layout(IReadOnlyList<string> lines, float fit, Func<string, float> measure)
    {
        ArgumentNullException.ThrowIfNull(lines);
        ArgumentNullException.ThrowIfNull(measure);
        var parsed = lines.Select(Parse).ToList();
        float indent = measure("  "), gap = measure("   ");
        float keys = parsed.Where(p => p.Kind == Kind.Key).Select(p => measure(p.Key)).DefaultIfEmpty(0).Max();
        float column = indent + keys + gap;
        var runs = new List<Run>();
        float width = 0;
        int row = 0;
        void Put(string text, float x, float room, bool title = false)
        {
            foreach (string piece in HudRenderer.Wrap([text], MathF.Max(60, room), measure))
            {
                runs.Add(new Run(piece, x, row++, title));
                width = MathF.Max(width, x + measure(piece));
            }
        }
        foreach (var (kind, key, text) in parsed)
        {
            switch (kind)
            {
                case Kind.Section:
                    Put(text, 0, fit, title: true);
                    break;
                case Kind.Note:
                    Put(text, indent, fit - indent);
                    break;
                case Kind.Key:
                    runs.Add(new Run(key, indent, row));
                    width = MathF.Max(width, indent + measure(key));
                    Put(text, column, fit - column);
                    break;
                case Kind.Continued:
                    Put(text, column, fit - column);
                    break;
            }
        }
        return (runs, width, row);
    }
}
