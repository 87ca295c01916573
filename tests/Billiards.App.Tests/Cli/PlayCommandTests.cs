using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Tests.Game;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Cli;

public class PlayCommandTests
{
    [Fact]
    public void PlayRunsTheSceneInThePlatformUntilItsLoopEnds()
    {
        string path = Path.Combine(Path.GetTempPath(), $"play-{Guid.NewGuid():N}.json");
        File.WriteAllText(path, """
            { "format": "billiards-scene/1", "name": "two balls", "table": { "preset": "pool-8ft" },
              "balls": [ { "id": "cue", "position": [-0.5, 0.0] }, { "id": "1", "position": [0.5, 0.0] } ] }
            """);
        try
        {
            var clock = new ManualClock();
            var window = new FakeWindow();
            var loop = new FakeFrameLoop(clock, 3, 1.0 / 60);
            var renderer = new RecordingRenderer();
            string? title = null;
            int code = PlayCommand.Play(path, t =>
            {
                title = t;
                return new GamePlatform(window, loop, renderer);
            }, TestScenes.Create, clock);
            Assert.Equal(0, code);
            Assert.Equal("Billiards: two balls", title);
            Assert.Equal(3, renderer.Frames.Count);
            Assert.All(renderer.Frames, f => Assert.Equal("pool-8ft", f.Table.Preset));
            Assert.NotNull(renderer.Frames[^1].Hud);
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public void ABadSceneIsOneLineAndANonZeroExitBeforeAnyWindow()
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = CommandLine.Run(["play", "/nonexistent/scene.json"], stdout, stderr);
        Assert.Equal(CommandLine.BadInput, code);
        string error = stderr.ToString();
        Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries));
        Assert.Contains("/nonexistent/scene.json", error, StringComparison.Ordinal);
        Assert.Empty(stdout.ToString());

        Assert.Throws<SceneException>(() => PlayCommand.Play("/nonexistent/scene.json", _ => throw new InvalidOperationException("no window may open")));
    }

    [Fact]
    public void PlayTakesAtMostOneScene()
    {
        var stderr = new StringWriter();
        Assert.Equal(CommandLine.BadInput, CommandLine.Run(["play", "a.json", "b.json"], new StringWriter(), stderr));
        Assert.Single(stderr.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries));
    }

    [Fact]
    public void TheDefaultSceneIsEightBall()
    {
        Assert.EndsWith(Path.Combine("assets", "scenes", "eight-ball.json"), PlayCommand.FindDefaultScene(), StringComparison.Ordinal);
    }
}

