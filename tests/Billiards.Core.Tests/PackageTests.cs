using System.Diagnostics;
using System.IO.Compression;
using System.Runtime.CompilerServices;
using System.Xml.Linq;

namespace Billiards.Core.Tests;

/// <summary>
/// <c>dotnet pack src/Billiards.Core</c> (of the build the tests run on, so no restore and no
/// compile) gives a package with the DLL, its XML docs, the README, the licence, a description,
/// and no dependency: nothing of graphics or audio comes with the physics.
/// </summary>
public sealed class PackageTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-pack-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

#if DEBUG
    private const string Configuration = "Debug";
#else
    private const string Configuration = "Release";
#endif

    private static string Repository([CallerFilePath] string file = "") => Path.GetFullPath(Path.Combine(Path.GetDirectoryName(file)!, "..", ".."));

    [Fact]
    public async Task ThePackageHoldsTheDllItsDocsTheReadmeAndTheLicenceAndDependsOnNothing()
    {
        var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (string a in new[] { "pack", Path.Combine(Repository(), "src", "Billiards.Core", "Billiards.Core.csproj"), "-c", Configuration, "--no-build", "-o", _dir, "-nodeReuse:false" })
        {
            start.ArgumentList.Add(a);
        }
        using (var process = Process.Start(start)!)
        {
            var stdout = process.StandardOutput.ReadToEndAsync();
            string stderr = await process.StandardError.ReadToEndAsync();
            Assert.True(process.WaitForExit(120_000), "dotnet pack did not finish");
            Assert.True(process.ExitCode == 0, await stdout + stderr);
        }

        string package = Assert.Single(Directory.GetFiles(_dir, "Billiards.Core.*.nupkg"));
        using var zip = ZipFile.OpenRead(package);
        string[] entries = [.. zip.Entries.Select(e => e.FullName)];
        Assert.Contains("lib/net10.0/Billiards.Core.dll", entries);
        Assert.Contains("lib/net10.0/Billiards.Core.xml", entries);
        Assert.Contains("README.md", entries);
        Assert.Contains("LICENSE", entries);

        XNamespace ns = "http://schemas.microsoft.com/packaging/2012/06/nuspec.xsd";
        using var nuspec = zip.GetEntry("Billiards.Core.nuspec")!.Open();
        var metadata = XDocument.Load(nuspec).Root!.Element(ns + "metadata")!;
        Assert.Equal("Billiards.Core", metadata.Element(ns + "id")!.Value);
        Assert.Equal(Path.GetFileName(package), $"Billiards.Core.{metadata.Element(ns + "version")!.Value}.nupkg");
        Assert.Equal("MIT", metadata.Element(ns + "license")!.Value);
        Assert.Equal("README.md", metadata.Element(ns + "readme")!.Value);
        Assert.Contains("physics", metadata.Element(ns + "description")!.Value, StringComparison.Ordinal);
        Assert.Empty(metadata.Descendants(ns + "dependency"));
    }
}
