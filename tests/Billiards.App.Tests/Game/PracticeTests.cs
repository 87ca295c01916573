using System.Numerics;
using System.Text.Json;
using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.App.Practice;
using Billiards.App.Rendering;
using Billiards.App.Tests.Cli;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Practice;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// Practice and drills from input scripts (assets/scripts), headless on a fake window with the real
/// physics: a drill attempted and counted in the results file, a saved position that <c>simulate</c>
/// plays to the window's result bit for bit; and practice's tools one by one.
/// </summary>
public sealed class PracticeTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), $"practice-{Guid.NewGuid():N}");

    public void Dispose()
    {
        if (Directory.Exists(_folder))
        {
            Directory.Delete(_folder, recursive: true);
        }
    }

    private static string Script(string name) => Path.Combine(AssetFolder.Assets, "scripts", name);

    private static int PlayHeadless(PlayCommand.PlayOptions options)
    {
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        int code = PlayCommand.Play(null, _ => new GamePlatform(window, new UntilClosedLoop(clock, window, 1.0 / 60), new NullFrameRenderer()), SimulationFactory.Create, clock, options);
        Assert.True(window.Closed, "the script never ended");
        return code;
    }

    [Fact]
    public void AScriptedDrillIsAttemptedTwiceAndBothAttemptsAreCountedInTheResultsFile()
    {
        PracticeNode? practice = null;
        var outcomes = new List<DrillOutcome>();
        int code = PlayHeadless(new PlayCommand.PlayOptions(Script("drill-attempts.json"), null)
        {
            Drill = "straight-in",
            DataFolder = _folder,
            Started = host =>
            {
                practice = host.Tree.Root.GetInTree<PracticeNode>();
                practice.AttemptEnded += outcomes.Add;
            },
        });
        Assert.Equal(0, code);
        // The first shot, straight at the 1, pots it; the second, turned 8 degrees off, misses.
        Assert.Equal(2, outcomes.Count);
        Assert.True(outcomes[0].Success, outcomes[0].Reason);
        Assert.False(outcomes[1].Success);
        Assert.Equal(new DrillRecord(2, 1, 1, null), practice!.Record);

        string results = Path.Combine(_folder, DrillRecords.FileName);
        using var doc = JsonDocument.Parse(File.ReadAllText(results));
        Assert.Equal(DrillRecords.Format, doc.RootElement.GetProperty("format").GetString());
        var drill = doc.RootElement.GetProperty("drills").GetProperty("straight-in");
        Assert.Equal(2, drill.GetProperty("attempts").GetInt32());
        Assert.Equal(1, drill.GetProperty("successes").GetInt32());
        Assert.Equal(1, drill.GetProperty("best_potted").GetInt32());
        // Nothing but the file itself: written atomically, no temporary file left.
        Assert.Equal([results], Directory.GetFiles(_folder));

        // Kept between runs: the next run starts from the stored counts.
        PlayHeadless(new PlayCommand.PlayOptions(Script("drill-attempts.json"), null) { Drill = "straight-in", DataFolder = _folder, Started = h => practice = h.Tree.Root.GetInTree<PracticeNode>() });
        Assert.Equal(new DrillRecord(4, 2, 1, null), practice!.Record);
        Assert.Equal(new DrillRecord(4, 2, 1, null), DrillRecords.Load(results)["straight-in"]);
    }

    [Fact]
    public void ASavedPracticePositionLoadsIntoSimulateAndPlaysTheWindowSShotBitForBit()
    {
        Directory.CreateDirectory(_folder);
        string saved = Path.Combine(_folder, "position.json");
        PracticeNode? practice = null;
        PhysicsNode? physics = null;
        var rests = new List<BallState[]>();
        var shots = new List<ShotSpec>();
        int code = PlayHeadless(new PlayCommand.PlayOptions(Script("practice-save.json"), null)
        {
            Practice = true,
            DataFolder = _folder,
            SavePath = saved,
            Started = host =>
            {
                practice = host.Tree.Root.GetInTree<PracticeNode>();
                physics = host.World.Physics;
                physics.Struck += shots.Add;
                physics.CameToRest += _ => rests.Add(physics.Simulation.Balls.ToArray());
            },
        });
        Assert.Equal(0, code);
        Assert.Equal(2, shots.Count);
        Assert.Equal(2, rests.Count);
        // The script set the aim, the power, the spin and the elevation; the retry played that shot again exactly.
        var shot = shots[0];
        Assert.Equal(shot, shots[1]);
        Assert.Equal(3.5, shot.Speed);
        Assert.NotEqual(0, shot.TipHeight);
        Assert.NotEqual(0, shot.TipSide);
        Assert.True(shot.ElevationDeg > 0);
        Assert.Equal(rests[0], rests[1]);

        // The file is a scene simulate reads; its shot is the window's to the bit, and so is its result.
        var scene = SceneLoader.Load(saved);
        Assert.Equal(shot, scene.Shot);
        var (exit, output, error) = CliRun.Run("simulate", saved);
        Assert.True(exit == 0, error);
        using var result = JsonDocument.Parse(output);
        var ids = physics!.Simulation.Ids;
        var balls = result.RootElement.GetProperty("balls").EnumerateArray().ToList();
        Assert.Equal(ids.Count, balls.Count);
        for (int i = 0; i < ids.Count; i++)
        {
            var ball = balls.Single(b => b.GetProperty("id").GetString() == ids[i].ToString());
            var p = ball.GetProperty("position").EnumerateArray().Select(x => x.GetDouble()).ToArray();
            Assert.Equal(rests[1][i].Position, new Vec3(p[0], p[1], p[2]));
            Assert.Equal(rests[1][i].State.ToName(), ball.GetProperty("state").GetString());
        }

        // F9 loaded the saved position back: its balls, and the cue set to its shot.
        var table = practice!.Position();
        Assert.Equal(scene.Balls.Select(b => (b.Id, b.Position)), table.Balls.Select(b => (b.Id, b.Position)));
        Assert.Equal(shot, practice.CurrentShot());
    }

    private static Scene PracticeScene() => SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "practice.json"));

    private TestGame Practice(Scene? scene = null, Drill? drill = null) =>
        new(scene ?? PracticeScene(), practice: new PracticeSetup(Path.Combine(_folder, "p.json"), drill), create: SimulationFactory.Create);

    private static Vector2 PixelOf(RenderFrame frame, Vec3 p) => RenderMath.ToPixel(RenderMath.ViewProjection(frame), p.ToVector3(), frame.Width, frame.Height)!.Value;

    private static Vec3 Ball(TestGame game, int number) => game.World.Physics.Simulation.Balls[game.World.Physics.Simulation.IndexOf(new BallId(number))].Position;

    [Fact]
    public void InMoveModeAnyBallFollowsTheCursorOnTheBedAndInsertAndDeleteAddAndRemoveBalls()
    {
        using var game = Practice();
        var frame = game.Frame();
        game.Window.Press(Key.M);
        var start = Ball(game, 2);
        var target = start + new Vec3(-0.2, 0.1, 0);
        game.Window.MoveTo(PixelOf(frame, start).X, PixelOf(frame, start).Y);
        game.Window.Down();
        game.Window.MoveTo(PixelOf(frame, target).X, PixelOf(frame, target).Y);
        game.Window.Up();
        frame = game.Frame();
        // Under the cursor to the rounding of a pixel (the frame's projection is single precision).
        Assert.True((Ball(game, 2) - target).LengthXY < 0.005, $"the 2 is at {Ball(game, 2)}, wanted {target}");
        Assert.Equal(start.Z, Ball(game, 2).Z);

        var practice = game.Host.Tree.Root.GetInTree<PracticeNode>();
        var empty = new Vec3(-0.3, -0.3, game.World.Physics.BallRadius);
        game.Window.MoveTo(PixelOf(frame, empty).X, PixelOf(frame, empty).Y);
        game.Window.Press(Key.Insert);
        Assert.True((Ball(game, 5) - empty).LengthXY < 0.005, "the 5, the lowest number missing, appears under the cursor");
        Assert.Equal(6, practice.Position().Balls.Count);

        frame = game.Frame();
        var one = Ball(game, 1);
        game.Window.MoveTo(PixelOf(frame, one).X, PixelOf(frame, one).Y);
        game.Window.Press(Key.Delete);
        Assert.DoesNotContain(practice.Position().Balls, b => b.Id == new BallId(1));
        Assert.Equal(5, practice.Position().Balls.Count);
    }

    [Fact]
    public void BackspaceRetriesTheLastShotTheBallsRestoredBitForBitAndTheCueSetToTheSameShot()
    {
        using var game = Practice();
        game.Frame();
        var practice = game.Host.Tree.Root.GetInTree<PracticeNode>();
        var before = game.World.Physics.Simulation.Balls.ToArray();
        game.Window.Press(Key.Left);
        game.Window.Press(Key.W);
        game.Window.Press(Key.Up);
        game.Window.Press(Key.Space);
        var shot = practice.LastShot!;
        game.RunUntilRest();
        Assert.NotEqual(before[0].Position, game.World.Physics.Simulation.Balls[0].Position);

        game.Window.Press(Key.Backspace);
        var restored = game.World.Physics.Simulation.Balls.ToArray();
        for (int i = 0; i < before.Length; i++)
        {
            Assert.Equal(before[i].Position, restored[i].Position);
        }
        Assert.Equal(shot, practice.CurrentShot());
        // Touching the aim leaves the restored shot for the cue's own.
        game.Window.Press(Key.D);
        Assert.NotEqual(shot, practice.CurrentShot());
    }

    [Fact]
    public void ZTakesTheLastShotBackInPracticeTheBallsRestoredBitForBit()
    {
        using var game = Practice();
        game.Frame();
        var before = game.World.Physics.Simulation.Balls.ToArray();
        game.Window.Press(Key.W);
        game.Window.Press(Key.Space);
        game.RunUntilRest();
        Assert.NotEqual(before[0].Position, game.World.Physics.Simulation.Balls[0].Position);

        game.Window.Press(TakeBackNode.UndoKey);
        var restored = game.World.Physics.Simulation.Balls.ToArray();
        Assert.Equal(before.Length, restored.Length);
        for (int i = 0; i < before.Length; i++)
        {
            Assert.Equal(before[i].Position, restored[i].Position);
            Assert.Equal(before[i].Velocity, restored[i].Velocity);
        }
        Assert.Null(game.Host.Tree.Root.GetInTree<TakeBackNode>().Refusal);
    }

    private static Dictionary<BallId, Vec3> OnTable(TestGame game)
    {
        var sim = game.World.Physics.Simulation;
        var balls = new Dictionary<BallId, Vec3>();
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            if (!sim.Balls[i].IsOutOfPlay)
            {
                balls[sim.Ids[i]] = sim.Balls[i].Position;
            }
        }
        return balls;
    }

    [Fact]
    public void PracticeStrikesThroughItsSessionAndTakesBackShotAfterShotToWhereItBegan()
    {
        using var game = Practice();
        game.Frame();
        var practice = game.Host.Tree.Root.GetInTree<PracticeNode>();
        var tables = new List<Dictionary<BallId, Vec3>>();
        for (int k = 0; k < 3; k++)
        {
            tables.Add(OnTable(game));
            game.Window.Press(Key.Left);
            game.Window.Press(Key.W);
            game.Window.Press(Key.Space);
            game.RunUntilRest();
            Assert.NotEqual(tables[^1], OnTable(game));
        }
        // Each shot went through practice's session: no referee, the player stays, every shot legal.
        var session = practice.Session!;
        Assert.Equal(3, session.Game.Shots.Count);
        Assert.All(session.Game.Shots, s => Assert.True(s.Ruling.Legal && s.Ruling.Continue));
        for (int k = 2; k >= 0; k--)
        {
            game.Window.Press(TakeBackNode.UndoKey);
            Assert.Equal(tables[k], OnTable(game));
            Assert.Equal(k, session.Game.Shots.Count);
        }
        game.Window.Press(TakeBackNode.UndoKey);
        Assert.Equal("No shot to take back.", game.Host.Tree.Root.GetInTree<TakeBackNode>().Refusal);
    }

    [Fact]
    public void TheSensitivityViewShowsHowOftenTheShotPotsAndDrawsEverySampleSEnding()
    {
        var drill = DrillLibrary.Load("straight-in");
        using var game = Practice(drill.Scene, drill);
        game.Frame();
        var practice = game.Host.Tree.Root.GetInTree<PracticeNode>();
        game.Window.Press(PracticeNode.SensitivityKey);
        var deadline = DateTime.UtcNow.AddSeconds(120);
        RenderFrame frame;
        do
        {
            Thread.Sleep(20);
            frame = game.Frame();
        }
        while (practice.Sensitivity is null && DateTime.UtcNow < deadline);
        var s = practice.Sensitivity!;
        Assert.Equal(PracticeNode.SensitivitySamples, s.Endings.Count);
        // The drill starts aimed straight at the 1, which is on the line to the pocket: level 3 pots most.
        Assert.True(s.PotRate > 0.5, $"{s.Pots} of {s.Endings.Count}");
        frame = game.Frame();
        Assert.Contains(frame.Hud!.Lines, l => l.Contains($"pots {s.Pots} of {s.Endings.Count}", StringComparison.Ordinal));
        int rings = frame.Hud.Aids!.Count(a => a.Radius == 0 && (a.Color.X < 0.5f || a.Color.Y < 0.5f));
        // Every ending of the cue ball in view gets its ring of 12 segments (one that rolled out of
        // the aiming view behind the camera is not drawn).
        var vp = Billiards.App.Rendering.RenderMath.ViewProjection(frame);
        double r = game.World.Physics.BallRadius * 0.5;
        bool InView(Billiards.Core.Mathematics.Vec3 c) => Enumerable.Range(0, 13).All(k => Billiards.App.Rendering.RenderMath.ToPixel(vp,
            new System.Numerics.Vector3((float)(c.X + (r * Math.Cos(2 * Math.PI * k / 12))), (float)(c.Y + (r * Math.Sin(2 * Math.PI * k / 12))), 0.001f), frame.Width, frame.Height) is not null);
        int inView = s.Endings.Count(e => e.Cue is { } c && InView(c));
        Assert.True(inView >= s.Endings.Count / 2, $"{inView} of {s.Endings.Count} endings in view");
        Assert.True(rings >= 12 * inView, $"{rings} segments of ghost endings, {inView} in view");

        // Another level samples again; a changed shot too.
        game.Window.Press(PracticeNode.LevelKey);
        Assert.Null(practice.Sensitivity);
        Assert.Equal(4, practice.SensitivityLevel);
    }

    [Fact]
    public void ADrillFixesItsPositionAndDrawsItsZoneOnTheCloth()
    {
        var drill = DrillLibrary.Load("stop-shot");
        using var game = Practice(drill.Scene, drill);
        var frame = game.Frame();
        var practice = game.Host.Tree.Root.GetInTree<PracticeNode>();
        Assert.Contains(frame.Hud!.Lines, l => l == "Drill: Stop shot");
        // The zone: a ring of segments around its centre on the bed, each end at the zone's radius.
        var zone = drill.Zone!;
        var centre = PixelOf(frame, zone.Centre);
        var edge = PixelOf(frame, zone.Centre + new Vec3(zone.Radius, 0, 0));
        Assert.True(frame.Hud.Aids!.Count(a => a.Radius == 0 && Vector2.Distance(a.A, centre) > 0.5f * Vector2.Distance(edge, centre)) >= 48);
        game.Window.Press(Key.Insert);
        Assert.Equal(2, practice.Position().Balls.Count);
        Assert.Equal("A drill's position is fixed.", practice.Message);
    }

    [Fact]
    public void TheStartMenuOffersPracticeAndEveryDrill()
    {
        using var game = new TestGame();
        string? asked = "none";
        game.World.Menu.Drills = [.. DrillLibrary.All().Select(d => (d.Name, d.Title))];
        game.World.Menu.DrillGallery = DrillLibrary.All();
        game.World.Menu.PracticeRequested += d => asked = d;
        game.World.Menu.ShowStart(MenuPage.Drills);
        game.Frame();
        var at = game.World.Menu.CentreOf("Kick shot")!.Value;
        game.Window.MoveTo(at.X, at.Y);
        game.Window.Down();
        Assert.Equal("kick-shot", asked);
        Assert.Equal(MenuPage.None, game.World.Menu.Page);
        game.World.Menu.ShowStart(MenuPage.Drills);
        var hud = game.Frame().Hud!;
        foreach (var d in DrillLibrary.All())
        {
            Assert.Contains(hud.Buttons!, b => b.Label == d.Title && b.Note == d.Goal && b.Picture is { Balls.Count: > 1 });
        }
        // Every button inside the window.
        Assert.All(hud.Buttons!, b => Assert.True(b.X >= 0 && b.X + b.Width <= 800 && b.Y + b.Height <= 600, $"{b.Label}: {b.X}, {b.Y}, {b.Width} x {b.Height}"));
        game.Window.Press(Billiards.App.Platform.Key.Escape); // back to the first screen
        game.Frame();
        at = game.World.Menu.CentreOf("Practice")!.Value;
        game.Window.MoveTo(at.X, at.Y);
        game.Window.Down();
        Assert.Null(asked);
    }

    [Theory]
    [InlineData(new[] { "play", "--drill", "no-such-drill" }, "--drill no-such-drill: no such drill")]
    [InlineData(new[] { "play", "--practice", "--rules", "eight-ball" }, "practice has no match")]
    [InlineData(new[] { "play", "--drill", "stop-shot", "x.json" }, "a drill brings its own position")]
    public void BadPracticeArgumentsAreOneLineAndExit2(string[] args, string message)
    {
        var (code, _, error) = CliRun.Run(args);
        Assert.Equal(2, code);
        Assert.Contains(message, error, StringComparison.Ordinal);
        Assert.Single(error.Trim().Split('\n'));
    }

    [Fact]
    public void TheDataFolderIsTheVariableSElseXDGDATAHOMESElseUnderHome()
    {
        Assert.Equal(Path.GetFullPath("/tmp/x"), DataFolder.Path(v => v == DataFolder.Variable ? "/tmp/x" : null));
        if (OperatingSystem.IsLinux())
        {
            Assert.Equal("/d/billiards", DataFolder.Path(v => v == "XDG_DATA_HOME" ? "/d" : v == "HOME" ? "/h" : null));
            Assert.Equal("/h/.local/share/billiards", DataFolder.Path(v => v == "HOME" ? "/h" : null));
        }
    }

    [Fact]
    public void ABrokenResultsFileIsOneWarningAndAFreshStartAndIsReplacedWhole()
    {
        Directory.CreateDirectory(_folder);
        string path = Path.Combine(_folder, DrillRecords.FileName);
        File.WriteAllText(path, "{ not json");
        var warnings = new StringWriter();
        var records = DrillRecords.Load(path, warnings);
        Assert.Contains("cannot read the drill results", warnings.ToString(), StringComparison.Ordinal);
        Assert.Equal(DrillRecord.None, records["stop-shot"]);
        records.Record("stop-shot", new DrillOutcome(true, 1, 0.02, "ok"));
        records.Record("stop-shot", new DrillOutcome(true, 1, 0.03, "ok"));
        records.Record("stop-shot", new DrillOutcome(false, 0, null, "no"));
        Assert.Equal(new DrillRecord(3, 2, 1, 0.02), DrillRecords.Load(path)["stop-shot"]);
    }
}

