using System.Text.RegularExpressions;
using Billiards.App.Cli;
using Billiards.App.Tests.Docs;
using Billiards.Core.Rules;

namespace Billiards.App.Tests.Cli;

/// <summary>
/// <c>--help</c> and docs/command-line.md say the same: every verb of the help has its section on
/// the page (a subcommand such as <c>report accuracy</c> its own), each verb's help line names that
/// section, and the options of a section's table are exactly the options its help lists.
/// </summary>
public sealed partial class HelpAndCommandLinePageTests
{
    private static readonly string s_page = File.ReadAllText(Path.Combine(Markdown.Root, VerbHelp.Page));

    /// <summary>A verb path ("simulate", "report accuracy") and its help text.</summary>
    private static IEnumerable<(string Path, string Help)> Verbs(string path = "")
    {
        string help = Help(path);
        foreach (var (name, _) in Commands(help))
        {
            string child = path.Length == 0 ? name : $"{path} {name}";
            yield return (child, Help(child));
            foreach (var grandchild in Verbs(child))
            {
                yield return grandchild;
            }
        }
    }

    private static string Help(string path)
    {
        var (code, output, error) = CliRun.Run([.. path.Split(' ', StringSplitOptions.RemoveEmptyEntries), "--help"]);
        Assert.True(code == 0, $"{path} --help: exit {code}: {error}");
        return output;
    }

    /// <summary>The lines of one section of a help text ("Options:", "Commands:").</summary>
    private static IEnumerable<string> Section(string help, string title) =>
        help.Replace("\r\n", "\n", StringComparison.Ordinal).Split('\n')
            .SkipWhile(l => l != title).Skip(1).TakeWhile(l => l.StartsWith("  ", StringComparison.Ordinal));

    private static IEnumerable<(string Name, string Description)> Commands(string help) =>
        Section(help, "Commands:").Select(l => CommandLine().Match(l)).Where(m => m.Success)
            .Select(m => (m.Groups[1].Value, m.Groups[2].Value.Trim()));

    /// <summary>The long options of a help text (--help, which every verb has, left out).</summary>
    private static SortedSet<string> HelpOptions(string help) =>
        new(Section(help, "Options:").SelectMany(l => LongOption().Matches(l.Split("  ", StringSplitOptions.RemoveEmptyEntries)[0]))
            .Select(m => m.Value).Where(o => o != "--help"), StringComparer.Ordinal);

    /// <summary>The text of the page's section whose heading is the verb path (up to the next heading).</summary>
    private static string PageSection(string heading)
    {
        var headings = Markdown.Headings(s_page);
        string[] lines = s_page.Replace("\r\n", "\n", StringComparison.Ordinal).Split('\n');
        int i = headings.FindIndex(h => h.Text == heading);
        Assert.True(i >= 0, $"{VerbHelp.Page} has no section \"{heading}\"");
        int end = i + 1 < headings.Count ? headings[i + 1].Line - 1 : lines.Length;
        return string.Join('\n', lines[headings[i].Line..end]);
    }

    /// <summary>The options a section's tables name at the start of their rows.</summary>
    private static SortedSet<string> PageOptions(string section) =>
        new(section.Split('\n').Where(l => l.StartsWith("| `-", StringComparison.Ordinal))
            .SelectMany(l => LongOption().Matches(l.Split('|')[1])).Select(m => m.Value).Where(o => o != "--help"), StringComparer.Ordinal);

    [Fact]
    public void EveryVerbOfTheHelpHasItsSectionAndItsHelpLineNamesIt()
    {
        var anchors = Markdown.Headings(s_page).Select(h => h.Anchor).ToHashSet(StringComparer.Ordinal);
        var verbs = Verbs().ToList();
        Assert.Contains(verbs, v => v.Path == "simulate");
        Assert.Contains(verbs, v => v.Path == "report accuracy");
        Assert.EndsWith($"Docs: {VerbHelp.Page}", Help("").Split("Description:")[1].Split("Usage:")[0].Trim(), StringComparison.Ordinal);
        foreach (var (path, help) in verbs)
        {
            string description = help.Split("Description:")[1].Split("Usage:")[0].Trim();
            string anchor = Markdown.Slug(path);
            Assert.DoesNotContain('\n', description);
            Assert.EndsWith($" Docs: {VerbHelp.Page}#{anchor}", description, StringComparison.Ordinal);
            Assert.Contains(anchor, anchors);
            Assert.Matches(@"^[A-Z][^.]*\. Docs: ", description);
        }
    }

