using Billiards.App.Camera;
using Billiards.App.Hud;
using Billiards.App.Game;
using Billiards.App.Input.Modes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Game;

public class CameraTests
{
    [Fact]
    public void Dragging_up_in_view_mode_stops_above_the_rail_and_the_cue_and_looks_down_ten_degrees_at_least()
    {
        using var game = new TestGame();
        var camera = game.World.Tree.Find<CameraNode>()!;
        game.Frame();
        game.Window.MoveTo(400, 300);
        game.Window.Down();
        for (int i = 1; i <= 40; i++)
        {
            game.Window.MoveTo(400, 300 - (20 * i)); // 800 px up: the seed's orbit alone would go to table level
        }
        game.Window.Up();
        game.Frame();
        var eye = camera.Camera.Eye;
        var centre = camera.Camera.Centre;
        double railTop = CueClearance.RailTop(game.Scene.Table);
        Assert.True(eye.Z >= railTop + CameraNode.RailMargin - 1e-9, $"eye at {eye.Z} m");
        double behind = (eye - centre).XY.Length;
        double down = Math.Atan2(eye.Z - centre.Z, behind);
        Assert.True(down >= (10 * Math.PI / 180) - 1e-6, $"looking down {down * 180 / Math.PI} deg");
        // Above the cue (elevation 0: the cue's line is level with the ball's centre) by the margin.
        Assert.True(eye.Z >= game.World.Physics.BallRadius + CameraNode.CueMargin - 1e-9);
    }

    [Fact]
    public void The_camera_follows_the_balls_while_they_roll_looks_down_on_the_table_on_its_key_and_is_back_behind_the_cue_ball_after()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        var camera = game.World.Tree.Find<CameraNode>()!;
        var frame = game.Frame();
        Assert.True(camera.Following);
        Assert.False(camera.Overhead);
        Assert.Equal(camera.Chase.Eye, frame.Eye);
        // The shot runs along +x: the view looks after the balls from behind the shot's line, and
        // its point of interest moves on with them.
        var firstTarget = frame.Target;
        for (int i = 0; i < 30; i++)
        {
            frame = game.Frame();
        }
        Assert.True(frame.Target.X > firstTarget.X + 0.05f, $"the view did not follow the balls: {firstTarget} to {frame.Target}");
        Assert.True(frame.Eye.X < frame.Target.X, "the view is not behind the shot's line");
        Assert.InRange(frame.Eye.Z, (float)(CueClearance.RailTop(game.Scene.Table) + CameraNode.RailMargin) - 1e-4f, (float)ChaseView.MaxHeight + 1e-4f);
        game.Window.Press(CameraNode.OverheadKey);   // the key switches to the view from above
        Assert.True(camera.Overhead);
        frame = game.Frame();
        var (eye, target) = CameraNode.OverheadView(game.Scene.Table, frame.Width, frame.Height, frame.FovYDegrees);
        Assert.Equal(eye, frame.Eye);
        Assert.Equal(target, frame.Target);
        game.Window.Press(CameraNode.OverheadKey);   // and back to following
        Assert.False(camera.Overhead);
        frame = game.Frame();
        Assert.Equal(camera.Chase.Eye, frame.Eye);
        game.RunUntilRest();
        frame = game.Frame();
        Assert.False(camera.Overhead);
        Assert.False(camera.Following);
        Assert.Equal(game.World.Physics.CueBallPosition.ToVector3(), frame.Target);
        // Behind the cue ball: the cue ball lies between the eye and the aim, which still points along +x.
        Assert.True(frame.Eye.X < frame.Target.X);
    }

    [Theory]
    [InlineData(1280, 720)]
    [InlineData(1920, 1080)]
    [InlineData(1024, 768)]
    public void The_overhead_view_frames_the_whole_table_below_the_hud_band(int width, int height)
    {
        var table = TableSpec.FromPreset("pool-9ft");
        var (eye, target) = CameraNode.OverheadView(table, width, height, CameraNode.FovYDegrees);
        var vp = RenderMath.View(eye, target) * RenderMath.Projection(CameraNode.FovYDegrees, (float)width / height);
        float hx = (float)table.HalfLength + TableModelGenerator.CushionDepth + TableModelGenerator.RailWidth;
        float hy = (float)table.HalfWidth + TableModelGenerator.CushionDepth + TableModelGenerator.RailWidth;
        foreach (var corner in new[] { new System.Numerics.Vector3(-hx, -hy, 0), new(hx, -hy, 0), new(hx, hy, 0), new(-hx, hy, 0) })
        {
            var p = RenderMath.ToPixel(vp, corner, width, height)!.Value;
            Assert.InRange(p.X, 0, width);
            Assert.InRange(p.Y, CameraNode.HudBand * height, height);
        }
    }
}

public class CueRailTests
{
    [Fact]
    public void The_cue_is_lifted_over_a_ball_behind_the_cue_ball_drawn_so_and_struck_so()
    {
        // The 2 lies 2.2 R behind the cue ball on the aim line (the cue points along +x at the start).
        string json = """
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
              "balls": [ { "id": "cue", "position": [0.0, 0.0] }, { "id": "2", "position": [-0.062865, 0.0] }, { "id": "1", "position": [0.6, 0.0] } ] }
            """;
        using var game = new TestGame(SceneLoader.Parse(json, "t.json"));
        var cue = game.World.Tree.Find<CueNode>()!;
        var frame = game.Frame();
        double r = game.World.Physics.BallRadius;
        double over = CueClearance.BallElevationDegrees(new Vec3(0, 0, r), new Vec3(1, 0, 0), new Vec3(-0.062865, 0, r), r);
        Assert.True(over > 30, $"{over} deg");
        Assert.Equal(over, cue.EffectiveElevationDegrees, 6);
        Assert.Equal((float)over, frame.Cue.ElevationDegrees, 3);
        Assert.Contains(frame.Hud!.Lines, l => l.Contains("(over a ball)", StringComparison.Ordinal));
        game.World.Physics.Strike(cue.MakeShot(2));
        Assert.Equal(over, Assert.Single(game.Simulation.Strikes).ElevationDeg, 6);
    }

