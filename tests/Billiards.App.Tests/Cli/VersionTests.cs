using System.Xml.Linq;

namespace Billiards.App.Tests.Cli;

/// <summary><c>billiards --version</c> prints <c>billiards VERSION</c>, the one version of Directory.Build.props, and exits 0 (scene-format.md).</summary>
public class VersionTests
{
    [Fact]
    public void VersionPrintsTheRepositorysOneVersion()
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (!File.Exists(Path.Combine(dir.FullName, "Directory.Build.props")))
        {
            dir = dir.Parent ?? throw new InvalidOperationException("Directory.Build.props is not above the test assembly");
        }
        string version = XDocument.Load(Path.Combine(dir.FullName, "Directory.Build.props")).Descendants("Version").Single().Value;

        var (code, stdout, stderr) = CliRun.Run("--version");

        Assert.Equal(0, code);
        Assert.Equal($"billiards {version}{Environment.NewLine}", stdout);
        Assert.Equal("", stderr);
    }
}
