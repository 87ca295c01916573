namespace Billiards.App.Tests.Docs;

/// <summary>
/// The front page and the manual link only to what exists: every relative link and picture of
/// README.md and of every page under docs/ names a file of the repository, and every anchor a
/// heading of its page.
/// </summary>
public sealed class DocsLinkTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-docs-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    public static TheoryData<string> Pages()
    {
        var pages = new TheoryData<string> { "README.md" };
        foreach (string file in Directory.EnumerateFiles(Path.Combine(Markdown.Root, "docs"), "*.md", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
        {
            pages.Add(Path.GetRelativePath(Markdown.Root, file).Replace('\\', '/'));
        }
        return pages;
    }

    [Theory]
    [MemberData(nameof(Pages))]
    public void EveryRelativeLinkAndAnchorOfThePageResolves(string page)
    {
        string file = Path.Combine(Markdown.Root, page);
        Assert.NotEmpty(Markdown.Links(File.ReadAllText(file)));
        Assert.Empty(Markdown.BrokenLinks(file));
    }

    [Theory]
    [MemberData(nameof(Pages))]
    public void EveryPictureNamesTheCommandThatMakesIt(string page)
    {
        // In its caption (a command in backquotes), or, for the pages a report writes with its
        // plots, in the page's own "Made by `billiards report ...`".
        string text = File.ReadAllText(Path.Combine(Markdown.Root, page));
        bool madeByReport = text.Contains("Made by `billiards report", StringComparison.Ordinal);
        foreach (var (alt, target) in Markdown.Pictures(text))
        {
            Assert.True(madeByReport || s_command.IsMatch(alt), $"{page}: the picture {target} names no command that makes it again: \"{alt}\"");
        }
    }

    private static readonly System.Text.RegularExpressions.Regex s_command = new("`(billiards |python3 |tools/docs/)[^`]*`");

    [Fact]
    public void TheManualIsThere()
    {
        string[] pages = ["playing", "replay-and-practice", "games-and-rules", "command-line", "file-formats", "physics",
                          "computer-player", "performance", "scaling-out", "architecture", "contributing"];
        string readme = File.ReadAllText(Path.Combine(Markdown.Root, "README.md"));
        Assert.All(pages, p => Assert.Contains($"(docs/{p}.md)", readme, StringComparison.Ordinal));
    }

    [Fact]
    public void TheCheckerFindsAMissingFileAMissingAnchorAndAnAnchorOfTheSamePage()
    {
        File.WriteAllText(Path.Combine(_dir, "other.md"), "# Other\n\n## A section: with (punctuation)\n");
        string page = Path.Combine(_dir, "page.md");
        File.WriteAllText(page, string.Join('\n',
            "# Page", "## Here", "",
            "[fine](other.md#a-section-with-punctuation) [fine too](#here) [web](https://example.org/x.md)",
            "[gone](missing.md) [no anchor](other.md#nowhere) [not here](#elsewhere)",
            "`[in code](missing-too.md)`", "```", "[in a block](missing-three.md)", "```",
            "![picture](gone.png)"));

        var broken = Markdown.BrokenLinks(page);

        Assert.Equal(4, broken.Count);
        Assert.Contains(broken, b => b.Contains("(missing.md): no such file", StringComparison.Ordinal));
        Assert.Contains(broken, b => b.Contains("(other.md#nowhere): no heading with the anchor #nowhere", StringComparison.Ordinal));
        Assert.Contains(broken, b => b.Contains("(#elsewhere): no heading", StringComparison.Ordinal));
        Assert.Contains(broken, b => b.Contains("(gone.png): no such file", StringComparison.Ordinal));
    }
}
