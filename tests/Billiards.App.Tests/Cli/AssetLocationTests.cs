using System.Diagnostics;
using Billiards.App.Cli;
using Billiards.App.Rendering;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Cli;

/// <summary>
/// The program finds its own assets beside its executable, whatever the working folder, while a
/// user's paths stay relative to the working folder; a missing or unreadable asset is one line.
/// </summary>
[Collection("GL")]
public sealed class AssetLocationTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-elsewhere-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    /// <summary>Runs the built billiards in its own process, from the temporary folder.</summary>
    private (int Code, string Out, string Err) Billiards(params string[] args)
    {
        var start = new ProcessStartInfo("dotnet")
        {
            WorkingDirectory = _dir,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "billiards.dll"));
        foreach (string a in args)
        {
            start.ArgumentList.Add(a);
        }
        using var process = Process.Start(start)!;
        var stdout = process.StandardOutput.ReadToEndAsync();
        string stderr = process.StandardError.ReadToEnd();
        Assert.True(process.WaitForExit(120_000), "billiards did not finish");
        return (process.ExitCode, stdout.Result, stderr);
    }

    [Fact]
    public void RenderAndSimulateRunFromAFolderWithoutAssets()
    {
        Assert.False(Directory.Exists(Path.Combine(_dir, "assets")));
        File.Copy(AssetFolder.Scene("eight-ball-break.json"), Path.Combine(_dir, "break.json"));

        // The scene and the picture are the user's paths, relative to the working folder; the
        // fonts of the ball numbers and the table model come from beside the executable.
        var (code, _, err) = Billiards("render", "break.json", "--out", "break.png", "--width", "320", "--height", "200");
        Assert.True(code == 0, err);
        var (w, h, pixels) = PngDecoder.Decode(File.ReadAllBytes(Path.Combine(_dir, "break.png")));
        Assert.Equal((320, 200), (w, h));
        int colours = Enumerable.Range(0, w * h).Select(i => (pixels[4 * i] << 16) | (pixels[(4 * i) + 1] << 8) | pixels[(4 * i) + 2]).Distinct().Count();
        Assert.True(colours > 500, $"the picture has only {colours} colours");

        (code, _, err) = Billiards("simulate", "break.json", "--out", "result.json");
        Assert.True(code == 0, err);
        Assert.Contains("\"billiards-result/1\"", File.ReadAllText(Path.Combine(_dir, "result.json")), StringComparison.Ordinal);
    }

    [Fact]
    public void ShippedScenesAreFoundBesideTheExecutable()
    {
        Assert.Equal(Path.Combine(AppContext.BaseDirectory, "assets", "scenes", "eight-ball.json"), PlayCommand.FindDefaultScene());
        Assert.Equal(Path.Combine(AppContext.BaseDirectory, "assets", "scenes", "nine-ball.json"), PlayCommand.FindRulesScene(Core.Rules.GameRules.NineBall));
        foreach (string file in new[] { "fonts/DejaVuSans-Bold.ttf", "fonts/DejaVuSansMono.ttf", "models/pool-9ft.obj", "scripts/eight-ball-game.json", "icons/billiards.png", "linux/billiards.desktop" })
        {
            Assert.True(File.Exists(AssetFolder.File(file)));
        }
    }

    [Fact]
    public void AMissingAssetIsOneLineNamingItAsMissing()
    {
        string path = Path.Combine(_dir, "fonts", "DejaVuSans-Bold.ttf");
        var e = Assert.Throws<AssetException>(() => FontFile.Open(path));
        var (message, code) = CommandLine.Classify(e);
        Assert.Equal(CommandLine.Failure, code);
        Assert.Equal($"billiards: {path}: missing asset (the program's assets belong in the folder assets beside its executable)", message);
        Assert.Throws<AssetException>(() => AssetFolder.File("fonts/no-such-font.ttf"));
    }

    [Fact]
    public void AnUnreadableAssetIsOneLineNamingItAsUnreadable()
    {
        string path = Path.Combine(_dir, "DejaVuSans-Bold.ttf");
        File.WriteAllText(path, "not a font");
        var e = Assert.Throws<AssetException>(() => FontFile.Open(path));
        var (message, code) = CommandLine.Classify(e);
        Assert.Equal(CommandLine.Failure, code);
        Assert.Equal($"billiards: {path}: unreadable asset (not a TrueType font that SkiaSharp can read)", message);
    }
}
