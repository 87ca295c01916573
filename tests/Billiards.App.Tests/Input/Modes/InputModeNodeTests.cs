using Billiards.App.Game;
using Billiards.App.Input.Modes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.App.Tests.Game;
using Billiards.Core.Balls;

namespace Billiards.App.Tests.Input.Modes;

/// <summary>The control modes driven through a fake window and a manual clock.</summary>
public class InputModeNodeTests
{
    private static InputModeNode Modes(TestGame game) => game.World.InputModes;

    private static CueNode Cue(TestGame game) => game.World.Tree.Find<CueNode>()!;

    /// <summary>The stroke of <see cref="StrokeTrackerTests"/>: d = 50 px, t = 50 ms, so 250 cm/s = 2.5 m/s.</summary>
    private static void Stroke(TestGame game, double start = 0)
    {
        game.Window.Press(Key.S);
        game.Clock.Now = start;
        game.Window.MoveTo(400, 300);
        game.Window.Down();
        (double t, float y)[] path = [(0.010, 320), (0.030, 360), (0.100, 350), (0.120, 320), (0.150, 290)];
        foreach (var (t, y) in path)
        {
            game.Clock.Now = start + t;
            game.Window.MoveTo(400, y);
        }
        game.Window.Up();
    }

    [Fact]
    public void AStrokeStrikesWithTheSpeedOfFormel31AlongTheView()
    {
        using var game = new TestGame();
        Stroke(game);
        var shot = Assert.Single(game.Simulation.Strikes);
        Assert.Equal(2.5, shot.Speed, 12);
        // The camera starts behind the cue ball (φ = π), so the stroke goes along +x.
        Assert.Equal(0, shot.AimDeg, 9);
        Assert.Equal(0, shot.TipSide);
        Assert.Equal(0, shot.TipHeight);
        // The cue is raised just enough for its butt to clear the head rail 0.635 m behind the ball.
        Assert.Equal(Cue(game).RailElevationDegrees, shot.ElevationDeg, 9);
        Assert.InRange(shot.ElevationDeg, 2, 3);
        Assert.Equal(InputMode.View, Modes(game).Mode); // the seed returns to view mode after a strike
    }

    [Fact]
    public void TheStrikeGoesFromTheCameraToTheBallInTheBedPlane()
    {
        using var game = new TestGame();
        // Orbit: φ = π + 0.01 * 50 = π + 0.5; the eye is at -(cos 0.5, sin 0.5) from the ball, so the aim is 0.5 rad.
        game.Window.MoveTo(0, 0);
        game.Window.Down();
        game.Window.MoveTo(50, 0);
        game.Window.Up();
        Stroke(game);
        var shot = Assert.Single(game.Simulation.Strikes);
        Assert.Equal(0.5 * 180 / Math.PI, shot.AimDeg, 9);
    }

    [Fact]
    public void TheMouseIsCapturedWhileStrokingAndReleasedAtTheStrike()
    {
        using var game = new TestGame();
        game.Window.Press(Key.S);
        game.Window.MoveTo(400, 300);
        game.Window.Down();
        Assert.True(game.Window.Captured);
        Assert.True(Modes(game).IsStroking);
        game.Window.MoveTo(400, 340);
        Assert.Equal(40, Cue(game).PullBackPixels);
        game.Window.Up();                          // let go without striking
        Assert.False(game.Window.Captured);
        Assert.Empty(game.Simulation.Strikes);
        Assert.Equal(0, Cue(game).PullBackPixels);
        Stroke(game, 1.0);
        Assert.Equal([true, false, true, false], game.Window.CaptureCalls);
    }

