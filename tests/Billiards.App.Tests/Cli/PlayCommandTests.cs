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

    private static List<Billiards.App.Rendering.HudInfo> Run(TempSettings settings, Func<Billiards.Core.Scenes.Scene, Billiards.Core.Physics.Simulation> create, params string[] clicks) =>
        Run(settings, create, _ => { }, clicks);

    private static List<Billiards.App.Rendering.HudInfo> Run(TempSettings settings, Func<Billiards.Core.Scenes.Scene, Billiards.Core.Physics.Simulation> create, Action<GraphicsQuality> graphics, params string[] clicks)
    {
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var renderer = new RecordingRenderer();
        var loop = new ClickingLoop(clock, window, renderer, clicks);
        Assert.Equal(0, PlayCommand.Play(null, _ => new GamePlatform(window, loop, renderer) { SetGraphics = graphics }, create, clock, new PlayCommand.PlayOptions(null, null) { StartMenu = true, SettingsPath = settings.Path }));
        return [.. renderer.Frames.Select(f => f.Hud!)];
    }

    [Fact]
    public void TheGraphicsAreChosenInTheSettingsAppliedToTheRendererAtOnceAndRemembered()
    {
        using var settings = new TempSettings();
        var applied = new List<GraphicsQuality>();
        // Automatic at first; a click makes it always sharp, a second fast; Back applies and saves it.
        var first = Run(settings, TestScenes.Create, applied.Add, "Settings", "Graphics", "Graphics", "Back");
        Assert.Contains(first[1].Buttons!, b => b.Label == "Graphics: automatic");
        Assert.Contains(first[2].Buttons!, b => b.Label == "Graphics: always sharp");
        Assert.Contains(first[3].Buttons!, b => b.Label.StartsWith("Graphics: fast", StringComparison.Ordinal));
        Assert.Equal([GraphicsQuality.Auto, GraphicsQuality.Fast], applied);
        Assert.Contains("\"graphics\": \"fast\"", File.ReadAllText(settings.Path), StringComparison.Ordinal);
        Assert.Equal(GameSettings.Default with { Graphics = GraphicsQuality.Fast }, GameSettings.Load(settings.Path));
        // The next run starts with it on the renderer and on the screen.
        applied.Clear();
        var second = Run(settings, TestScenes.Create, applied.Add, "Settings");
        Assert.Equal(GraphicsQuality.Fast, applied[0]);
        Assert.Contains(second[1].Buttons!, b => b.Label.StartsWith("Graphics: fast", StringComparison.Ordinal));
        Assert.True(GraphicsWords.ReducesWhileMoving(GraphicsQuality.Fast, softwareRenderer: false));
        Assert.False(GraphicsWords.ReducesWhileMoving(GraphicsQuality.Sharp, softwareRenderer: true));
        Assert.Equal(GraphicsWords.ReducesWhileMoving(GraphicsQuality.Auto, softwareRenderer: true), !GraphicsWords.ReducesWhileMoving(GraphicsQuality.Auto, softwareRenderer: false));
    }

    private static bool Chosen(Billiards.App.Rendering.HudInfo hud, string label) => hud.Buttons!.Any(b => b.Label == label && b.Chosen);

    [Fact]
    public void PlainPlayOpensTheStartMenuAndItsChoiceStartsThatGameAndIsRemembered()
    {
        using var settings = new TempSettings();
        var hud = Run(settings, TestScenes.Create, "Play", "9-ball", "Person", "Start");
        var first = hud[0];
        // A title and screens, and nothing of the game behind: no scoreboard, no keys, no "PAUSED".
        Assert.Contains(first.Labels!, l => l.Text == "Billiards");
        Assert.Equal(["Play", "Play online", "Practice", "Drills", "Settings", "Controls", "Quit"], first.Buttons!.Select(b => b.Label));
        Assert.Null(first.Board);
        Assert.Empty(first.Lines);
        Assert.True(first.Backdrop);
        // The Play screen: the game and the opponent under their headings, the last choice marked.
        var play = hud[1];
        Assert.Contains(play.Labels!, l => l.Text == "Game");
        Assert.Contains(play.Labels!, l => l.Text.StartsWith("Opponent", StringComparison.Ordinal));
        Assert.True(Chosen(play, "8-ball") && Chosen(play, "Computer 3"));
        var last = hud[^1];
        Assert.Null(last.Buttons);
        Assert.StartsWith("9-ball", last.Board!.Title, StringComparison.Ordinal);
        Assert.Equal("Player 2", last.Board.Players[1].Name);
        // The next run offers the same game and opponent.
        var next = Run(settings, TestScenes.Create, "Play");
        Assert.True(Chosen(next[^1], "9-ball") && Chosen(next[^1], "Person"), string.Join(", ", next[^1].Buttons!.Where(b => b.Chosen).Select(b => b.Label)));
    }

    [Fact]
    public void NoButtonMovesWhenAChoiceChanges()
    {
        using var settings = new TempSettings();
        var hud = Run(settings, TestScenes.Create, "Play", "Snooker", "Computer 5", "Person");
        var before = hud[1].Buttons!.Select(b => (b.X, b.Y, b.Width, b.Height)).ToList();
        for (int i = 2; i < 5; i++)
        {
            Assert.Equal(before, hud[i].Buttons!.Select(b => (b.X, b.Y, b.Width, b.Height)));
        }
        Assert.True(Chosen(hud[4], "Snooker") && Chosen(hud[4], "Person") && !Chosen(hud[4], "Computer 5"));
    }

    [Theory]
    [InlineData(new[] { "Drills", "Stop shot" }, "Drill: Stop shot")]
    [InlineData(new[] { "Practice" }, "Practice")]
    public void TheStartMenuStartsPracticeOrADrill(string[] clicks, string title)
    {
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var renderer = new RecordingRenderer();
        var loop = new ClickingLoop(clock, window, renderer, clicks);
        using var settings = new TempSettings();
        string data = Path.Combine(Path.GetTempPath(), $"data-{Guid.NewGuid():N}");
        int code = PlayCommand.Play(null, _ => new GamePlatform(window, loop, renderer), TestScenes.Create, clock, new PlayCommand.PlayOptions(null, null) { StartMenu = true, SettingsPath = settings.Path, DataFolder = data });
        Assert.Equal(0, code);
        if (clicks[0] == "Drills")
        {
            // The gallery: every drill a card with its picture and goal.
            var gallery = renderer.Frames[1].Hud!.Buttons!.Where(b => b.Picture is not null).ToList();
            Assert.Equal(Billiards.App.Practice.DrillLibrary.Names().Count, gallery.Count);
            Assert.All(gallery, b => Assert.False(string.IsNullOrEmpty(b.Note)));
        }
        var last = renderer.Frames[^1].Hud!;
        // Practice and drills have the match's scoreboard style, not the developer lines.
        Assert.StartsWith(title, last.Board!.Title, StringComparison.Ordinal);
        Assert.False(last.Developer);
        Assert.False(Directory.Exists(data), "nothing is written before an attempt ends");
    }

    [Fact]
    public void ThePhysicsChoiceInWordsMakesTheGameAndIsRememberedAfterARestart()
    {
        using var settings = new TempSettings();
        var scenes = new List<Billiards.Core.Scenes.Scene>();
        Billiards.Core.Physics.Simulation Create(Billiards.Core.Scenes.Scene scene)
        {
            scenes.Add(scene);
            return TestScenes.Create(scene);
        }

        var firstRun = Run(settings, Create, "Settings", "Cushion", "Cushion", "Cloth", "Back", "Play", "Start");
        Assert.Contains(firstRun[1].Buttons!, b => b.Label == "Cushion: standard (Han 2005)");
        Assert.Contains(firstRun[1].Buttons!, b => b.Label == "Cloth: standard");
        // The same game and opponent with other physics is a new game, made with them.
        var played = scenes[^1].Physics;
        Assert.Equal("stronge-compliant", played.Models.BallCushion.Name);
        Assert.Equal((0.15, 0.005), (played.Params.MuS, played.Params.MuR));
        Assert.Contains("stronge-compliant", File.ReadAllText(settings.Path), StringComparison.Ordinal);

        // The next run starts with them, in words on the Settings screen, and its first game is made with them.
        scenes.Clear();
        var secondRun = Run(settings, Create, "Settings");
        Assert.Contains(secondRun[1].Buttons!, b => b.Label == "Cushion: soft rubber (Stronge, compliant)");
        Assert.Contains(secondRun[1].Buttons!, b => b.Label == "Cloth: fast (tournament cloth)");
        Assert.Equal("stronge-compliant", scenes[0].Physics.Models.BallCushion.Name);
    }

    [Fact]
    public void TheComputersPaceIsChosenInTheSettingsKeepsTheGameAndIsRemembered()
    {
        using var settings = new TempSettings();
        int games = 0;
        Billiards.Core.Physics.Simulation Create(Billiards.Core.Scenes.Scene scene)
        {
            games++;
            return TestScenes.Create(scene);
        }

        Run(settings, Create);
        int oneGame = games; // the simulations one game makes
        games = 0;
        var first = Run(settings, Create, "Settings", "Computer's pace", "Back", "Play", "Start");
        Assert.Contains(first[1].Buttons!, b => b.Label == "Computer's pace: watchable");
        Assert.Equal(oneGame, games); // the pace alone made no new game
        Assert.Contains("\"computer_pace\": \"fast\"", File.ReadAllText(settings.Path), StringComparison.Ordinal);
        var second = Run(settings, Create, "Settings");
        Assert.Contains(second[1].Buttons!, b => b.Label == "Computer's pace: fast");
        Assert.Equal(GameSettings.Default with { FastComputer = true }, GameSettings.Load(settings.Path));
    }

    // A settings file of the test's own, never the user's.
    internal sealed class TempSettings : IDisposable
    {
        private readonly string _dir = Directory.CreateTempSubdirectory("billiards-settings-").FullName;

        public string Path => System.IO.Path.Combine(_dir, "billiards", "settings.json");

        public void Dispose() => Directory.Delete(_dir, recursive: true);
    }
}
