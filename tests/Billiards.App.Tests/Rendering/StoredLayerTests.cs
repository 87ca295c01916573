using System.Numerics;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Rendering;

/// <summary>
/// The table, the balls at rest and the HUD are kept between frames while they stand still
/// (<see cref="StaticLayer"/>, <see cref="HudLayer"/>). A frame put back from them must show what
/// drawing it afresh shows, and anything that moves must show at once.
/// </summary>
public sealed class StoredLayerTests : IDisposable
{
    private const int Width = 480, Height = 300;
    private const float R = 0.028575f;

    // One sample: the layers serve a single-sampled target like a window on a software rasteriser.
    private readonly OffscreenRenderer _renderer;

    public StoredLayerTests()
    {
        try
        {
            _renderer = new OffscreenRenderer(samples: 1);
        }
        catch (InvalidOperationException first)
        {
            TestDisplay.Ensure(first.Message);
            _renderer = new OffscreenRenderer(samples: 1);
        }
    }

    public void Dispose() => _renderer.Dispose();

    private static RenderFrame Frame(Vector3 oneAt)
    {
        var frame = new RenderFrame
        {
            Table = TableSpec.FromPreset("pool-9ft"),
            Width = Width,
            Height = Height,
            Eye = new Vector3(-1.7f, 0, 1.3f),
            Target = new Vector3(0.15f, 0, 0),
            Hud = new HudInfo(["Player 1: open table", "FPS: 60"], Vector2.Zero, ShowHelp: true, HelpLines: ["H or F1  help", "Escape   menu"]),
        };
        frame.Balls.Add(new BallVisual(PoolBalls.Cue, new Vector3(-0.5f, 0, R), Quaternion.Identity));
        frame.Balls.Add(new BallVisual(new BallId(1), oneAt, Quaternion.Identity));
        frame.Balls.Add(new BallVisual(new BallId(8), new Vector3(0.7f, 0.1f, R), Quaternion.Identity));
        return frame;
    }

    /// <summary>Mean of one colour channel over the 5 x 5 pixels round a point.</summary>
    private static double Mean(byte[] pixels, Vector2 at, int channel)
    {
        double sum = 0;
        for (int dy = -2; dy <= 2; dy++)
        {
            for (int dx = -2; dx <= 2; dx++)
            {
                sum += pixels[((((int)at.Y + dy) * Width) + (int)at.X + dx) * 4 + channel];
            }
        }
        return sum / 25;
    }

    /// <summary>Largest difference of any colour channel between two frames (0..255).</summary>
    private static int MaxDifference(byte[] a, byte[] b)
    {
        int max = 0;
        for (int i = 0; i < a.Length; i++)
        {
            max = Math.Max(max, Math.Abs(a[i] - b[i]));
        }
        return max;
    }

    [Fact]
    public void AStillFrameDrawnFromTheStoredLayersMatchesTheFrameDrawnAfresh()
    {
        var at = new Vector3(0.3f, -0.3f, R);
        byte[] fresh = _renderer.Render(Frame(at));
        _renderer.Render(Frame(at));
        long layers = _renderer.Renderer.LayersReused, hud = _renderer.Renderer.HudReused;
        byte[] stored = _renderer.Render(Frame(at));

        Assert.True(_renderer.Renderer.LayersReused > layers, "the third still frame did not come from the stored table and balls");
        Assert.True(_renderer.Renderer.HudReused > hud, "the third still frame did not come from the stored HUD");
        // The HUD is stored with premultiplied alpha in 8 bits: one step of rounding at most.
        Assert.InRange(MaxDifference(fresh, stored), 0, 1);
    }

