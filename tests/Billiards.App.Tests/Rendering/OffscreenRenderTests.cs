using System.Numerics;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Table;
using Xunit.Abstractions;

namespace Billiards.App.Tests.Rendering;

[Collection("GL")]
public class OffscreenRenderTests(GlFixture gl, ITestOutputHelper output)
{
    private const int Width = 640, Height = 400;

    private enum Hue { Other, White, Black, Yellow, Blue, Red, Green }

    // The number discs are on the ball's x axis: turned to +-y they face neither the camera nor the lamps.
    private static readonly Quaternion s_sideways = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2);

    private static RenderFrame KnownFrame()
    {
        const float R = 0.028575f;
        var frame = new RenderFrame
        {
            Table = TableSpec.FromPreset("pool-9ft"),
            Width = Width,
            Height = Height,
            Eye = new Vector3(-1.7f, 0, 1.3f),
            Target = new Vector3(0.15f, 0, 0),
        };
        frame.Balls.Add(new BallVisual(PoolBalls.Cue, new Vector3(-0.5f, 0, R), s_sideways));
        frame.Balls.Add(new BallVisual(new BallId(1), new Vector3(0.3f, -0.3f, R), s_sideways));
        frame.Balls.Add(new BallVisual(new BallId(2), new Vector3(0.3f, 0, R), s_sideways));
        frame.Balls.Add(new BallVisual(new BallId(3), new Vector3(0.3f, 0.3f, R), s_sideways));
        frame.Balls.Add(new BallVisual(new BallId(8), new Vector3(0.7f, 0.1f, R), s_sideways));
        return frame;
    }

    [Fact]
    public void RenderDrawsEachBallInItsColourOnGreenCloth()
    {
        var frame = KnownFrame();
        byte[] pixels = gl.Renderer.Render(frame);
        output.WriteLine(gl.Renderer.Description);
        Assert.Equal(Width * Height * 4, pixels.Length);
        var vp = RenderMath.ViewProjection(frame);
        var expected = new Dictionary<int, Hue> { [0] = Hue.White, [1] = Hue.Yellow, [2] = Hue.Blue, [3] = Hue.Red, [8] = Hue.Black };
        foreach (var ball in frame.Balls)
        {
            var centre = RenderMath.ToPixel(vp, ball.Position, Width, Height)!.Value;
            var hue = Dominant(pixels, centre, 2);
            Assert.True(expected[ball.Id.Value] == hue, $"ball {ball.Id} at pixel {centre}: expected {expected[ball.Id.Value]}, found {hue}");
        }
        foreach (var spot in new[] { new Vector3(-0.2f, 0.35f, 0), new Vector3(0.9f, -0.4f, 0), new Vector3(-0.9f, 0, 0) })
        {
            var pixel = RenderMath.ToPixel(vp, spot, Width, Height)!.Value;
            Assert.Equal(Hue.Green, Dominant(pixels, pixel, 2));
        }
        // Not a blank frame: many different colours.
        var distinct = new HashSet<int>();
        for (int i = 0; i < pixels.Length; i += 4)
        {
            distinct.Add((pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2]);
        }
        Assert.True(distinct.Count > 500, $"only {distinct.Count} colours");
    }

    [Fact]
    public void RenderHidesInvisibleBallsAndDrawsTheCue()
    {
        var frame = KnownFrame();
        var vp = RenderMath.ViewProjection(frame);
        var two = frame.Balls[2];
        frame.Balls[2] = two with { Visible = false };
        var cueBall = frame.Balls[0];
        // The cue points along +x at the cue ball, so it lies behind it (towards the camera).
        frame.Cue = new CueVisual(true, cueBall.Position, Vector3.UnitX, 8, 0.1f, Vector2.Zero);
        byte[] pixels = gl.Renderer.Render(frame);
        var at = RenderMath.ToPixel(vp, two.Position, Width, Height)!.Value;
        Assert.Equal(Hue.Green, Dominant(pixels, at, 1));
        // A point on the cue's shaft, 0.25 m behind the tip, is drawn in maple, not cloth.
        var shaft = Vector3.Transform(new Vector3(-0.25f, 0, 0), Primitives.CuePlacement(frame.Cue, frame.BallRadius));
        var pixel = RenderMath.ToPixel(vp, shaft, Width, Height)!.Value;
        var (r, g, b) = Pixel(pixels, (int)pixel.X, (int)pixel.Y);
        Assert.True(r > g && g > b && r > 120, $"cue shaft pixel ({r},{g},{b})");
    }

    [Fact]
    public void TheScoreboardStaysInABandAlongTheTopEdgeAndTheDeveloperLinesWaitForTheirKey()
    {
        var frame = KnownFrame();
        byte[] plain = gl.Renderer.Render(frame);
        var cards = new[]
        {
            new Billiards.App.Hud.PlayerCard("Anna", true, "solids: 1 2 3 4 5 6 7", [1, 2, 3, 4, 5, 6, 7], ""),
            new Billiards.App.Hud.PlayerCard("Ben (computer)", false, "stripes: 9 10 11 12 13 14 15", [9, 10, 11, 12, 13, 14, 15], "fouls in a row 2"),
        };
        string longRuling = "Foul by Anna: the cue ball was pocketed and the cue ball first touched the 11, not a legal target. Warning: Anna has two fouls in a row.";
        var board = new Billiards.App.Hud.Scoreboard("8-ball  shot 12  games 0-1", "H help", cards, "Call: 3 in foot-left (B, C);  Space shoots, G hint", longRuling, ["Ben shoots again.", "Anna is at the table."]);
        frame.Hud = new HudInfo(["Mode: view [V]", "FPS: 60"], Vector2.Zero, false, []) { Board = board };
        byte[] drawn = gl.Renderer.Render(frame);
        (int Top, int Below) Changed(byte[] a, byte[] b)
        {
            int top = 0, below = 0;
            for (int y = 0; y < Height; y++)
            {
                for (int x = 0; x < Width; x++)
                {
                    int i = ((y * Width) + x) * 4;
                    if (Math.Abs(a[i] - b[i]) + Math.Abs(a[i + 1] - b[i + 1]) + Math.Abs(a[i + 2] - b[i + 2]) > 30)
                    {
                        _ = y < Height / 4 ? top++ : below++;
                    }
                }
            }
            return (top, below);
        }
        var (inBand, outside) = Changed(plain, drawn);
        Assert.True(inBand > 2000, $"the scoreboard changed {inBand} pixels in the top quarter");
        Assert.Equal(0, outside);

        // F2: the developer lines, under the band.
        frame.Hud = frame.Hud with { Developer = true };
        var (top, below) = Changed(drawn, gl.Renderer.Render(frame));
        Assert.True(top + below > 100, $"the developer lines changed {top + below} pixels");
    }

    [Fact]
    public void RenderDrawsTheHudAndTheCollisionDebugLines()
    {
        var frame = KnownFrame();
        byte[] plain = gl.Renderer.Render(frame);
        frame.Hud = new HudInfo(["Mode: SHOT", "Speed 2.50 m/s"], new Vector2(0.5f, 0.5f), true, ["v  view", "s  shot", "e  effet"])
        {
            Gauges = new Billiards.App.Hud.CueGauges(new Vector2(0.5f, 0.5f), 5, 0.4f),
        };
        frame.ShowCollisionGeometry = true;
        var a = new Vector3(-0.3f, -0.4f, 0.001f);
        frame.CollisionTriangles = [new DebugTriangle(a, a + new Vector3(0.4f, 0, 0), a + new Vector3(0, 0.3f, 0), Vector3.UnitZ)];
        byte[] drawn = gl.Renderer.Render(frame);

        // The text panel at the top left darkens or lights pixels there.
        int changed = 0;
        for (int y = 4; y < 40; y++)
        {
            for (int x = 4; x < 150; x++)
            {
                int i = ((y * Width) + x) * 4;
                changed += Math.Abs(plain[i] - drawn[i]) + Math.Abs(plain[i + 1] - drawn[i + 1]) > 30 ? 1 : 0;
            }
        }
        Assert.True(changed > 200, $"HUD changed {changed} pixels");

        // The spin point is a red dot on the white diagram at the bottom right.
        bool redDot = false;
        for (int y = Height - 100; y < Height; y++)
        {
            for (int x = Width - 100; x < Width; x++)
            {
                var (r, g, b) = Pixel(drawn, x, y);
                redDot |= r > 180 && g < 60 && b < 60;
            }
        }
        Assert.True(redDot, "no spin point");

        // The debug triangle's edge from a to a + 0.4 x is red.
        var vp = RenderMath.ViewProjection(frame);
        var mid = RenderMath.ToPixel(vp, a + new Vector3(0.2f, 0, 0), Width, Height)!.Value;
        bool redLine = false;
        for (int dy = -2; dy <= 2; dy++)
        {
            var (r, g, b) = Pixel(drawn, (int)mid.X, (int)mid.Y + dy);
            redLine |= r > 150 && g < 90 && b < 90;
        }
        Assert.True(redLine, "no red collision edge");
    }

    /// <summary>Green channel averaged over a square of pixels round a point on the bed.</summary>
    private static double Green(byte[] pixels, Matrix4x4 vp, Vector3 onBed, int radius)
    {
        var at = RenderMath.ToPixel(vp, onBed, Width, Height)!.Value;
        double sum = 0;
        int n = 0;
        for (int dy = -radius; dy <= radius; dy++)
        {
            for (int dx = -radius; dx <= radius; dx++)
            {
                sum += Pixel(pixels, (int)at.X + dx, (int)at.Y + dy).G;
                n++;
            }
        }
        return sum / n;
    }

    [Fact]
    public void RenderTheClothIsTexturedNotOneFlatColour()
    {
        // The lamps' light varies smoothly over the bed (a few levels over hundreds of pixels); the
        // cloth's weave and mottle change from one pixel to the next. Mean absolute difference of
        // horizontal neighbours in a patch of open cloth, green channel.
        var frame = KnownFrame();
        frame.Balls.Clear();
        frame.Eye = new Vector3(-0.6f, 0, 0.5f);
        frame.Target = new Vector3(-0.2f, 0, 0);
        byte[] pixels = gl.Renderer.Render(frame);
        var centre = RenderMath.ToPixel(RenderMath.ViewProjection(frame), new Vector3(-0.25f, 0, 0), Width, Height)!.Value;
        double differences = 0;
        int n = 0;
        var levels = new HashSet<int>();
        for (int y = (int)centre.Y - 30; y < (int)centre.Y + 30; y++)
        {
            for (int x = (int)centre.X - 60; x < (int)centre.X + 60; x++)
            {
                var (r, g, b) = Pixel(pixels, x, y);
                Assert.Equal(Hue.Green, Classify(r, g, b));
                differences += Math.Abs(g - Pixel(pixels, x + 1, y).G);
                levels.Add(g);
                n++;
            }
        }
        double mean = differences / n;
        output.WriteLine($"cloth: mean neighbour difference {mean:F2} levels, {levels.Count} green levels");
        Assert.True(mean > 0.8, $"the cloth is flat: neighbours differ by {mean:F2} levels on average");
        Assert.True(levels.Count >= 12, $"the cloth has only {levels.Count} green levels");
    }

    [Fact]
    public void RenderABallCastsAShadowOnTheClothAwayFromTheLamps()
    {
        // A ball at y = 0.4 m: the lamps hang over the long axis (y = 0), so its shadow falls
        // outwards, towards +y, and at its foot. Both are darker than open cloth at the same
        // distance from the lamps on the other side of the long axis.
        var frame = KnownFrame();
        frame.Balls.Clear();
        var ball = new Vector3(0.1f, 0.4f, frame.BallRadius);
        frame.Balls.Add(new BallVisual(new BallId(2), ball, s_sideways));
        frame.Eye = new Vector3(-1.2f, 0, 1.4f);
        frame.Target = new Vector3(0.1f, 0.2f, 0);
        var vp = RenderMath.ViewProjection(frame);
        byte[] pixels = gl.Renderer.Render(frame);
        float r = frame.BallRadius;
        double open = Green(pixels, vp, new Vector3(ball.X, -ball.Y - (1.15f * r), 0), 1);
        double outside = Green(pixels, vp, new Vector3(ball.X, ball.Y + (1.15f * r), 0), 1);
        output.WriteLine($"open cloth {open:F1}, beside the ball away from the lamps {outside:F1}");
        Assert.True(outside < 0.85 * open, $"no shadow beside the ball: {outside:F1} against {open:F1} on open cloth");
    }

    [Fact]
    public void RenderABallInTheAirCastsAFainterSofterShadowTheHigherItIs()
    {
        // A ball straight under the middle lamp at several heights, seen from above and to the
        // side; each frame divided by the same frame without the ball. The shadow's darkest point
        // lightens and the part of the bed in deep shadow (under 70 % of its light) shrinks as the
        // ball rises, while its faint edge keeps its reach: an area light's shadow softening.
        var frame = KnownFrame();
        frame.Balls.Clear();
        frame.Eye = new Vector3(0, -0.9f, 1.3f);
        frame.Target = new Vector3(0, 0, 0);
        var vp = RenderMath.ViewProjection(frame);
        byte[] bare = gl.Renderer.Render(frame);
        float r = frame.BallRadius;
        var points = new List<Vector2>();
        for (float y = -0.12f; y <= 0.12f; y += 0.004f)
        {
            for (float x = -0.12f; x <= 0.12f; x += 0.004f)
            {
                points.Add(new Vector2(x, y));
            }
        }
        double[] heights = [r, 0.06, 0.12, 0.24];
        var darkest = new double[heights.Length];
        var deep = new int[heights.Length];
        var touched = new int[heights.Length];
        for (int k = 0; k < heights.Length; k++)
        {
            frame.Balls.Clear();
            frame.Balls.Add(new BallVisual(new BallId(2), new Vector3(0, 0, (float)heights[k]), s_sideways));
            byte[] pixels = gl.Renderer.Render(frame);
            darkest[k] = 1;
            foreach (var p in points)
            {
                var at = RenderMath.ToPixel(vp, new Vector3(p, 0), Width, Height)!.Value;
                var (pr, pg, pb) = Pixel(pixels, (int)at.X, (int)at.Y);
                if (Classify(pr, pg, pb) != Hue.Green)
                {
                    continue; // the ball itself
                }
                double ratio = pg / (double)Math.Max(1, Pixel(bare, (int)at.X, (int)at.Y).G);
                darkest[k] = Math.Min(darkest[k], ratio);
                deep[k] += ratio < 0.7 ? 1 : 0;
                touched[k] += ratio < 0.97 ? 1 : 0;
            }
            output.WriteLine($"ball at {heights[k]:F3} m: darkest {darkest[k]:F2} of the light, {deep[k]} points in deep shadow, {touched[k]} darkened at all");
        }
        for (int k = 1; k < heights.Length; k++)
        {
            Assert.True(darkest[k] > darkest[k - 1], $"the shadow at {heights[k]} m is no fainter than at {heights[k - 1]} m");
        }
        // On the bed the ball hides the middle of its own shadow from this camera: the deep
        // shadow's shrinking is counted from the first height in the air.
        for (int k = 2; k < heights.Length; k++)
        {
            Assert.True(deep[k] < deep[k - 1] || deep[k] == 0, $"the deep shadow at {heights[k]} m ({deep[k]}) is not smaller than at {heights[k - 1]} m ({deep[k - 1]})");
        }
        // Softer, not gone: the lightened shadow still covers about as much of the bed.
        Assert.True(touched[^1] > 0.8 * touched[1], $"the shadow at {heights[^1]} m covers {touched[^1]} points against {touched[1]} at {heights[1]} m");
        // Still a shadow at 24 cm: the ball is not drawn without one.
        Assert.True(darkest[^1] < 0.95, $"no shadow under the ball at {heights[^1]} m");
    }

    private static (int R, int G, int B) Pixel(byte[] pixels, int x, int y)
    {
        int i = ((y * Width) + x) * 4;
        return (pixels[i], pixels[i + 1], pixels[i + 2]);
    }

    private static Hue Classify(int r, int g, int b)
    {
        int max = Math.Max(r, Math.Max(g, b)), min = Math.Min(r, Math.Min(g, b));
        if (min > 150)
        {
            return Hue.White;
        }
        if (max < 50)
        {
            return Hue.Black;
        }
        if (r > 120 && g > 90 && b < g * 0.6)
        {
            return Hue.Yellow;
        }
        if (b > r + 30 && b > g + 15)
        {
            return Hue.Blue;
        }
        if (r > 100 && g < r * 0.45 && b < r * 0.45)
        {
            return Hue.Red;
        }
        if (g > r + 25 && g > b + 10)
        {
            return Hue.Green;
        }
        return Hue.Other;
    }

    /// <summary>The most frequent hue in a square around a pixel.</summary>
    private static Hue Dominant(byte[] pixels, Vector2 at, int radius)
    {
        var counts = new Dictionary<Hue, int>();
        for (int dy = -radius; dy <= radius; dy++)
        {
            for (int dx = -radius; dx <= radius; dx++)
            {
                var (r, g, b) = Pixel(pixels, Math.Clamp((int)at.X + dx, 0, Width - 1), Math.Clamp((int)at.Y + dy, 0, Height - 1));
                var hue = Classify(r, g, b);
                counts[hue] = counts.GetValueOrDefault(hue) + 1;
            }
        }
        return counts.MaxBy(kv => kv.Value).Key;
    }
}
