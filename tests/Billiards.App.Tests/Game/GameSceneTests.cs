using Billiards.App.Camera;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Input.Modes;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;

namespace Billiards.App.Tests.Game;

public class GameSceneTests
{
    [Fact]
    public void ASceneWithRulesAndACueBallGetsEveryNode()
    {
        using var game = new TestGame(TestScenes.TwoBalls(rules: "eight-ball"));
        var tree = game.World.Tree;
        Assert.NotNull(tree.Find<TableNode>());
        Assert.NotNull(tree.Find<PhysicsNode>());
        Assert.NotNull(tree.Find<CameraNode>());
        Assert.NotNull(tree.Find<CueNode>());
        Assert.NotNull(tree.Find<InputModeNode>());
        Assert.NotNull(tree.Find<SystemKeysNode>());
        Assert.NotNull(tree.Find<HudNode>());
    }

    [Fact]
    public void ASceneWithoutACueBallHasNoCue()
    {
        using var noCue = new TestGame(TestScenes.TwoBalls(withCue: false));
        Assert.Null(noCue.World.Tree.Find<CueNode>());
        Assert.NotNull(noCue.World.Tree.Find<CameraNode>());
    }

    [Fact]
    public void ASceneWithAShotPlaysItWhenTheGameStarts()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        var shot = Assert.Single(game.Simulation.Strikes);
        Assert.Equal(2.0, shot.Speed);
        Assert.True(game.World.Physics.IsRolling);
        using var quiet = new TestGame(TestScenes.TwoBalls());
        Assert.Empty(quiet.Simulation.Strikes);
        Assert.False(quiet.World.Physics.IsRolling);
    }

    [Fact]
    public void TheCameraMovesWithTheCueBallWhenTheBallsRest()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        var camera = game.World.Tree.Find<CameraNode>()!.Camera;
        var eye = camera.Eye;
        var start = game.World.Physics.CueBallPosition;
        game.RunUntilRest();
        var end = game.World.Physics.CueBallPosition;
        Assert.True(end.X - start.X > 0.9, "the fake rolled the cue ball about v^2 / 2a = 1 m");
        Assert.Equal(end.X, camera.Centre.X, 12);
        Assert.Equal(eye.X + (end.X - start.X), camera.Eye.X, 12);
    }

    [Fact]
    public void PocketedBallsVanish()
    {
        using var game = new TestGame(TestScenes.TwoBalls(rules: "eight-ball", withShot: true));
        game.Frame();
        game.Simulation.Pocket(new BallId(1));
        var frame = game.Frame();
        Assert.False(frame.Balls.Single(b => b.Id.Value == 1).Visible);
        Assert.True(frame.Balls.Single(b => PoolBalls.IsCue(b.Id)).Visible);
        game.RunUntilRest();
        Assert.False(game.Frame().Balls.Single(b => b.Id.Value == 1).Visible);
    }

    [Fact]
    public void AScratchedCueBallComesBackInHandOnTheHeadSpotAndTheGameGoesOn()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        game.Frame();
        game.Simulation.Pocket(PoolBalls.Cue);
        game.RunUntilRest();
        var physics = game.World.Physics;
        Assert.True(physics.BallInHand);
        Assert.True(physics.HasCueBall);
        // The 9 ft table's head spot: a quarter of the length (2.54 m) from the head rail's side of the centre.
        Assert.Equal(-2.54 / 4, physics.CueBallPosition.X, 9);
        Assert.Equal(0, physics.CueBallPosition.Y, 9);
        Assert.Equal(InputMode.Move, game.World.InputModes.Mode);
        var frame = game.Frame();
        Assert.True(frame.Balls.Single(b => PoolBalls.IsCue(b.Id)).Visible);
        Assert.True(frame.Cue.Visible);
        Assert.Contains(frame.Hud!.Lines, l => l.StartsWith("Ball in hand", StringComparison.Ordinal));

        // Anywhere on the bed, but not off it or on another ball.
        Assert.True(physics.TryPlaceCueBall(new Vec3(0.3, 0.4, 0)));
        Assert.False(physics.TryPlaceCueBall(new Vec3(2.0, 0, 0)));
        Assert.False(physics.TryPlaceCueBall(new Vec3(0.635 + 0.01, 0, 0)));
        Assert.Equal(new Vec3(0.3, 0.4, physics.BallRadius), physics.CueBallPosition);

        // The next strike plays from there: a new simulation with the cue ball at the placement.
        physics.Strike(new ShotSpec(1.0, 0, 0, 0, 0));
        Assert.False(physics.BallInHand);
        Assert.Equal(0.3, game.Simulation.State[game.Simulation.IndexOf(PoolBalls.Cue)].Position.X, 9);
        Assert.False(game.Simulation.State[game.Simulation.IndexOf(PoolBalls.Cue)].IsPocketed);
    }

    [Fact]
    public void WithoutAGameTheScratchIsTheFreeTableSessionsToRuleAndItGivesTheCueBallBackInHand()
    {
        // The physics node returns no cue ball of its own where a node strikes through it: the
        // scene's session without a referee rules on the shot and gives the ball back.
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        var physics = game.World.Physics;
        var session = game.World.Tree.Find<FreeTableNode>()!.Session!;
        bool returned = false;
        physics.CueBallReturned += _ => returned = true;
        game.Frame();
        game.Simulation.Pocket(PoolBalls.Cue);
        game.RunUntilRest();
        Assert.True(returned);
        Assert.True(physics.BallInHand);
        Assert.Equal(Billiards.Core.Rules.BallInHand.Table, session.BallInHand);
        var ruled = Assert.Single(session.Game.Shots).Ruling;
        Assert.True(ruled.Legal && ruled.Continue);
    }

    [Fact]
    public void TheFrameCarriesTableCameraCueAndHud()
    {
        using var game = new TestGame();
        game.Window.FramebufferSize = (1024, 768);
        var frame = game.Frame();
        Assert.Equal((1024, 768), (frame.Width, frame.Height));
        Assert.Equal("pool-9ft", frame.Table.Preset);
        var camera = game.World.Tree.Find<CameraNode>()!.Camera;
        Assert.Equal(camera.Eye.ToVector3(), frame.Eye);
        Assert.Equal(camera.Centre.ToVector3(), frame.Target);
        Assert.True(frame.Cue.Visible);
        Assert.Equal(1, frame.Cue.AimDirection.X, 6);
        Assert.Equal(SeedControls.CueRestGap, frame.Cue.PullBack, 6);
        Assert.Equal(2, frame.Balls.Count);
        Assert.NotNull(frame.Hud);
    }
}