    [Theory]
    [InlineData(5)]
    [InlineData(12)]
    [InlineData(32)]
    [InlineData(57)]
    public void TheElevationDiagramFromTheStoredHudMatchesItDrawnAfresh(float elevation)
    {
        // The cue's line in the diagram is a tilted quad: above about 10 deg its bounding box held
        // whole squares it does not cover, and those were copied from the stored layer as black.
        var at = new Vector3(0.3f, -0.3f, R);
        RenderFrame WithGauges()
        {
            // At 720 lines the HUD's scale is 2: the diagram's quarter circle is 88 px across.
            var frame = Frame(at);
            frame.Width = 1280;
            frame.Height = 720;
            frame.Hud = frame.Hud! with { ShowHelp = false, Gauges = new Billiards.App.Hud.CueGauges(Vector2.Zero, elevation, 0.5f) };
            return frame;
        }
        byte[] fresh = _renderer.Render(WithGauges());
        _renderer.Render(WithGauges());
        long hud = _renderer.Renderer.HudReused;
        byte[] stored = _renderer.Render(WithGauges());
        Assert.True(_renderer.Renderer.HudReused > hud, "the third still frame did not come from the stored HUD");
        Assert.InRange(MaxDifference(fresh, stored), 0, 1);
    }

    [Fact]
    public void TheHudStaysStoredWhileTheAimLineFollowsAMovingView()
    {
        var at = new Vector3(0.3f, -0.3f, R);
        RenderFrame WithAimLine(float x)
        {
            var frame = Frame(at);
            frame.Hud = frame.Hud! with { ShowHelp = false, Aids = [new AidShape(new Vector2(x, 200), new Vector2(x + 200, 150), 0, Vector4.One)] };
            return frame;
        }
        _renderer.Render(WithAimLine(100));
        _renderer.Render(WithAimLine(110));
        long hud = _renderer.Renderer.HudReused;
        byte[] later = _renderer.Render(WithAimLine(120));

        Assert.True(_renderer.Renderer.HudReused > hud, "a moved aim line redrew the stored HUD");
        // The line is drawn where it now is: across its middle's column some pixel is near white
        // (the cloth around it is green, its red channel low).
        int reddest = Enumerable.Range(170, 11).Max(y => (int)later[((y * Width) + 220) * 4]);
        Assert.True(reddest > 180, $"no aim line at its new place (red at most {reddest})");
    }

    [Fact]
    public void TheHelpOverlayOpensAgainFromItsStoredLayerAndTheHudStaysStored()
    {
        var at = new Vector3(0.3f, -0.3f, R);
        var open = Frame(at);
        var closed = Frame(at);
        closed.Hud = closed.Hud! with { ShowHelp = false };
        for (int i = 0; i < 3; i++)
        {
            _renderer.Render(open);
        }
        _renderer.Render(closed);
        long help = _renderer.Renderer.HelpReused, hud = _renderer.Renderer.HudReused;
        byte[] reopened = _renderer.Render(open);

        Assert.True(_renderer.Renderer.HelpReused > help, "the reopened help overlay was drawn afresh");
        Assert.True(_renderer.Renderer.HudReused > hud, "opening the help overlay redrew the HUD");
        using var afresh = new OffscreenRenderer(samples: 1);
        Assert.InRange(MaxDifference(afresh.Render(open), reopened), 0, 1);
    }

    [Fact]
    public void ABallThatMovesShowsAtOnceAndItsOldPlaceIsCloth()
    {
        var from = new Vector3(0.3f, -0.3f, R);
        var to = new Vector3(0.0f, 0.35f, R);
        for (int i = 0; i < 3; i++)
        {
            _renderer.Render(Frame(from));
        }
        byte[] moved = _renderer.Render(Frame(to));
        // A second renderer with nothing stored draws the moved frame afresh.
        using var afresh = new OffscreenRenderer(samples: 1);
        byte[] expected = afresh.Render(Frame(to));
        Assert.InRange(MaxDifference(expected, moved), 0, 1);
        var vp = RenderMath.ViewProjection(Frame(to));
        var old = RenderMath.ToPixel(vp, from, Width, Height)!.Value;
        int o = (((int)old.Y * Width) + (int)old.X) * 4;
        Assert.True(moved[o + 1] > moved[o] && moved[o + 1] > moved[o + 2], $"the old place of ball 1 is not cloth green: {moved[o]} {moved[o + 1]} {moved[o + 2]}");
    }

