using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Game;

public class AimLineTests
{
    [Fact]
    public void TheLineRunsToTheGhostBallDrawsItsRingAndTheObjectBallsDirectionAndLHidesIt()
    {
        using var game = new TestGame(); // practice: the line starts on
        var frame = game.Frame();
        var aids = frame.Hud!.Aids!;
        var line = game.World.Tree.Find<AimLineNode>()!;
        Assert.True(line.Visible);
        // Aiming along +x from (-0.635, 0) at the 1 on (0.635, 0): a full hit, the ghost ball 2R short of it.
        double r = game.World.Physics.BallRadius;
        Assert.Equal(new BallId(1), line.Preview!.Ball);
        Assert.Equal(0.635 - (2 * r), line.Preview.Ghost.X, 9);
        var vp = RenderMath.ViewProjection(frame);
        Vector2 Pixel(double x) => RenderMath.ToPixel(vp, new Vector3((float)x, 0, (float)r), frame.Width, frame.Height)!.Value;
        var ring = Assert.Single(aids, a => a.Radius > 0);
        Assert.Equal(Pixel(0.635 - (2 * r)), ring.A);
        var lines = aids.Where(a => a.Radius == 0).ToList();
        Assert.Equal(2, lines.Count);
        Assert.Equal(Pixel(-0.635 + r), lines[0].A);   // from the cue ball's front
        Assert.Equal(ring.A, lines[0].B);              // to the ghost ball
        Assert.Equal(Pixel(0.635), lines[1].A);        // the 1 goes on along +x
        Assert.Equal(Pixel(0.635 + AimLineNode.ObjectLineLength), lines[1].B);
        // The ring is a ball's radius across at the ghost ball's distance.
        Assert.InRange(ring.Radius, 1, 60);

        game.Window.Press(AimLineNode.ToggleKey);
        Assert.Empty(game.Frame().Hud!.Aids!);
        game.Window.Press(AimLineNode.ToggleKey);
        Assert.NotEmpty(game.Frame().Hud!.Aids!);
    }

    [Fact]
    public void APathThatMeetsNoBallStopsAtTheCushionAndShowsItsMirrorBank()
    {
        using var game = new TestGame(); // cue ball (-0.635, 0), the 1 on (0.635, 0)
        var camera = game.World.Tree.Find<Billiards.App.Camera.CameraNode>()!;
        camera.Camera.SetPhi((30 * Math.PI / 180) + Math.PI);   // aim 30 deg: past the 1, to the side cushion
        var frame = game.Frame();
        var line = game.World.Tree.Find<AimLineNode>()!;
        double r = game.World.Physics.BallRadius;
        var table = game.Scene.Table;
        Assert.Null(line.Preview!.Ball);
        // The cue ball touches the side cushion where its centre is R inside the nose line.
        double s = (table.HalfWidth - r) / Math.Sin(30 * Math.PI / 180);
        Assert.Equal(table.HalfWidth - r, line.Preview.Ghost.Y, 9);
        Assert.Equal(-0.635 + (s * Math.Cos(30 * Math.PI / 180)), line.Preview.Ghost.X, 9);
        // The bank: the y component turned round, BankLength long.
        var bank = line.Preview.Bank!.Value;
        Assert.Equal(line.Preview.Ghost.X + (AimPreview.BankLength * Math.Cos(30 * Math.PI / 180)), bank.X, 9);
        Assert.Equal(line.Preview.Ghost.Y - (AimPreview.BankLength * Math.Sin(30 * Math.PI / 180)), bank.Y, 9);
        var vp = RenderMath.ViewProjection(frame);
        var lines = frame.Hud!.Aids!.Where(a => a.Radius == 0).ToList();
        Assert.Equal(2, lines.Count);
        Assert.Equal(lines[0].B, lines[1].A);
        Assert.Equal(RenderMath.ToPixel(vp, new Vector3((float)bank.X, (float)bank.Y, (float)r), frame.Width, frame.Height)!.Value, lines[1].B);
        Assert.DoesNotContain(frame.Hud.Aids!, a => a.Radius > 0);
    }

