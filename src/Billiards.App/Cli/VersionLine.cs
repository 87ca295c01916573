using System.CommandLine;
using System.CommandLine.Invocation;
using System.Reflection;

namespace Billiards.App.Cli;

/// <summary>
/// <c>billiards --version</c>: prints <c>billiards VERSION</c>, the repository's one version
/// (Directory.Build.props), and exits 0 (scene-format.md). System.CommandLine's own version
/// action would print the bare informational version with the commit appended.
/// </summary>
internal sealed class VersionLine : SynchronousCommandLineAction
{
    /// <summary>The version, without the build metadata (the commit) the SDK appends after '+'.</summary>
    public static string Version
    {
        get
        {
            string informational = typeof(VersionLine).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion ?? "0.0.0";
            int plus = informational.IndexOf('+', StringComparison.Ordinal);
            return plus < 0 ? informational : informational[..plus];
        }
    }

    /// <summary>Puts this action on the root command's version option.</summary>
    public static void Install(RootCommand root)
    {
        foreach (Option option in root.Options)
        {
            if (option is VersionOption version)
            {
                version.Action = new VersionLine();
            }
        }
    }

    /// <inheritdoc />
    public override int Invoke(ParseResult parseResult)
    {
        parseResult.InvocationConfiguration.Output.WriteLine($"billiards {Version}");
        return 0;
    }
}