public class FrameCapOptionTests
{
    [Theory]
    [InlineData(-1)]
    [InlineData(1001)]
    [InlineData(double.NaN)]
    public void ACapOutOfRangeIsRefusedInOneLine(double value)
    {
        var e = Assert.Throws<CliException>(() => PlayCommand.FrameCap(value));
        Assert.StartsWith("--fps-cap ", e.Message, StringComparison.Ordinal);
        Assert.Contains("expected 0 (no cap) to 1000", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void NoCapZeroAndARatePass()
    {
        Assert.Null(PlayCommand.FrameCap(null));
        Assert.Equal(0, PlayCommand.FrameCap(0));
        Assert.Equal(144, PlayCommand.FrameCap(144));
    }
}

public class StartMenuTests
{
    private sealed class ClickingLoop(ManualClock clock, FakeWindow window, RecordingRenderer renderer, string[] clicks) : IFrameLoop
    {
        public void Run(Action frame)
        {
            frame();
            foreach (string label in clicks)
            {
                var button = renderer.Frames[^1].Hud!.Buttons!.First(b => b.Label.Contains(label, StringComparison.Ordinal));
                window.MoveTo(button.X + (button.Width / 2), button.Y + (button.Height / 2));
                window.Down();
                window.Up();
                clock.Advance(1.0 / 60);
                frame();
            }
            for (int i = 0; i < 3; i++)
            {
                clock.Advance(1.0 / 60);
                frame();
            }
        }
    }

    [Fact]
    public void PlainPlayOpensTheStartMenuAndItsChoiceStartsThatGame()
    {
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var renderer = new RecordingRenderer();
        var loop = new ClickingLoop(clock, window, renderer, ["nine-ball", "person", "Start"]);
        using var settings = new TempSettings();
        int code = PlayCommand.Play(null, _ => new GamePlatform(window, loop, renderer), TestScenes.Create, clock, new PlayCommand.PlayOptions(null, null) { StartMenu = true, SettingsPath = settings.Path });
        Assert.Equal(0, code);
        var first = renderer.Frames[0].Hud!;
        Assert.Contains(first.Buttons!, b => b.Label == "> eight-ball <");
        Assert.Contains(first.Buttons!, b => b.Label == "> level 3 <");
        Assert.Contains(first.Lines, l => l.StartsWith("eight-ball", StringComparison.Ordinal));
        var last = renderer.Frames[^1].Hud!;
        Assert.Null(last.Buttons);
        Assert.Contains(last.Lines, l => l.StartsWith("nine-ball", StringComparison.Ordinal));
        Assert.Contains(last.Lines, l => l.Contains("Player 2: on the 1", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData("Stop shot", "Drill: Stop shot")]
    [InlineData("Practice (no referee)", "Practice: M then drag any ball")]
    public void TheStartMenuStartsPracticeOrADrill(string click, string line)
    {
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var renderer = new RecordingRenderer();
        var loop = new ClickingLoop(clock, window, renderer, [click]);
        using var settings = new TempSettings();
        string data = Path.Combine(Path.GetTempPath(), $"data-{Guid.NewGuid():N}");
        int code = PlayCommand.Play(null, _ => new GamePlatform(window, loop, renderer), TestScenes.Create, clock, new PlayCommand.PlayOptions(null, null) { StartMenu = true, SettingsPath = settings.Path, DataFolder = data });
        Assert.Equal(0, code);
        var last = renderer.Frames[^1].Hud!;
        Assert.Null(last.Board); // no match: no scoreboard
        Assert.Contains(last.Lines, l => l.StartsWith(line, StringComparison.Ordinal));
        Assert.False(Directory.Exists(data), "nothing is written before an attempt ends");
    }

    [Fact]
    public void ThePhysicsChoiceMakesTheGameAndIsRememberedAfterARestart()
    {
        using var settings = new TempSettings();
        var scenes = new List<Billiards.Core.Scenes.Scene>();
        Billiards.Core.Physics.Simulation Create(Billiards.Core.Scenes.Scene scene)
        {
            scenes.Add(scene);
            return TestScenes.Create(scene);
        }
        List<Billiards.App.Rendering.HudInfo> Run(params string[] clicks)
        {
            var clock = new ManualClock();
            var window = new FakeWindow { FramebufferSize = (1280, 720) };
            var renderer = new RecordingRenderer();
            var loop = new ClickingLoop(clock, window, renderer, clicks);
            Assert.Equal(0, PlayCommand.Play(null, _ => new GamePlatform(window, loop, renderer), Create, clock, new PlayCommand.PlayOptions(null, null) { StartMenu = true, SettingsPath = settings.Path }));
            return [.. renderer.Frames.Select(f => f.Hud!)];
        }

        var firstRun = Run("Physics: stronge-compliant", "fast cloth", "Start");
        Assert.Contains(firstRun[0].Buttons!, b => b.Label == "> Physics: han-2005 <");
        Assert.Contains(firstRun[0].Buttons!, b => b.Label == "> standard cloth <");
        // The same game and opponent with other physics is a new game, made with them.
        var played = scenes[^1].Physics;
        Assert.Equal("stronge-compliant", played.Models.BallCushion.Name);
        Assert.Equal((0.15, 0.005), (played.Params.MuS, played.Params.MuR));
        Assert.Contains("stronge-compliant", File.ReadAllText(settings.Path), StringComparison.Ordinal);

        // The next run starts with them, marked in the menu, and its first game is made with them.
        scenes.Clear();
        var secondRun = Run();
        Assert.Contains(secondRun[0].Buttons!, b => b.Label == "> Physics: stronge-compliant <");
        Assert.Contains(secondRun[0].Buttons!, b => b.Label == "> fast cloth <");
        Assert.Equal("stronge-compliant", scenes[0].Physics.Models.BallCushion.Name);
    }

    [Fact]
    public void TheComputersPaceIsChosenInTheStartMenuKeepsTheGameAndIsRemembered()
    {
        using var settings = new TempSettings();
        int games = 0;
        List<Billiards.App.Rendering.HudInfo> Run(params string[] clicks)
        {
            var clock = new ManualClock();
            var window = new FakeWindow { FramebufferSize = (1280, 720) };
            var renderer = new RecordingRenderer();
            var loop = new ClickingLoop(clock, window, renderer, clicks);
            Billiards.Core.Physics.Simulation Create(Billiards.Core.Scenes.Scene scene)
            {
                games++;
                return TestScenes.Create(scene);
            }
            Assert.Equal(0, PlayCommand.Play(null, _ => new GamePlatform(window, loop, renderer), Create, clock, new PlayCommand.PlayOptions(null, null) { StartMenu = true, SettingsPath = settings.Path }));
            return [.. renderer.Frames.Select(f => f.Hud!)];
        }

        Run();
        int oneGame = games; // the simulations one game makes
        games = 0;
        var first = Run("computer: watchable", "Start");
        Assert.Contains(first[0].Buttons!, b => b.Label == "computer: watchable");
        Assert.Equal(oneGame, games); // the pace alone made no new game
        Assert.Contains("\"computer_pace\": \"fast\"", File.ReadAllText(settings.Path), StringComparison.Ordinal);
        var second = Run();
        Assert.Contains(second[0].Buttons!, b => b.Label == "computer: fast");
        Assert.Equal(GameSettings.Default with { FastComputer = true }, GameSettings.Load(settings.Path));
    }

    // A settings file of the test's own, never the user's.
    private sealed class TempSettings : IDisposable
    {
        private readonly string _dir = Directory.CreateTempSubdirectory("billiards-settings-").FullName;

        public string Path => System.IO.Path.Combine(_dir, "billiards", "settings.json");

        public void Dispose() => Directory.Delete(_dir, recursive: true);
    }
}