    [Fact]
    public void TheObjectBallsLineStopsWhereTheBallReachesTheCushion()
    {
        string json = """
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
              "balls": [ { "id": "cue", "position": [0.5, 0.0] }, { "id": "1", "position": [1.0, 0.0] } ] }
            """;
        using var game = new TestGame(Billiards.Core.Scenes.SceneLoader.Parse(json, "t.json"));
        var frame = game.Frame();
        double r = game.World.Physics.BallRadius;
        var vp = RenderMath.ViewProjection(frame);
        var lines = frame.Hud!.Aids!.Where(a => a.Radius == 0).ToList();
        double stop = game.Scene.Table.HalfLength - r;
        Assert.True(stop < 1.0 + AimLineNode.ObjectLineLength);
        Assert.Equal(RenderMath.ToPixel(vp, new Vector3((float)stop, 0, (float)r), frame.Width, frame.Height)!.Value, lines[1].B);
    }

    [Fact]
    public void NothingIsDrawnWhileTheBallsRoll()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        Assert.Empty(game.Frame().Hud!.Aids!);
    }

    [Theory]
    [InlineData("Anna", "Ben", false)]
    [InlineData("Anna", "cpu:3", false)]
    [InlineData("Anna", "cpu:2", true)]
    [InlineData("computer:1", "Ben", true)]
    public void InAMatchItStartsOnOnlyAgainstAComputerOfLevelTwoOrLess(string a, string b, bool on)
    {
        var players = new[] { Seat.Parse(a, 0)!, Seat.Parse(b, 1)! };
        var scene = TestScenes.TwoBalls(rules: "eight-ball");
        using var host = new GameHost(scene, TestScenes.Create, new FakeWindow(), new ManualClock(), new MatchSetup(GameRules.EightBall, players));
        Assert.Equal(on, host.Tree.Root.GetInTree<AimLineNode>().Visible);
    }
}

public class CallLineTests
{
    [Theory]
    [InlineData("nine-ball", "nine-ball", 0, false)]
    [InlineData("nine-ball", "nine-ball", 3, false)]
    [InlineData("eight-ball", "eight-ball", 0, false)]
    [InlineData("eight-ball", "eight-ball", 3, true)]
    [InlineData("ten-ball", "ten-ball", 3, true)]
    public void TheHudShowsACallOnlyWhereTheRulesCallTheShot(string name, GameRules rules, int shot, bool shown)
    {
        var players = new[] { new Seat("Anna"), new Seat("Ben") };
        // A scene's game block sets the shot number.
        var scene = TestScenes.TwoBalls(rules: name) with { Game = new GameState(rules) { Shot = shot, Players = new PerPlayer<string>("Anna", "Ben") } };
        using var host = new GameHost(scene, TestScenes.Create, new FakeWindow(), new ManualClock(), new MatchSetup(rules, players));
        var lines = host.RunFrame().Hud!.Lines;
        Assert.Equal(shot, host.Tree.Root.GetInTree<MatchNode>().Session.State.Shot);
        Assert.Equal(shown, lines.Any(l => l.StartsWith("Call: ", StringComparison.Ordinal)));
        Assert.Contains(lines, l => l.Contains("Space shoots", StringComparison.Ordinal));
    }
}