    [Fact]
    public void EverythingButViewingIsLockedWhileBallsRoll()
    {
        using var game = new TestGame();
        Stroke(game);
        Assert.True(Modes(game).IsLocked);
        Assert.False(Cue(game).IsVisible);
        foreach (var key in new[] { Key.S, Key.E, Key.M })
        {
            game.Window.Press(key);
            Assert.Equal(InputMode.View, Modes(game).Mode);
        }
        game.Window.Press(Key.Up);
        Assert.Equal(0, Cue(game).ElevationDegrees);
        // Viewing still works.
        double phi = game.World.Tree.Find<Billiards.App.Camera.CameraNode>()!.Camera.Phi;
        game.Window.MoveTo(0, 0);
        game.Window.Down();
        game.Window.MoveTo(10, 0);
        game.Window.Up();
        Assert.Equal(phi + 0.1, game.World.Tree.Find<Billiards.App.Camera.CameraNode>()!.Camera.Phi, 12);

        game.RunUntilRest();
        Assert.False(Modes(game).IsLocked);
        Assert.True(Cue(game).IsVisible);
        game.Window.Press(Key.S);
        Assert.Equal(InputMode.Shot, Modes(game).Mode);
    }

    [Fact]
    public void ModeKeysSwitchModesAndASwitchAbandonsAStroke()
    {
        using var game = new TestGame();
        var seen = new List<InputMode>();
        Modes(game).ModeChanged += seen.Add;
        game.Window.Press(Key.E);
        game.Window.Press(Key.M);
        game.Window.Press(Key.V);
        game.Window.Press(Key.S);
        game.Window.MoveTo(0, 300);
        game.Window.Down();
        game.Window.MoveTo(0, 350);
        game.Window.Press(Key.E);                  // mid-stroke
        Assert.False(Modes(game).IsStroking);
        Assert.False(game.Window.Captured);
        game.Window.MoveTo(0, 200);                // would have struck in shot mode
        Assert.Empty(game.Simulation.Strikes);
        Assert.Equal([InputMode.Spin, InputMode.Move, InputMode.View, InputMode.Shot, InputMode.Spin], seen);
    }

    [Fact]
    public void EffetModeMovesTheTipAndTheStrikeCarriesTipAndElevation()
    {
        using var game = new TestGame();
        game.Window.Press(Key.E);
        game.Window.MoveTo(0, 0);
        game.Window.Down();
        game.Window.MoveTo(100, -50);              // Formel 32-33: e = (1, 0.5) cm
        game.Window.Up();
        Assert.Equal(1.0, Cue(game).Tip.X, 12);
        Assert.Equal(0.5, Cue(game).Tip.Y, 12);
        game.Window.Press(Key.Up);
        game.Window.Press(Key.Up);
        game.Window.Wheel(3);                      // effet mode: the wheel raises the cue too
        Assert.Equal(5, Cue(game).ElevationDegrees);
        game.Window.Press(Key.Down);
        Stroke(game, 1.0);
        var shot = Assert.Single(game.Simulation.Strikes);
        Assert.Equal(1.0 / 2.86, shot.TipSide, 12);
        Assert.Equal(0.5 / 2.86, shot.TipHeight, 12);
        Assert.Equal(4, shot.ElevationDeg);
    }

    [Fact]
    public void ElevationIsClamped()
    {
        using var game = new TestGame();
        game.Window.Press(Key.Down);
        Assert.Equal(0, Cue(game).ElevationDegrees);
        game.Window.Press(Key.S);
        game.Window.Wheel(500);
        Assert.Equal(SeedControls.MaxElevationDegrees, Cue(game).ElevationDegrees);
    }

    [Fact]
    public void MovingTheCueBallFollowsFormel34AndTheCameraFollowsIt()
    {
        using var game = new TestGame();
        var camera = game.World.Tree.Find<Billiards.App.Camera.CameraNode>()!.Camera;
        var ball = game.World.Physics.CueBallPosition;
        var eye = camera.Eye;
        game.Window.Press(Key.M);
        game.Window.MoveTo(0, 0);
        game.Window.Down();
        // Looking along +x: f = (1, 0, 0), s = (0, -1, 0). dx = 20, dy = -10:
        // p = p_old - (-10) f + 20 s, one centimetre per pixel: (+0.1, -0.2) m.
        game.Window.MoveTo(20, -10);
        var moved = game.World.Physics.CueBallPosition;
        Assert.Equal(ball.X + 0.1, moved.X, 9);
        Assert.Equal(ball.Y - 0.2, moved.Y, 9);
        // Formel 35: the camera keeps its offset from the ball.
        Assert.Equal(eye.X + 0.1, camera.Eye.X, 9);
        Assert.Equal(eye.Y - 0.2, camera.Eye.Y, 9);
        Assert.Equal(eye.Z, camera.Eye.Z, 12);

        // A long push is clamped at the foot cushion: x = L/2 - R; the camera moves only as far.
        game.Window.MoveTo(20, -1000);
        double r = game.World.Physics.BallRadius;
        double maxX = game.World.Physics.Table.HalfLength - r;
        Assert.Equal(maxX, game.World.Physics.CueBallPosition.X, 12);
        Assert.Equal(maxX - moved.X, camera.Eye.X - (eye.X + 0.1), 9);
        Assert.Equal(maxX, camera.Centre.X, 9);
        game.Window.Up();

        // The strike hands the placement to Core (a new simulation with the ball there).
        Stroke(game, 1.0);
        var cue = game.Simulation.State[game.Simulation.IndexOf(PoolBalls.Cue)];
        Assert.Single(game.Simulation.Strikes);
        Assert.Equal(maxX, cue.Position.X, 12);
        Assert.Equal(ball.Y - 0.2, cue.Position.Y, 9);
    }