internal sealed class NullFrameRenderer : IFrameRenderer
{
    public void Draw(RenderFrame frame)
    {
    }
}

public class PracticeHelpTests
{
    [Fact]
    public void TheHelpShowsPracticeSKeysInPracticeAndTheMatchSInAMatchAndFitsA720LineWindow()
    {
        var practice = HelpText.For(match: false, practice: true);
        var match = HelpText.For(match: true, practice: false);
        Assert.Contains(practice, l => l.Contains("Backspace", StringComparison.Ordinal));
        Assert.Contains(practice, l => l.Contains("F6 / F7", StringComparison.Ordinal));
        Assert.DoesNotContain(practice, l => l.StartsWith("Match", StringComparison.Ordinal));
        Assert.DoesNotContain(match, l => l.Contains("Backspace", StringComparison.Ordinal));
        Assert.Contains(match, l => l.StartsWith("Match", StringComparison.Ordinal));
        // Every section but the other's, in order.
        // Each section once: the two together are every line, the common ones twice; a scene with neither keeps the match's.
        var common = practice.Intersect(match).Count();
        Assert.Equal(HelpText.Lines.Count, practice.Count + match.Count - common);
        Assert.Equal(match, HelpText.For(match: false, practice: false));
        int scale = HudRenderer.Scale(720);
        Assert.True((practice.Count * HudFont.LineHeight * scale) + (4 * 8 * scale) <= 720, $"{practice.Count} lines");

        using var game = new TestGame(SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "practice.json")), practice: new PracticeSetup(Path.Combine(Path.GetTempPath(), "unused.json")), create: SimulationFactory.Create);
        Assert.Equal(practice, game.Frame().Hud!.HelpLines);
    }
}