public class CallPickerTests
{
    [Fact]
    public void AClickOnABallCallsItAndAClickOnAPocketCallsThatPocketADragCallsNothing()
    {
        var players = new[] { new Seat("Anna"), new Seat("Ben") };
        var scene = TestScenes.TwoBalls(rules: "eight-ball") with { Game = new GameState(GameRules.EightBall) { Shot = 3, Players = new PerPlayer<string>("Anna", "Ben") } };
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var clock = new ManualClock();
        using var host = new GameHost(scene, TestScenes.Create, window, clock, new MatchSetup(GameRules.EightBall, players));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        host.RunFrame();
        for (int i = 0; i < 20; i++)
        {
            window.Press(Key.Right); // aim 20 deg off the 1: nothing on the line
        }
        var frame = host.RunFrame();
        // With nothing aimed at, the call defaults to the nearest legal ball: the 1, the only one.
        Assert.Equal(new BallId(1), match.Call.CurrentCall!.Ball);
        var vp = RenderMath.ViewProjection(frame);
        var r = (float)host.World.Physics.BallRadius;
        var ball = RenderMath.ToPixel(vp, new Vector3(0.635f, 0, r), 1280, 720)!.Value;
        var pockets = Billiards.Core.Table.TableGeometry.Build(scene.Table, r).Pockets.ToArray();
        var footLeft = pockets.Single(p => PoolPockets.Set.Id(p.Pocket) == PoolPockets.FootLeft);
        var pocket = RenderMath.ToPixel(vp, footLeft.Centre.ToVector3() with { Z = 0 }, 1280, 720)!.Value;

        window.MoveTo(ball.X, ball.Y);
        window.Down();
        window.Up();
        Assert.Equal(new BallId(1), match.Call.CurrentCall!.Ball);
        window.MoveTo(pocket.X, pocket.Y);
        window.Down();
        window.Up();
        Assert.Equal(new Call(new BallId(1), PoolPockets.FootLeft), match.Call.CurrentCall);
        var footRight = pockets.Single(p => PoolPockets.Set.Id(p.Pocket) == PoolPockets.FootRight);
        var other = RenderMath.ToPixel(vp, footRight.Centre.ToVector3() with { Z = 0 }, 1280, 720)!.Value;
        window.MoveTo(other.X, other.Y);
        window.Down();
        window.Up();
        Assert.Equal(new Call(new BallId(1), PoolPockets.FootRight), match.Call.CurrentCall);

        // A drag that starts on a pocket orbits the camera and calls nothing.
        var left = RenderMath.ToPixel(vp, footLeft.Centre.ToVector3() with { Z = 0 }, 1280, 720)!.Value;
        window.MoveTo(left.X, left.Y);
        window.Down();
        window.MoveTo(left.X + 40, left.Y);
        window.Up();
        Assert.Equal(new Call(new BallId(1), PoolPockets.FootRight), match.Call.CurrentCall);
    }

    [Fact]
    public void AClickOnTheDarkHoleOfAPocketCallsItNotOnlyAClickInItsMouth()
    {
        var players = new[] { new Seat("Anna"), new Seat("Ben") };
        var scene = TestScenes.TwoBalls(rules: "eight-ball") with { Game = new GameState(GameRules.EightBall) { Shot = 3, Players = new PerPlayer<string>("Anna", "Ben") } };
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        using var host = new GameHost(scene, TestScenes.Create, window, new ManualClock(), new MatchSetup(GameRules.EightBall, players));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        host.RunFrame();
        window.Press(Billiards.App.Camera.CameraNode.OverheadKey);
        var frame = host.RunFrame();
        var vp = RenderMath.ViewProjection(frame);
        var r = (float)host.World.Physics.BallRadius;
        var capture = Billiards.Core.Table.TableGeometry.Build(scene.Table, r).Pockets.ToArray()
            .Single(p => PoolPockets.Set.Id(p.Pocket) == PoolPockets.FootRight).Centre;
        // The hole as the table model cuts it: the middle of its floor's rim points round that pocket.
        var floor = TableModelGenerator.Generate(scene.Table).Single(m => m.Material.Name == "pocket_floor").Positions
            .Where(p => Math.Abs(p.X - capture.X) < 0.15 && Math.Abs(p.Y - capture.Y) < 0.15).ToList();
        var hole = new Vector3((floor.Min(p => p.X) + floor.Max(p => p.X)) / 2, (floor.Min(p => p.Y) + floor.Max(p => p.Y)) / 2, 0);
        var holePixel = RenderMath.ToPixel(vp, hole, 1280, 720)!.Value;
        var capturePixel = RenderMath.ToPixel(vp, capture.ToVector3() with { Z = 0 }, 1280, 720)!.Value;
        var captureEdge = RenderMath.ToPixel(vp, capture.ToVector3() with { Z = 0 } + new Vector3(r, 0, 0), 1280, 720)!.Value;
        // The hole's middle lies beyond what a click round the capture circle alone reaches.
        Assert.True(Vector2.Distance(holePixel, capturePixel) > MathF.Max(1.5f * Vector2.Distance(capturePixel, captureEdge), 12),
            $"the hole's middle is {Vector2.Distance(holePixel, capturePixel)} px from the capture circle's");

        match.Call.CallBall(new BallId(1));
        window.MoveTo(holePixel.X, holePixel.Y);
        window.Down();
        window.Up();
        Assert.Equal(new Call(new BallId(1), PoolPockets.FootRight), match.Call.CurrentCall);
    }
}