    [Fact]
    public void AMovingCameraIsDrawnAtReducedResolutionAndAStillOneAtFullResolution()
    {
        var renderer = _renderer.Renderer;
        renderer.DynamicResolution = true;
        try
        {
            var at = new Vector3(0.3f, -0.3f, R);
            var first = Frame(at);
            _renderer.Render(first);
            var moved = Frame(at);
            moved.Eye += new Vector3(0.05f, 0.02f, 0);
            long reduced = renderer.ReducedFrames;
            byte[] moving = _renderer.Render(moved);
            Assert.Equal(reduced + 1, renderer.ReducedFrames);
            // A view that stands still stays reduced for a moment (a dragged camera stands still
            // between the mouse's reports), then is drawn sharp.
            for (int k = 1; k < Renderer.StillFramesToSharpen; k++)
            {
                _renderer.Render(moved);
            }
            Assert.Equal(reduced + Renderer.StillFramesToSharpen, renderer.ReducedFrames);
            byte[] still = _renderer.Render(moved);
            Assert.Equal(reduced + Renderer.StillFramesToSharpen, renderer.ReducedFrames);
            // The reduced frame is the same picture, softer: each ball in its place and colour.
            var vp = RenderMath.ViewProjection(moved);
            foreach (var ball in moved.Balls)
            {
                var p = RenderMath.ToPixel(vp, ball.Position, Width, Height)!.Value;
                for (int c = 0; c < 3; c++)
                {
                    Assert.InRange(Math.Abs(Mean(moving, p, c) - Mean(still, p, c)), 0, 25);
                }
            }
            Assert.True(MaxDifference(moving, still) > 0, "the moving frame was not drawn differently");
        }
        finally
        {
            renderer.DynamicResolution = false;
        }
    }

    [Theory]
    [InlineData(2f)]
    [InlineData(9f)]
    [InlineData(25f)]
    [InlineData(70f)]
    [InlineData(160f)]
    public void ASphereHasTheFewestSlicesWhoseOutlineStaysWithinHalfAPixel(float radiusPixels)
    {
        int n = Renderer.SlicesFor(radiusPixels);
        static float Sagitta(float r, int slices) => r * (1 - MathF.Cos(MathF.PI / slices));
        int index = Array.IndexOf(Renderer.SphereSlices, n);
        Assert.True(index >= 0);
        if (index < Renderer.SphereSlices.Length - 1)
        {
            Assert.True(Sagitta(radiusPixels, n) <= Renderer.OutlineTolerancePixels, $"{n} slices leave {Sagitta(radiusPixels, n)} px at r = {radiusPixels} px");
        }
        if (index > 0)
        {
            Assert.True(Sagitta(radiusPixels, Renderer.SphereSlices[index - 1]) > Renderer.OutlineTolerancePixels, $"fewer than {n} slices would do at r = {radiusPixels} px");
        }
    }

    [Fact]
    public void ABallsRadiusOnScreenFollowsThePinholeCamera()
    {
        var frame = Frame(new Vector3(0.3f, -0.3f, R));
        var ball = new Vector3(0.2f, 0.1f, R);
        float d = Vector3.Distance(ball, frame.Eye);
        float expected = R * 0.5f * Height / MathF.Tan(frame.FovYDegrees * MathF.PI / 360) / d;
        Assert.Equal(expected, Renderer.RadiusPixels(ball, frame, R), 3);
        // The same against two projected points on the ball's rim, perpendicular to the view.
        var vp = RenderMath.ViewProjection(frame);
        var up = Vector3.Normalize(Vector3.Cross(Vector3.Cross(ball - frame.Eye, Vector3.UnitZ), ball - frame.Eye));
        var a = RenderMath.ToPixel(vp, ball + (R * up), Width, Height)!.Value;
        var b = RenderMath.ToPixel(vp, ball - (R * up), Width, Height)!.Value;
        Assert.InRange(Vector2.Distance(a, b) / 2, expected * 0.97f, expected * 1.03f);
    }
}