    [Fact]
    public void The_raised_elevation_is_drawn_and_fed_into_the_strike()
    {
        string json = """
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
              "balls": [ { "id": "cue", "position": [-1.2, 0.0] }, { "id": "1", "position": [0.6, 0.0] } ] }
            """;
        using var game = new TestGame(SceneLoader.Parse(json, "t.json"));
        var cue = game.World.Tree.Find<CueNode>()!;
        var frame = game.Frame();
        Assert.Equal(0, cue.ElevationDegrees);
        Assert.True(cue.EffectiveElevationDegrees > 10);
        Assert.Equal((float)cue.EffectiveElevationDegrees, frame.Cue.ElevationDegrees, 4);
        Assert.Contains(frame.Hud!.Lines, l => l.Contains("(over the rail)", StringComparison.Ordinal));
        game.World.Physics.Strike(cue.MakeShot(2));
        Assert.Equal(cue.EffectiveElevationDegrees, Assert.Single(game.Simulation.Strikes).ElevationDeg, 9);
    }
}

public class PowerTests
{
    [Fact]
    public void A_push_polled_in_one_frame_is_timed_over_that_frame_not_as_instant()
    {
        var tracker = new StrokeTracker { MinimumInterval = 0.050 };
        tracker.Begin(300, 1.0);
        tracker.Move(400, 1.0);      // back 100 px, delivered with the push in one poll
        tracker.Move(350, 1.0);      // forward: d = 50
        double? speed = tracker.Move(290, 1.0);
        // d = 50 px over one 50 ms frame: 50 / 50 * 250 = 250 cm/s, not the 800 cap.
        Assert.Equal(250, speed!.Value, 9);
    }

    [Fact]
    public void Pushes_of_different_speeds_give_the_speeds_between_the_extremes()
    {
        var speeds = new List<double>();
        foreach (double seconds in new[] { 0.4, 0.2, 0.1, 0.05, 0.025 })
        {
            var tracker = new StrokeTracker { MinimumInterval = 1.0 / 60 };
            tracker.Begin(300, 0);
            tracker.Move(400, 0.1);
            tracker.Move(399, 0.2);                 // the forward move starts the timer: d = 99 px
            double? s = tracker.Move(299, 0.2 + seconds);
            speeds.Add(s!.Value);
        }
        // 99 px at 250 / t(ms): 61.9, 123.8, 247.5, 495, 800 (capped) cm/s.
        Assert.Equal([99 * 250 / 400.0, 99 * 250 / 200.0, 99 * 250 / 100.0, 99 * 250 / 50.0, 800], speeds.Select(v => Math.Round(v, 6)));
    }

    [Fact]
    public void The_hud_shows_a_power_meter_while_stroking_and_the_shot_after()
    {
        using var game = new TestGame();
        game.Frame();
        game.Window.Press(Key.S);
        game.Clock.Now = 10;
        game.Window.MoveTo(400, 300);
        game.Window.Down();
        game.Clock.Now = 10.1;
        game.Window.MoveTo(400, 400);              // back 100 px
        var frame = game.Host.RunFrame();
        Assert.False(frame.Hud!.Power!.Pushing);
        Assert.Equal(100 / (SeedControls.MaxPullBack / SeedControls.PullBackMetresPerPixel), frame.Hud.Power.Fraction, 5);
        game.Clock.Now = 10.2;
        game.Window.MoveTo(400, 380);              // forward: measuring, d = 80
        game.Clock.Now = 10.25;
        game.Window.MoveTo(400, 340);              // 40 px forward in 50 ms
        frame = game.Host.RunFrame();
        Assert.True(frame.Hud!.Power!.Pushing);
        Assert.StartsWith("Power ", frame.Hud.Power.Label, StringComparison.Ordinal);
        game.Clock.Now = 10.3;
        game.Window.MoveTo(400, 290);              // past the start: strike
        game.Window.Up();
        frame = game.Frame();
        var shot = Assert.Single(game.Simulation.Strikes);
        Assert.Equal($"Shot {shot.Speed:0.00} m/s", frame.Hud!.Power!.Label);
        Assert.Equal(shot.Speed / HudNode.MaxStrokeSpeed, frame.Hud.Power.Fraction, 5);
    }
}

public class HelpOverlayTests
{
    [Fact]
    public void Long_help_lines_wrap_at_spaces_and_keep_their_indentation()
    {
        var lines = HudRenderer.Wrap(["  S   shot: hold the left button and push", "short"], 20);
        Assert.All(lines, l => Assert.True(l.Length <= 20, l));
        Assert.Equal("short", lines[^1]);
        Assert.Equal("shot: hold the left button and push", string.Join(" ", lines.Take(lines.Count - 1).Select(l => l.Trim())).Replace("S   ", "", StringComparison.Ordinal));
        Assert.StartsWith("    ", lines[1], StringComparison.Ordinal);
    }
}