    // Move mode (M), the pointer on the cue ball's pixel in the frame drawn, the button down.
    private static (Billiards.Core.Mathematics.Vec3 Ball, System.Numerics.Matrix4x4 ViewProjection, System.Numerics.Vector2 Pixel) PressOnTheCueBallInMoveMode(TestGame game, RenderFrame frame)
    {
        game.Window.Press(Key.M);
        var ball = game.World.Physics.CueBallPosition;
        var vp = RenderMath.ViewProjection(frame);
        var start = RenderMath.ToPixel(vp, ball.ToVector3(), frame.Width, frame.Height)!.Value;
        game.Window.MoveTo(start.X, start.Y);
        game.Window.Down();
        return (ball, vp, start);
    }

    [Fact]
    public void FromAboveTheCueBallFollowsThePointerOnTheScreenNotTheCue()
    {
        using var game = new TestGame();
        var cameraNode = game.World.Tree.Find<Billiards.App.Camera.CameraNode>()!;
        cameraNode.Camera.SetPhi(2.0);                // the cue aims somewhere across the table
        game.Window.Press(Billiards.App.Camera.CameraNode.OverheadKey);
        var frame = game.Frame();
        Assert.True(cameraNode.Overhead);
        var (before, _, start) = PressOnTheCueBallInMoveMode(game, frame);
        game.Window.MoveTo(start.X + 120, start.Y - 60);   // right and up on the screen
        game.Window.Up();
        var after = game.World.Physics.CueBallPosition;
        // Right on the screen is +x on the table, up is +y; the ball stays under the pointer (within a pixel).
        Assert.True(after.X > before.X && after.Y > before.Y);
        var end = RenderMath.ToPixel(RenderMath.ViewProjection(game.Frame()), after.ToVector3(), frame.Width, frame.Height)!.Value;
        Assert.InRange(end.X - (start.X + 120), -1.5, 1.5);
        Assert.InRange(end.Y - (start.Y - 60), -1.5, 1.5);
    }