public class SystemKeysAndHudTests
{
    [Fact]
    public void EscapeOpensTheMenuWhoseQuitAsksFirstAndF11TogglesFullscreen()
    {
        using var game = new TestGame();
        game.Window.Press(Key.F11);
        Assert.Equal(1, game.Window.FullscreenToggles);
        var menu = game.World.Menu;
        game.Window.Press(Key.Escape);
        Assert.Equal(Billiards.App.Hud.MenuPage.Pause, menu.Page);
        Assert.True(game.World.Loop.Paused);
        var frame = game.Frame();
        Assert.Equal(["Resume [Esc]", "Restart [R]", "Menu [M]", "Quit [Q]"], frame.Hud!.Buttons!.Select(b => b.Label));
        Assert.Equal("Paused", frame.Hud.Title);
        // The game takes no input meanwhile.
        game.Window.Press(Key.E);
        Assert.Equal(InputMode.View, game.World.InputModes.Mode);
        game.Window.Press(Key.Q);
        Assert.Equal(Billiards.App.Hud.MenuPage.ConfirmQuit, menu.Page);
        game.Window.Press(Key.N);
        Assert.Equal(Billiards.App.Hud.MenuPage.Pause, menu.Page);
        game.Window.Press(Key.Escape);
        Assert.Equal(Billiards.App.Hud.MenuPage.None, menu.Page);
        Assert.False(game.World.Loop.Paused);
        Assert.Null(game.Frame().Hud!.Buttons);
        Assert.False(game.Window.Closed);
        // By the mouse: Escape, then Quit, then Yes.
        game.Window.Press(Key.Escape);
        game.Frame();
        Click(game, menu.CentreOf("Quit")!.Value);
        Assert.Equal(Billiards.App.Hud.MenuPage.ConfirmQuit, menu.Page);
        Assert.False(game.Window.Closed);
        Click(game, menu.CentreOf("Yes")!.Value);
        Assert.True(game.Window.Closed);
    }

