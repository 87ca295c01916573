using System.Diagnostics;
using System.Text.Json;
using Billiards.App.Cli;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Cli;

/// <summary>
/// The command-line cases of the hardening issue: each is one line on stderr, exit 2 for bad
/// input or 1 for the environment, no stack trace, nothing written (no temporary file left), and
/// every output path refused before any work.
/// </summary>
public sealed class HardeningCliTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-hardening-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static (int Code, string Out, string Err) Run(params string[] args) => CliRun.Run(args);

    private string Write(string name, string json)
    {
        string path = Path.Combine(_dir, name);
        Directory.CreateDirectory(Path.GetDirectoryName(path)!);
        File.WriteAllText(path, json);
        return path;
    }

    private static void AssertRefused(int expectedCode, (int Code, string Out, string Err) run, string expected)
    {
        Assert.Equal(expectedCode, run.Code);
        Assert.Equal("", run.Out);
        string[] lines = run.Err.TrimEnd('\n').Split('\n');
        Assert.Single(lines);
        Assert.DoesNotContain("   at ", run.Err);
        Assert.Contains(expected, run.Err, StringComparison.Ordinal);
    }

    // Only the files the test made itself: nothing half-written, no "*.tmp-*".
    private void AssertNothingWritten(params string[] expectedFiles)
    {
        var files = Directory.GetFileSystemEntries(_dir, "*", SearchOption.AllDirectories).Select(f => Path.GetRelativePath(_dir, f)).Order().ToArray();
        Assert.Equal(expectedFiles.Order().ToArray(), files);
    }

    private const string Frictionless = """
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
          "physics": { "params": { "mu_s": 0, "mu_r": 0 } },
          "rack": { "game": "eight-ball", "seed": 1 },
          "balls": [ { "id": "cue", "position": [-0.635, 0.0] } ],
          "shot": { "speed": 8.0, "aim_deg": 0.0 } }
        """;

    private const string Shot = """{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "speed": 1, "aim_deg": 0 } }""";

    [Theory]
    [InlineData("simulate")]
    [InlineData("render")]
    public void AnEmptyOutIsBadInput(string verb)
    {
        string scene = Write("a.json", Shot);
        AssertRefused(CommandLine.BadInput, Run(verb, scene, "--out", ""), "billiards: --out: the path is empty");
        AssertNothingWritten("a.json");
    }

    [Fact]
    public void AnEmptyReportOutIsBadInput()
    {
        AssertRefused(CommandLine.BadInput, Run("report", "accuracy", "--out", ""), "billiards: --out: the path is empty");
    }

    [Theory]
    [InlineData("simulate", "sub")]
    [InlineData("simulate", "sub/")]
    [InlineData("simulate", ".")]
    [InlineData("render", "sub")]
    [InlineData("render", "sub/")]
    [InlineData("render", ".")]
    public void AnOutNamingAFolderIsRefusedAndLeavesNoTemporaryFile(string verb, string output)
    {
        string scene = Write("a.json", Shot);
        Directory.CreateDirectory(Path.Combine(_dir, "sub"));
        string target = output == "." ? _dir + "/." : Path.Combine(_dir, output);
        AssertRefused(CommandLine.BadInput, Run(verb, scene, "--out", target), "names a folder; expected a file");
        AssertNothingWritten("a.json", "sub");
    }

    [Fact]
    public void AReportWhoseCsvNameIsAFolderWritesNothing()
    {
        string scenes = Path.Combine(_dir, "scenes");
        Write("scenes/one.json", Shot);
        Directory.CreateDirectory(Path.Combine(_dir, "out", "accuracy.csv"));
        var run = Run("report", "accuracy", "--scenes", scenes, "--out", Path.Combine(_dir, "out"));
        AssertRefused(CommandLine.BadInput, run, "accuracy.csv in it is a folder");
        AssertNothingWritten("scenes", Path.Combine("scenes", "one.json"), "out", Path.Combine("out", "accuracy.csv"));
    }

    [Fact]
    public void AReportWhoseOutIsAFileIsRefusedBeforeMeasuring()
    {
        string scenes = Path.Combine(_dir, "scenes");
        Write("scenes/one.json", Shot);
        string file = Write("taken", "x");
        // One line only: not a single progress line of a measurement came first.
        AssertRefused(CommandLine.BadInput, Run("report", "accuracy", "--scenes", scenes, "--out", file), "is a file; expected a folder");
    }

    [Fact]
    public void AReportSceneWithoutAShotIsOneLineBeforeMeasuring()
    {
        string scenes = Path.Combine(_dir, "scenes");
        Write("scenes/a.json", Shot);
        string noShot = Write("scenes/b.json", """{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ] }""");
        var run = Run("report", "accuracy", "--scenes", scenes, "--out", Path.Combine(_dir, "out"));
        AssertRefused(CommandLine.BadInput, run, $"{noShot}: $: the accuracy report measures a shot");
        Assert.False(Directory.Exists(Path.Combine(_dir, "out")));
    }

    [Theory]
    [InlineData("""{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, "x"] } ], "shot": { "speed": 1, "aim_deg": 0 } }""", "$.balls[0].position[1]: expected a number")]
    [InlineData("""{ "format": "billiards-scene/1", "physics": { "model": "thesis", "integrator": "exact" }, "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "speed": 1, "aim_deg": 0 } }""", "$.physics.integrator: unknown value \"exact\"")]
    public void ABadReportSceneLateInTheSuiteIsRefusedBeforeMeasuring(string json, string expected)
    {
        string scenes = Path.Combine(_dir, "scenes");
        Write("scenes/a.json", Shot);
        Write("scenes/z.json", json);
        AssertRefused(CommandLine.BadInput, Run("report", "accuracy", "--scenes", scenes, "--out", Path.Combine(_dir, "out")), expected);
    }

    [Fact]
    public void AFrictionlessTableWithUntilEndsAtUntilAndWithoutAtTheTimeBound()
    {
        string scene = Write("frictionless.json", Frictionless);
        var (code, stdout, _) = Run("simulate", scene, "--until", "3600");
        Assert.Equal(0, code);
        using (var result = JsonDocument.Parse(stdout))
        {
            Assert.Equal("until", result.RootElement.GetProperty("stats").GetProperty("stop").GetString());
            // The exact integrator stops at the first step boundary at or after the time.
            Assert.InRange(result.RootElement.GetProperty("t_end").GetDouble(), 3600 - 1e-6, 3600 + 1.0 / 250 + 1e-6);
        }
        (code, stdout, _) = Run("simulate", scene, "--integrator", "event");
        Assert.Equal(0, code);
        using (var result = JsonDocument.Parse(stdout))
        {
            Assert.Equal("max-time", result.RootElement.GetProperty("stats").GetProperty("stop").GetString());
            Assert.False(result.RootElement.GetProperty("stats").GetProperty("at_rest").GetBoolean());
        }
    }

    [Fact]
    public void AnUntilBeyondTheCapIsRefusedWithTheCap()
    {
        string scene = Write("frictionless.json", Frictionless);
        AssertRefused(CommandLine.BadInput, Run("simulate", scene, "--until", "1e308"), "--until 1E+308: expected a time from 0 to 3600 s");
        AssertRefused(CommandLine.BadInput, Run("render", scene, "--at", "1e308", "--out", Path.Combine(_dir, "x.png")), "--at 1E+308: expected a time from 0 to 3600 s");
        AssertNothingWritten("frictionless.json");
    }

    [Fact]
    public void TheEventBoundStopsARunAndSaysSo()
    {
        var scene = SceneLoader.Parse(Frictionless, "frictionless.json");
        var outcome = SimulationRunner.Run(scene, new RunOptions(Until: 3600, MaxEvents: 50));
        Assert.Equal(StopReason.MaxEvents, outcome.Stop);
        Assert.True(outcome.Simulation.Events.Count >= 50);
        Assert.True(outcome.Simulation.Time < 3600);
        var wall = SimulationRunner.Run(scene, new RunOptions(Until: 3600, MaxWallSeconds: 0));
        Assert.Equal(StopReason.WallClock, wall.Stop);
        Assert.Contains("\"stop\": \"wall-clock\"", System.Text.Encoding.UTF8.GetString(ResultWriter.ToUtf8(wall)), StringComparison.Ordinal);
    }

    [Fact]
    public void AFolderThatCannotBeWrittenIsAnEnvironmentProblem()
    {
        if (!OperatingSystem.IsLinux())
        {
            return;
        }
        string scene = Write("a.json", Shot);
        // /sys refuses new files even to root, as a read-only disk does.
        AssertRefused(CommandLine.Failure, Run("simulate", scene, "--out", "/sys/result.json"), "billiards: --out /sys/result.json: cannot write in /sys");
    }

    [Fact]
    public void AnUnexpectedExceptionIsOneLineWithExitCode1()
    {
        var (message, code) = CommandLine.Classify(new NullReferenceException("boom\nsecond line"));
        Assert.Equal(CommandLine.Failure, code);
        Assert.Equal("billiards: internal error (NullReferenceException): boom second line", CommandLine.OneLine(message));
    }

    [Fact]
    public void AFailedWriteLeavesNeitherTheTargetNorATemporaryFile()
    {
        string good = Path.Combine(_dir, "good.txt");
        string bad = Path.Combine(_dir, "missing", "bad.txt");
        Assert.ThrowsAny<IOException>(() => OutputFiles.WriteAll([(good, [1, 2, 3]), (bad, [4])]));
        AssertNothingWritten();
    }

    [Fact]
    public void PlayWithoutADisplayIsOneLineAndExitCode1()
    {
        if (!OperatingSystem.IsLinux())
        {
            return;
        }
        // A real process, so that GLFW starts without a display (the test process may have one).
        string app = Path.Combine(AppContext.BaseDirectory, "billiards.dll");
        var start = new ProcessStartInfo("dotnet") { RedirectStandardError = true, RedirectStandardOutput = true, UseShellExecute = false };
        start.ArgumentList.Add(app);
        start.ArgumentList.Add("play");
        start.ArgumentList.Add(AssetFolder.Scene("stun.json"));
        start.Environment.Remove("DISPLAY");
        start.Environment.Remove("WAYLAND_DISPLAY");
        using var process = Process.Start(start)!;
        string stdout = process.StandardOutput.ReadToEnd();
        string stderr = process.StandardError.ReadToEnd();
        process.WaitForExit();
        AssertRefused(CommandLine.Failure, (process.ExitCode, stdout, stderr), "billiards: play: no display");
    }
}