    [Fact]
    public void BehindTheBallTheCueBallFollowsThePointerOnTheBedFinelyWithShiftAndTheArrows()
    {
        // The seed's centimetre a pixel put the ball 1 m away for a 100 px drag: too coarse to place it.
        using var game = new TestGame();
        var frame = game.Frame();
        var (before, vp, start) = PressOnTheCueBallInMoveMode(game, frame);
        game.Window.MoveTo(start.X + 30, start.Y - 40);     // right and up on the screen
        var after = game.World.Physics.CueBallPosition;
        // In the view the drag began in, the ball lies under the pointer (within half a pixel).
        var seen = RenderMath.ToPixel(vp, after.ToVector3(), frame.Width, frame.Height)!.Value;
        Assert.InRange(seen.X - (start.X + 30), -0.5, 0.5);
        Assert.InRange(seen.Y - (start.Y - 40), -0.5, 0.5);
        // Away from the camera (+x here) and to its right (-y); a few millimetres a pixel, not the seed's centimetre.
        Assert.True(after.X > before.X && after.Y < before.Y);
        double coarse = (after - before).LengthXY;
        Assert.InRange(coarse, 0.02, 0.25);

        // Shift: a tenth as far for the same drag.
        var mid = after;
        game.Window.Hold(Key.Shift);
        game.Window.MoveTo(start.X + 60, start.Y - 80);
        game.Window.Release(Key.Shift);
        game.Window.Up();
        var fine = game.World.Physics.CueBallPosition;
        Assert.InRange((fine - mid).LengthXY / coarse, 0.07, 0.13);

        // The arrows: 5 mm a press away from the camera, 0.5 mm with Shift, and to the screen's left.
        game.Window.Press(Key.Up);
        Assert.Equal(fine.X + SeedControls.KeyMoveMetres, game.World.Physics.CueBallPosition.X, 9);
        Assert.Equal(fine.Y, game.World.Physics.CueBallPosition.Y, 9);
        game.Window.Hold(Key.Shift);
        game.Window.Press(Key.Left);
        game.Window.Release(Key.Shift);
        Assert.Equal(fine.Y + SeedControls.FineKeyMoveMetres, game.World.Physics.CueBallPosition.Y, 9);
        Assert.Equal(0, Cue(game).ElevationDegrees);   // the arrows moved the ball, not the cue
    }

    [Fact]
    public void AtTheBreakTheBallInHandSlidesAlongTheHeadStringWhenDraggedAcrossTheTable()
    {
        // The break's ball in hand starts on the head string: a sideways drag whose bed points put
        // it a hair beyond the line was refused whole, and the ball did not move at all.
        var scene = Billiards.Core.Scenes.SceneLoader.Load(Billiards.App.Cli.PlayCommand.FindRulesScene(Billiards.Core.Rules.GameRules.EightBall));
        using var game = new TestGame(scene, new MatchSetup(Billiards.Core.Rules.GameRules.EightBall, [new Billiards.Core.Rules.Seat("Anna"), new Billiards.Core.Rules.Seat("Ben")]));
        game.Frame();
        var frame = game.Frame();
        var (before, _, start) = PressOnTheCueBallInMoveMode(game, frame);
        for (int i = 1; i <= 6; i++)
        {
            game.Window.MoveTo(start.X + (10 * i), start.Y - (0.5f * i));   // right, a little up: across the line
        }
        game.Window.Up();
        var after = game.World.Physics.CueBallPosition;
        Assert.True(before.Y - after.Y > 0.02, $"the ball moved {(before.Y - after.Y) * 100:0.0} cm to the right");
        Assert.True(after.X <= before.X, "the ball stays in the kitchen");
    }

    [Fact]
    public void TheCueBallCannotBeMovedOntoAnotherBall()
    {
        using var game = new TestGame();
        var ball = game.World.Physics.CueBallPosition;
        game.Window.Press(Key.M);
        game.Window.MoveTo(0, 0);
        game.Window.Down();
        game.Window.MoveTo(0, -127);               // 1.27 m forward: onto the 1 ball at (0.635, 0)
        Assert.Equal(ball, game.World.Physics.CueBallPosition);
    }

    [Fact]
    public void WithoutACueBallOnlyViewModeExists()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withCue: false));
        Assert.Null(game.World.Tree.Find<CueNode>());
        game.Window.Press(Key.S);
        game.Window.Press(Key.E);
        game.Window.Press(Key.M);
        Assert.Equal(InputMode.View, Modes(game).Mode);
        var frame = game.Frame();
        Assert.False(frame.Cue.Visible);
    }

    [Fact]
    public void RightDragAndWheelZoomInViewMode()
    {
        using var game = new TestGame();
        var camera = game.World.Tree.Find<Billiards.App.Camera.CameraNode>()!.Camera;
        double d = camera.Distance;
        game.Window.MoveTo(0, 0);
        game.Window.Down(MouseButton.Right);
        game.Window.MoveTo(0, 20);                 // Listing 6: scale 0.8
        game.Window.Up(MouseButton.Right);
        Assert.Equal(d * 0.8, camera.Distance, 12);
        game.Window.Wheel(1);                      // one notch = 10 px: scale 0.9
        Assert.Equal(d * 0.8 * 0.9, camera.Distance, 12);
    }
}
