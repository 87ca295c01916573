using System.Globalization;
using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Rendering;
using Billiards.App.Tests.Game;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Hud;

/// <summary>
/// The scoreboard never covers what the player plays: over ten shipped positions of 8-ball, 10-ball
/// and snooker, seen from behind the cue as a game opens, the called ball (or the ball the aim line
/// meets) and its pocket lie below the scoreboard's band, and the rendered HUD (its panels and text)
/// changes none of the called ball's pixels; and in three positions at the head (baulk) end, the
/// called ball would lie under the band if the camera framed the whole window.
/// </summary>
[Collection("GL")]
public sealed class HudFramingTests(GlFixture gl)
{
    public static TheoryData<string> Positions =>
    [
        "eight-ball.json", "rules/eight-ball-break.json", "positions/eight-ball-in-hand.json", "positions/eight-ball-open-table.json",
        "positions/eight-ball-stripes.json", "rules/eight-ball-on-the-eight.json", "games/eight-ball-last-balls.json",
        "positions/ten-ball-corner.json", "positions/nine-ball-side-pocket.json", "snooker.json",
        .. NearEnd.Keys,
    ];

    // Positions the framing below the scoreboard must save: the cue ball against the head (baulk)
    // cushion, so the camera behind it looks down steeply up the table, and the called ball and its
    // pocket near that end, high in the view. Framed over the whole window instead, the called ball
    // lies under the scoreboard's band.
    private static readonly Dictionary<string, string> NearEnd = new()
    {
        ["near-end: the 3 into the head-left corner"] = Position("pool-9ft", "eight-ball", [-1.236, -0.3], """{ "id": "3", "position": [-1.1, 0.4] }, { "id": "8", "position": [0.9, 0.3] }"""),
        ["near-end: the 3 into the side pocket"] = Position("pool-9ft", "eight-ball", [-1.236, -0.3], """{ "id": "3", "position": [-1.1, 0.6] }, { "id": "8", "position": [0.9, 0.3] }"""),
        ["near-end: a red into the baulk corner, the brown on its spot"] = Position("snooker-12ft", "snooker", [-1.752, -0.3], """{ "id": "red-1", "position": [-1.56, 0.6] }, { "id": "brown", "position": [-1.047, 0.0] }, { "id": "black", "position": [1.46, 0.0] }"""),
    };

    private static string Position(string preset, string rules, double[] cue, string balls) => $$"""
        { "format": "billiards-scene/1", "name": "near end", "table": { "preset": "{{preset}}" },
          "balls": [ { "id": "cue", "position": [{{cue[0].ToString(CultureInfo.InvariantCulture)}}, {{cue[1].ToString(CultureInfo.InvariantCulture)}}] }, {{balls}} ],
          "game": { "rules": "{{rules}}", "players": ["Anna", "Ben"], "shooter": 0, "shot": 3 } }
        """;

    private static (TestGame Game, RenderFrame Frame, BallId Ball, Vector3? Pocket) Open(string file, int width, int height)
    {
        var scene = NearEnd.TryGetValue(file, out var json) ? SceneLoader.Parse(json, "near-end.json") : SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", file));
        var rules = scene.PlayedAs ?? throw new InvalidOperationException($"{file} names no game");
        var game = new TestGame(scene, new MatchSetup(rules, [new Seat("Player 1"), new Seat("Player 2")]));
        game.Window.FramebufferSize = (width, height);
        var frame = game.Frame();
        frame = game.Frame();
        frame.BallSet = scene.BallSet; // the fake simulation's set is pool's
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        var aim = game.World.Tree.Root.GetInTree<AimLineNode>();
        BallId? ball = match.Call.CurrentCall?.Ball ?? match.Call.CurrentNomination?.Ball ?? aim.Preview?.Ball;
        Assert.True(ball is not null, $"{file}: no called ball and the aim line meets none");
        Vector3? pocket = null;
        var table = scene.Table;
        var pocketId = match.Call.CurrentCall?.Pocket ?? aim.Preview?.Pocket;
        if (pocketId is { } p && p.Index >= 0 && p.Index < table.Pockets.Count)
        {
            var m = table.Pockets[p.Index].MouthMiddle(table);
            pocket = new Vector3((float)m.X, (float)m.Y, 0);
        }
        return (game, frame, ball.Value, pocket);
    }

    [Theory]
    [MemberData(nameof(Positions))]
    public void TheCalledBallAndItsPocketLieBelowTheScoreboard(string file)
    {
        foreach (var (width, height) in new[] { (1280, 720), (900, 560) })
        {
            var (game, frame, ball, pocket) = Open(file, width, height);
            using (game)
            {
                float band = HudRenderer.BoardUnits * HudRenderer.Scale(height);
                var vp = RenderMath.ViewProjection(frame);
                var visual = frame.Balls.Single(b => b.Id == ball);
                var at = RenderMath.ToPixel(vp, visual.Position, width, height)!.Value;
                Assert.True(at.Y > band && at.Y < height && at.X > 0 && at.X < width, $"{file} at {width}x{height}: the {ball.Value} at {at} (band {band} px)");
                if (pocket is { } p)
                {
                    var pp = RenderMath.ToPixel(vp, p, width, height)!.Value;
                    Assert.True(pp.Y > band, $"{file} at {width}x{height}: its pocket at {pp} under the band of {band} px");
                }
            }
        }
    }

    [Theory]
    [MemberData(nameof(Positions))]
    public void TheCalledBallsPixelsShowInTheRenderedFrame(string file)
    {
        const int Width = 640, Height = 360;
        var (game, frame, ball, _) = Open(file, Width, Height);
        using (game)
        {
            // The HUD's panels and text (not the aim aids, which mark the ball on purpose) over the frame, and the frame bare.
            frame.Hud = frame.Hud! with { Aids = null };
            var with = gl.Renderer.Render(frame);
            var visual = frame.Balls.Single(b => b.Id == ball);
            var at = RenderMath.ToPixel(RenderMath.ViewProjection(frame), visual.Position, Width, Height)!.Value;
            frame.Hud = null;
            var without = gl.Renderer.Render(frame);
            // The ball's middle, 5 x 5 pixels round its centre: none changed by the HUD.
            int differ = 0, inside = 0;
            for (int dy = -2; dy <= 2; dy++)
            {
                for (int dx = -2; dx <= 2; dx++)
                {
                    int x = (int)at.X + dx, y = (int)at.Y + dy;
                    if (x < 0 || y < 0 || x >= Width || y >= Height)
                    {
                        continue;
                    }
                    inside++;
                    int i = ((y * Width) + x) * 4;
                    int d = Math.Abs(with[i] - without[i]) + Math.Abs(with[i + 1] - without[i + 1]) + Math.Abs(with[i + 2] - without[i + 2]);
                    differ += d > 24 ? 1 : 0;
                }
            }
            Assert.True(inside == 25 && differ == 0, $"{file}: the {ball.Value} at {at}: {differ} of its {inside} pixels in the window are covered by the HUD");
        }
    }
}
