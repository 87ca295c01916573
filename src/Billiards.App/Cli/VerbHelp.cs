using Billiards.Core.Rules;

namespace Billiards.App.Cli;

/// <summary>
/// The one line of <c>--help</c> that says what a verb does, followed by where it is documented:
/// its section of <see cref="Page"/>, whose headings are the verbs (a test holds the help and the
/// page together).
/// </summary>
public static class VerbHelp
{
    /// <summary>The page that documents every verb and option, relative to the repository.</summary>
    public const string Page = "docs/command-line.md";

    /// <summary>The program's own description: what it is and where its verbs are documented.</summary>
    public static string Root => $"Billiards: a pool game and billiards physics engine. Docs: {Page}";

    /// <summary>A verb's description: <paramref name="what"/> and its section of the page.</summary>
    /// <param name="what">One sentence: what the verb does.</param>
    /// <param name="section">The section's anchor on the page, e.g. "simulate" or "report-accuracy".</param>
    public static string Verb(string what, string section) => $"{what} Docs: {Page}#{section}";

    /// <summary>
    /// The games a <c>--rules</c> option takes, from the registered rulesets: "eight-ball, nine-ball, ...
    /// or three-cushion", so that a game added to the registry is in every verb's help.
    /// </summary>
    public static string Games
    {
        get
        {
            var names = RuleNames.GameNames;
            return names.Count < 2 ? string.Join("", names) : $"{string.Join(", ", names.Take(names.Count - 1))} or {names[^1]}";
        }
    }
}
