using System.Security.Cryptography;
using Billiards.App.Audio;
using Billiards.App.Cli;
using Billiards.App.Tests.Audio;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Xunit.Abstractions;

namespace Billiards.App.Tests.Cli;

public sealed class RenderAudioCommandTests(ITestOutputHelper output) : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-audio-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static (int Code, string Err) Run(params string[] args)
    {
        var stderr = new StringWriter();
        int code = CommandLine.Run(args, new StringWriter(), stderr);
        return (code, stderr.ToString());
    }

    private string Render(string scene, string name, params string[] extra)
    {
        string path = Path.Combine(_dir, name);
        var (code, err) = Run(["render-audio", scene, "--out", path, .. extra]);
        Assert.True(code == 0, err);
        return path;
    }

    private static string Break => AssetFolder.Scene("eight-ball-break.json");

    [Fact]
    public void TheBreakWritesA48KhzWavWhoseOnsetsMatchEveryAudibleSeparateEventWithin2Ms()
    {
        var wav = WavAnalysis.Read(Render(Break, "break.wav"));
        Assert.Equal(48000, wav.Rate);
        Assert.Equal(16, wav.BitsPerSample);
        Assert.Equal(2, wav.Channels);

        // The events as `simulate` reports them, independently of the audio path.
        var outcome = SimulationRunner.Run(SceneLoader.Load(Break), new RunOptions(null, null));
        var events = outcome.Simulation.Events;
        int checkedEvents = 0;
        double worst = 0;
        for (int i = 0; i < events.Count; i++)
        {
            var e = events[i];
            if (e.Speed <= 0.05 || (i > 0 && e.Time - events[i - 1].Time < 0.010))
            {
                continue;
            }
            double? onset = wav.Onset(e.Time);
            Assert.True(onset.HasValue, $"no onset near event {i} ({e.Kind} at {e.Time:F4} s, {e.Speed:F3} m/s)");
            double error = onset!.Value - e.Time;
            Assert.True(Math.Abs(error) <= 0.002, $"event {i} ({e.Kind} at {e.Time:F4} s): onset {error * 1000:F2} ms off");
            worst = Math.Max(worst, Math.Abs(error));
            checkedEvents++;
        }
        output.WriteLine($"{checkedEvents} of {events.Count} events checked; worst onset error {worst * 1000:F3} ms");
        // The break has dozens of such events; a render that found few would prove little.
        Assert.True(checkedEvents >= 15, $"only {checkedEvents} events checked");
        // Sound lasts past the last event (the last drop's roll along the return), and not absurdly long.
        Assert.InRange(wav.Mono.Length / (double)wav.Rate, events[^1].Time, events[^1].Time + 60);
    }

    [Fact]
    public void TheSameSceneGivesTheSameBytes()
    {
        byte[] first = File.ReadAllBytes(Render(Break, "a.wav"));
        byte[] second = File.ReadAllBytes(Render(Break, "b.wav"));
        Assert.Equal(SHA256.HashData(first), SHA256.HashData(second));
        Assert.True(first.Length > 48000 * 4, "the render is shorter than a second");
    }

    [Fact]
    public void AFullPowerBreakClipsNoSampleThoughItsRawMixWouldClip()
    {
        string scene = Path.Combine(_dir, "full-power.json");
        File.WriteAllText(scene, $$"""
            {
              "format": "billiards-scene/1",
              "table": { "preset": "pool-9ft" },
              "rack": { "game": "eight-ball", "seed": 1 },
              "balls": [ { "id": "cue", "position": [-0.635, 0.0] } ],
              "shot": { "speed": {{SceneLoader.MaxShotSpeed}}, "aim_deg": 0.0, "tip": [0.0, 0.0], "elevation_deg": 0.0 }
            }
            """);
        var wav = WavAnalysis.Read(Render(scene, "full.wav"));
        int clipped = wav.Samples.Count(s => s is short.MaxValue or <= -short.MaxValue);
        Assert.Equal(0, clipped);
        // The limiter's ceiling (-1 dBFS) holds on every sample.
        Assert.True(wav.Samples.Max(s => Math.Abs((int)s)) <= 0.89 * 32767 + 1);

        // Without the limiter the same break goes past full scale: the test above is not vacuous.
        float[] raw = ShotAudio.Render(SceneLoader.Load(scene), 48000, limit: false);
        output.WriteLine($"raw peak {raw.Max(Math.Abs):F3}, limited peak {wav.Samples.Max(s => Math.Abs((int)s)) / 32767.0:F3}");
        Assert.True(raw.Max(Math.Abs) > 1, "the raw mix never reaches full scale; choose a harder scene");
    }

    [Fact]
    public void TheRateOptionIsHonoured()
    {
        var wav = WavAnalysis.Read(Render(Break, "break-22.wav", "--rate", "22050"));
        Assert.Equal(22050, wav.Rate);
    }

    [Theory]
    [InlineData("--rate", "0")]
    [InlineData("--rate", "fast")]
    [InlineData("--rate", "1000000")]
    public void ABadRateIsOneLineAndWritesNothing(string option, string value)
    {
        string path = Path.Combine(_dir, "x.wav");
        var (code, err) = Run("render-audio", Break, "--out", path, option, value);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Single(err.TrimEnd('\n').Split('\n'));
        Assert.Empty(Directory.GetFiles(_dir));
    }

    [Fact]
    public void ABadSceneIsOneLineNamingTheFileAndWritesNothing()
    {
        string scene = Path.Combine(_dir, "bad.json");
        File.WriteAllText(scene, """{ "format": "billiards-scene/1", "shot": { "speed": "hard" } }""");
        string path = Path.Combine(_dir, "x.wav");
        var (code, err) = Run("render-audio", scene, "--out", path);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Single(err.TrimEnd('\n').Split('\n'));
        Assert.StartsWith(scene, err);
        Assert.False(File.Exists(path));
    }

    [Fact]
    public void AnOutputThatIsNotWavIsRefused()
    {
        var (code, err) = Run("render-audio", Break, "--out", Path.Combine(_dir, "x.mp3"));
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Contains("expected a .wav file", err);
    }
}