    [Fact]
    public void ThePauseMenuLeadsToTheStartMenuWhoseEscapeComesBackToTheGame()
    {
        var scene = Billiards.Core.Scenes.SceneLoader.Load(Billiards.App.Cli.PlayCommand.FindRulesScene(Billiards.Core.Rules.GameRules.NineBall));
        using var game = new TestGame(scene, new Billiards.App.Game.MatchSetup(Billiards.Core.Rules.GameRules.NineBall, [new Billiards.Core.Rules.Seat("Anna"), new Billiards.Core.Rules.Seat("Computer L2", 2)]));
        var menu = game.World.Menu;
        var match = game.World.Tree.Root.GetInTree<Billiards.App.Game.MatchNode>();
        var session = match.Session;
        game.Window.Press(Key.Escape);
        game.Window.Press(Key.M);
        Assert.Equal(Billiards.App.Hud.MenuPage.Start, menu.Page);
        Assert.True(game.World.Loop.Paused);
        Assert.Contains(game.Frame().Hud!.Buttons!, b => b.Label == "Play");
        game.Window.Press(Key.Escape);
        Assert.Equal(Billiards.App.Hud.MenuPage.None, menu.Page);
        Assert.False(game.World.Loop.Paused);
        Assert.Same(session, match.Session);
        // By the mouse too.
        game.Window.Press(Key.Escape);
        game.Frame();
        Click(game, menu.CentreOf("Menu [M]")!.Value);
        Assert.Equal(Billiards.App.Hud.MenuPage.Start, menu.Page);
    }

    [Fact]
    public void AnOnlineGamesPauseMenuHasNoWayToTheStartMenu()
    {
        var scene = Billiards.Core.Scenes.SceneLoader.Load(Billiards.App.Cli.PlayCommand.FindRulesScene(Billiards.Core.Rules.GameRules.EightBall));
        using var game = new TestGame(scene, new Billiards.App.Game.MatchSetup(Billiards.Core.Rules.GameRules.EightBall, [new Billiards.Core.Rules.Seat("Anna"), new Billiards.Core.Rules.Seat("Ben") { Kind = Billiards.Core.Rules.SeatKind.Remote }]));
        var menu = game.World.Menu;
        game.Window.Press(Key.Escape);
        Assert.DoesNotContain(game.Frame().Hud!.Buttons!, b => b.Label.StartsWith("Menu", StringComparison.Ordinal));
        game.Window.Press(Key.M);
        Assert.Equal(Billiards.App.Hud.MenuPage.Pause, menu.Page);
    }

    [Fact]
    public void RestartPutsThePracticeBallsBack()
    {
        using var game = new TestGame();
        game.Frame();
        var start = game.World.Physics.CueBallPosition;
        game.World.Physics.Strike(new Billiards.Core.Cue.ShotSpec(2, 90));
        game.RunUntilRest();
        Assert.NotEqual(start, game.World.Physics.CueBallPosition);
        game.Window.Press(Key.Escape);
        game.Window.Press(Key.R);
        Assert.Equal(start, game.World.Physics.CueBallPosition);
        Assert.Equal(Billiards.App.Hud.MenuPage.None, game.World.Menu.Page);
    }

    internal static void Click(TestGame game, System.Numerics.Vector2 at)
    {
        game.Window.MoveTo(at.X, at.Y);
        game.Window.Down();
        game.Window.Up();
    }

    [Fact]
    public void F3TogglesTheCollisionGeometry()
    {
        using var game = new TestGame();
        Assert.False(game.Frame().ShowCollisionGeometry);
        game.Window.Press(Key.F3);
        var frame = game.Frame();
        Assert.True(frame.ShowCollisionGeometry);
        // The scene's model's real geometry, not a stand-in.
        Assert.Equal(TableNode.CollisionGeometryOf(game.Scene), frame.CollisionTriangles);
        Assert.NotEmpty(frame.CollisionTriangles);
    }

