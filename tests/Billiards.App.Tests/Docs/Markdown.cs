using System.Text;
using System.Text.RegularExpressions;

namespace Billiards.App.Tests.Docs;

/// <summary>The repository's Markdown as a reader sees it: headings with their anchors, and links.</summary>
internal static partial class Markdown
{
    /// <summary>The repository's root (the folder of Billiards.sln above the test assembly).</summary>
    public static string Root { get; } = FindRoot();

    /// <summary>A heading: its level (1 for #), its text and its anchor.</summary>
    public sealed record Heading(int Level, string Text, string Anchor, int Line);

    /// <summary>A link or picture: its target as written and the line it is on.</summary>
    public sealed record Link(string Target, int Line);

    /// <summary>The lines of a document outside fenced code blocks, with their 1-based numbers.</summary>
    public static IEnumerable<(int Number, string Text)> ProseLines(string text)
    {
        bool fenced = false;
        string[] lines = text.Replace("\r\n", "\n", StringComparison.Ordinal).Split('\n');
        for (int i = 0; i < lines.Length; i++)
        {
            if (lines[i].TrimStart().StartsWith("```", StringComparison.Ordinal))
            {
                fenced = !fenced;
                continue;
            }
            if (!fenced)
            {
                yield return (i + 1, lines[i]);
            }
        }
    }

    /// <summary>Every heading, with the anchor GitHub and DocFX give it (repeats get -1, -2, ...).</summary>
    public static List<Heading> Headings(string text)
    {
        var seen = new Dictionary<string, int>(StringComparer.Ordinal);
        var headings = new List<Heading>();
        foreach (var (number, line) in ProseLines(text))
        {
            Match m = HeadingLine().Match(line);
            if (!m.Success)
            {
                continue;
            }
            string title = m.Groups[2].Value.Trim();
            string anchor = Slug(title);
            if (seen.TryGetValue(anchor, out int n))
            {
                seen[anchor] = n + 1;
                anchor = $"{anchor}-{n + 1}";
            }
            else
            {
                seen[anchor] = 0;
            }
            headings.Add(new Heading(m.Groups[1].Value.Length, title, anchor, number));
        }
        return headings;
    }

    /// <summary>A heading's anchor: lower case, punctuation dropped, spaces as hyphens.</summary>
    public static string Slug(string heading)
    {
        var b = new StringBuilder();
        foreach (char c in heading.ToLowerInvariant())
        {
            if (char.IsLetterOrDigit(c) || c == '-' || c == '_')
            {
                b.Append(c);
            }
            else if (c == ' ')
            {
                b.Append('-');
            }
        }
        return b.ToString();
    }

    /// <summary>Every inline link and picture outside code (fenced blocks and code spans).</summary>
    public static List<Link> Links(string text)
    {
        var links = new List<Link>();
        foreach (var (number, line) in ProseLines(text))
        {
            string prose = CodeSpan().Replace(line, "");
            foreach (Match m in InlineLink().Matches(prose))
            {
                links.Add(new Link(m.Groups[1].Value, number));
            }
        }
        return links;
    }

    /// <summary>Every picture outside fenced code: its alt text and its target.</summary>
    public static List<(string Alt, string Target)> Pictures(string text) =>
        [.. ProseLines(text).SelectMany(l => Picture().Matches(l.Text)).Select(m => (m.Groups[1].Value, m.Groups[2].Value))];

    /// <summary>
    /// The broken relative links of a Markdown file: a target that does not exist, or an anchor
    /// that no heading of the target (or of the file itself, for "#anchor") has. Web addresses and
    /// DocFX cross-references (xref:) are not followed.
    /// </summary>
    public static List<string> BrokenLinks(string file)
    {
        var broken = new List<string>();
        string folder = Path.GetDirectoryName(file)!;
        foreach (Link link in Links(File.ReadAllText(file)))
        {
            string target = link.Target;
            if (Regex.IsMatch(target, "^[a-z][a-z0-9+.-]*:", RegexOptions.IgnoreCase))
            {
                continue;
            }
            string path = target;
            string? anchor = null;
            int hash = target.IndexOf('#', StringComparison.Ordinal);
            if (hash >= 0)
            {
                path = target[..hash];
                anchor = target[(hash + 1)..];
            }
            string full = path.Length == 0 ? file : Path.GetFullPath(Path.Combine(folder, Uri.UnescapeDataString(path)));
            string where = $"{Path.GetRelativePath(Root, file)}:{link.Line}: ({target})";
            if (!File.Exists(full) && !Directory.Exists(full))
            {
                broken.Add($"{where}: no such file");
                continue;
            }
            if (anchor is not null)
            {
                if (!full.EndsWith(".md", StringComparison.OrdinalIgnoreCase) || !File.Exists(full))
                {
                    broken.Add($"{where}: an anchor into a file that is not Markdown");
                }
                else if (!Headings(File.ReadAllText(full)).Any(h => h.Anchor == anchor))
                {
                    broken.Add($"{where}: no heading with the anchor #{anchor}");
                }
            }
        }
        return broken;
    }

    private static string FindRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "Billiards.sln")))
            {
                return dir.FullName;
            }
        }
        throw new InvalidOperationException("the repository (Billiards.sln) is not above the test assembly");
    }

    [GeneratedRegex(@"!\[((?:[^\]`]|`[^`]*`)*)\]\(([^)\s]+)\)")]
    private static partial Regex Picture();

    [GeneratedRegex(@"^(#{1,6})\s+(.*?)\s*#*\s*$")]
    private static partial Regex HeadingLine();

    [GeneratedRegex(@"`[^`]*`")]
    private static partial Regex CodeSpan();

    [GeneratedRegex(@"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+""[^""]*"")?\s*\)")]
    private static partial Regex InlineLink();
}
