using Billiards.App.Cli;

namespace Billiards.App.Tests.Rendering;

[Collection("GL")]
public class RenderCommandTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("billiards-render-").FullName;

    private string Scene(string json)
    {
        string path = Path.Combine(_folder, "scene.json");
        File.WriteAllText(path, json);
        return path;
    }

    private const string EightBall = """
        {
          "format": "billiards-scene/1",
          "table": { "preset": "pool-9ft" },
          "rack": { "game": "eight-ball", "seed": 1 },
          "balls": [ { "id": "cue", "position": [-0.635, 0.0] } ],
          "shot": { "speed": 5.0, "aim_deg": 0.0, "tip": [0.0, 0.2], "elevation_deg": 5.0 }
        }
        """;

    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = CommandLine.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    [Fact]
    public void Render_WritesAPngOfTheRequestedSize()
    {
        string scene = Scene(EightBall);
        string png = Path.Combine(_folder, "shot.png");
        var (code, _, err) = Run("render", scene, "--out", png, "--width", "320", "--height", "200");
        Assert.True(code == 0, err);
        var (w, h, pixels) = PngDecoder.Decode(File.ReadAllBytes(png));
        Assert.Equal((320, 200), (w, h));
        Assert.Contains(pixels.Where((_, i) => i % 4 == 1), g => g > 80);
        Assert.Empty(Directory.GetFiles(_folder, "*.tmp-*"));
    }

    [Fact]
    public void Render_draws_a_position_practice_saved()
    {
        // What practice's save key writes: the practice scene's balls with a shot, every field explicit.
        var practice = Billiards.Core.Scenes.SceneLoader.Load(Billiards.Core.Scenes.AssetFolder.Scene("practice.json"));
        string scene = Path.Combine(_folder, "saved.json");
        File.WriteAllBytes(scene, Billiards.Core.Scenes.SceneWriter.ToUtf8(practice with { Rack = null, Shot = new Billiards.Core.Cue.ShotSpec(2.5, 12.5, 0.1, -0.2, 4) }));
        string png = Path.Combine(_folder, "saved.png");
        var (code, _, err) = Run("render", scene, "--out", png, "--width", "160", "--height", "100");
        Assert.True(code == 0, err);
        var (w, h, pixels) = PngDecoder.Decode(File.ReadAllBytes(png));
        Assert.Equal((160, 100), (w, h));
        Assert.Contains(pixels.Where((_, i) => i % 4 == 1), g => g > 80);
    }

    [Fact]
    public void Render_AcceptsACamera()
    {
        string scene = Scene(EightBall);
        string png = Path.Combine(_folder, "top.png");
        var (code, _, err) = Run("render", scene, "--out", png, "--width", "64", "--height", "64", "--camera", "0,0,3,0,0,0,60");
        Assert.True(code == 0, err);
        var (_, _, pixels) = PngDecoder.Decode(File.ReadAllBytes(png));
        // Straight down on the centre of the bed: green.
        int centre = ((32 * 64) + 32) * 4;
        Assert.True(pixels[centre + 1] > pixels[centre] + 30, "the centre is not cloth");
    }

    [Theory]
    [InlineData("--width", "0")]
    [InlineData("--height", "100000")]
    [InlineData("--at", "-1")]
    [InlineData("--camera", "1,2,3")]
    [InlineData("--camera", "1,2,x,0,0,0")]
    [InlineData("--camera", "0,0,1,0,0,1")]
    public void Render_RejectsBadArgumentsWithOneLineAndNoFile(string option, string value)
    {
        string scene = Scene(EightBall);
        string png = Path.Combine(_folder, "bad.png");
        var (code, _, err) = Run("render", scene, "--out", png, option, value);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Single(err.TrimEnd('\n').Split('\n'));
        Assert.False(File.Exists(png));
    }

    [Fact]
    public void Render_RejectsABadSceneWithOneLineAndNoFile()
    {
        string scene = Scene("""{ "format": "billiards-scene/1", "table": { "preset": "pool-99ft" } }""");
        string png = Path.Combine(_folder, "bad.png");
        var (code, _, err) = Run("render", scene, "--out", png);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Single(err.TrimEnd('\n').Split('\n'));
        Assert.Contains("scene.json", err);
        Assert.False(File.Exists(png));
    }

    [Fact]
    public void Render_AtALaterTimeDrawsTheSimulationOrSaysItCannot()
    {
        // The physics models are written elsewhere: until they simulate, --at > 0 must fail cleanly.
        string scene = Scene(EightBall);
        string png = Path.Combine(_folder, "later.png");
        var (code, _, err) = Run("render", scene, "--out", png, "--at", "0.5", "--width", "64", "--height", "36");
        if (code == 0)
        {
            var (w, h, _) = PngDecoder.Decode(File.ReadAllBytes(png));
            Assert.Equal((64, 36), (w, h));
        }
        else
        {
            Assert.Single(err.TrimEnd('\n').Split('\n'));
            Assert.Contains("cannot simulate yet", err);
            Assert.False(File.Exists(png));
        }
    }

    [Fact]
    public void Render_RejectsAMissingOutputFolder()
    {
        string scene = Scene(EightBall);
        var (code, _, err) = Run("render", scene, "--out", Path.Combine(_folder, "no", "such", "x.png"));
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Contains("does not exist", err);
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);
}