    [Fact]
    public void HAndF1ToggleTheHelpWhichListsEveryKey()
    {
        using var game = new TestGame();
        Assert.False(game.Frame().Hud!.ShowHelp);
        game.Window.Press(Key.H);
        var hud = game.Frame().Hud!;
        Assert.True(hud.ShowHelp);
        foreach (string key in new[] { "V ", "S ", "E ", "M ", "Up / Down", "P ", "N ", "G ", "H or F1", "F11", "Escape" })
        {
            Assert.Contains(hud.HelpLines, l => l.TrimStart().StartsWith(key, StringComparison.Ordinal));
        }
        game.Window.Press(Key.F1);
        Assert.False(game.Frame().Hud!.ShowHelp);
    }

    [Fact]
    public void PPausesAndNStepsOnce()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        game.Window.Press(Key.P);
        var frame = game.Frame(0.1);
        Assert.Equal(0, game.Simulation.StepCount);
        Assert.Contains("PAUSED (P resumes, N steps)", frame.Hud!.Lines);
        game.Window.Press(Key.N);
        game.Frame(0.1);
        game.Frame(0.1);
        Assert.Equal(1, game.Simulation.StepCount);
        game.Window.Press(Key.P);
        game.Frame(0.1);
        Assert.True(game.Simulation.StepCount > 1);
    }

    [Fact]
    public void TheHudShowsModeLastShotSpinElevationAndFrameRate()
    {
        using var game = new TestGame();
        for (int i = 0; i < 5; i++)
        {
            game.Frame(1.0 / 64);
        }
        var lines = game.Frame(1.0 / 64).Hud!.Lines;
        Assert.Equal(
            ["Mode: view [V]", "Last shot: -", "Spin: side 0.00 R, height 0.00 R", "Elevation: 3 deg (over the rail)", "FPS: 64", "H or F1: help"],
            lines);

        game.Window.Press(Key.E);
        game.Window.MoveTo(0, 0);
        game.Window.Down();
        game.Window.MoveTo(143, 0);                // e_x = 1.43 cm = 0.5 R
        game.Window.Up();
        for (int i = 0; i < 4; i++)
        {
            game.Window.Press(Key.Up);             // 4 deg: above the 2.5 deg the head rail asks for
        }
        var hud = game.Frame(1.0 / 64).Hud!;
        Assert.Equal("Mode: spin [E]", hud.Lines[0]);
        Assert.Equal("Spin: side +0.50 R, height 0.00 R", hud.Lines[2]);
        Assert.Equal("Elevation: 4 deg", hud.Lines[3]);
        Assert.Equal(0.5f, hud.SpinPoint.X, 6);
    }

    [Fact]
    public void TheHudShowsTheLastShotAndTheLock()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        var lines = game.Frame().Hud!.Lines;
        Assert.Equal("Mode: view [V] (balls rolling: view only)", lines[0]);
        Assert.Equal("Last shot: 2.00 m/s", lines[1]);
    }

    [Fact]
    public void Formel4FrameRateIs1000OverTheFrameTimeInMsCountedOverHalfASecond()
    {
        var meter = new FrameRateMeter();
        meter.AddFrame(20);                        // 1000 / 20 = 50
        Assert.Equal(50, meter.Current);
        Assert.Equal(50, meter.Smoothed);
        meter.AddFrame(10);                        // 100; 2 frames in 30 ms
        Assert.Equal(100, meter.Current);
        Assert.Equal(2 / 0.030, meter.Smoothed, 9);
        meter.AddFrame(0);                         // skipped
        Assert.Equal(2 / 0.030, meter.Smoothed, 9);
    }

    [Fact]
    public void FrameRateShowsASlowRateWithinOneWindowAfterManyFastFrames()
    {
        // 600 frames of 1 ms, then 2 FPS: an average over frames would still show hundreds.
        var meter = new FrameRateMeter();
        for (int i = 0; i < 600; i++)
        {
            meter.AddFrame(1);
        }
        Assert.Equal(1000, meter.Smoothed, 6);
        meter.AddFrame(500);                       // closes the window the fast frames began
        meter.AddFrame(500);                       // a window of its own
        Assert.Equal(2, meter.Smoothed, 9);
    }
}