    [Fact]
    public void EachSectionsOptionsAreExactlyTheOptionsItsHelpLists()
    {
        foreach (var (path, help) in Verbs())
        {
            if (Commands(help).Any())
            {
                continue; // a verb of verbs (report): its options are its subcommands'
            }
            var inHelp = HelpOptions(help);
            var onPage = PageOptions(PageSection(path));
            Assert.True(inHelp.SetEquals(onPage),
                $"{path}: in --help, not on the page: {string.Join(' ', inHelp.Except(onPage))}; on the page, not in --help: {string.Join(' ', onPage.Except(inHelp))}");
            Assert.NotEmpty(inHelp);
        }
    }

    [Fact]
    public void TheProgramsOwnOptionsAreOnThePageBeforeTheFirstVerb()
    {
        string intro = s_page[..s_page.IndexOf("\n## ", StringComparison.Ordinal)];
        var options = HelpOptions(Help(""));
        Assert.Contains("--version", options);
        Assert.Equal(options, PageOptions(intro));
    }

    [Fact]
    public void EverySectionOfThePageIsAVerbOfTheHelp()
    {
        var verbs = Verbs().Select(v => v.Path).ToHashSet(StringComparer.Ordinal);
        var sections = Markdown.Headings(s_page).Where(h => h.Level >= 2 && Regex.IsMatch(h.Text, "^[a-z][a-z-]*( [a-z-]+)?$"));
        Assert.All(sections, h => Assert.Contains(h.Text, verbs));
        Assert.Equal(verbs.Count, sections.Count());
    }

    /// <summary>
    /// The help names every registered game; the page every shipped one (Core's rulesets). Other
    /// tests of this process register games of their own (<c>touch</c>), so the help may name
    /// more than the page, but only registered games, and the shipped ones in their order.
    /// </summary>
    [Fact]
    public void EveryRulesOptionNamesEveryRegisteredGameInTheHelpAndOnThePage()
    {
        var shipped = Ruleset.All.Where(r => r.GetType().Assembly == typeof(Ruleset).Assembly).Select(r => r.Name).ToList();
        Assert.Contains("three-cushion", shipped);
        var withRules = Verbs().Where(v => HelpOptions(v.Help).Contains("--rules")).ToList();
        Assert.Contains(withRules, v => v.Path == "selfplay");
        Assert.Contains(withRules, v => v.Path == "host");
        foreach (var (path, help) in withRules)
        {
            string line = Section(help, "Options:").Single(l => l.TrimStart().StartsWith("--rules", StringComparison.Ordinal));
            var registered = RuleNames.GameNames;
            var named = GameName().Matches(line).Select(m => m.Value).Where(registered.Contains).Distinct().ToList();
            Assert.True(named.Where(shipped.Contains).SequenceEqual(shipped), $"{path} --rules names {string.Join(", ", named)}; the shipped games are {string.Join(", ", shipped)}");
            string row = PageSection(path).Split('\n').Single(l => l.StartsWith("| `--rules", StringComparison.Ordinal));
            var onPage = GameName().Matches(row).Select(m => m.Value).Where(registered.Contains).Distinct().ToList();
            Assert.True(onPage.SequenceEqual(shipped), $"{VerbHelp.Page}, {path}: --rules names {string.Join(", ", onPage)}; the shipped games are {string.Join(", ", shipped)}");
        }
    }

    [GeneratedRegex(@"^  (\S+)(?: <[^>]+>)*\s{2,}(.*)$")]
    private static partial Regex CommandLine();

    [GeneratedRegex(@"[a-z]+(?:-[a-z]+)*")]
    private static partial Regex GameName();

    [GeneratedRegex(@"--[a-z][a-z-]*")]
    private static partial Regex LongOption();
}
