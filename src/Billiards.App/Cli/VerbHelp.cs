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
}
