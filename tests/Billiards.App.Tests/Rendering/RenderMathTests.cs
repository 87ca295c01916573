using System.Numerics;
using Billiards.App.Rendering;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Rendering;

public class RenderMathTests
{
    [Fact]
    public void ToPixelPutsTheTargetAtTheCentre()
    {
        var vp = RenderMath.View(new Vector3(-2, 0.5f, 1.5f), new Vector3(0.3f, -0.2f, 0)) * RenderMath.Projection(45, 16f / 9);
        var pixel = RenderMath.ToPixel(vp, new Vector3(0.3f, -0.2f, 0), 1280, 720);
        Assert.NotNull(pixel);
        Assert.Equal(640, pixel.Value.X, 2);
        Assert.Equal(360, pixel.Value.Y, 2);
    }

    [Fact]
    public void ToPixelZUpIsUpAndTheRightIsRight()
    {
        // Looking along +x with z up: +z goes up the picture (smaller y), -y goes right.
        var vp = RenderMath.View(Vector3.Zero, Vector3.UnitX) * RenderMath.Projection(60, 1);
        var up = RenderMath.ToPixel(vp, new Vector3(1, 0, 0.2f), 100, 100)!.Value;
        var right = RenderMath.ToPixel(vp, new Vector3(1, -0.2f, 0), 100, 100)!.Value;
        Assert.True(up.Y < 50);
        Assert.Equal(50, up.X, 3);
        Assert.True(right.X > 50);
        Assert.Equal(50, right.Y, 3);
        Assert.Null(RenderMath.ToPixel(vp, new Vector3(-1, 0, 0), 100, 100));
    }

    [Fact]
    public void ProjectionMapsNearAndFarToTheGlDepthRange()
    {
        var p = RenderMath.Projection(45, 1.5f, 0.1f, 10);
        var near = Vector4.Transform(new Vector4(0, 0, -0.1f, 1), p);
        var far = Vector4.Transform(new Vector4(0, 0, -10, 1), p);
        Assert.Equal(-1, near.Z / near.W, 4);
        Assert.Equal(1, far.Z / far.W, 4);
        // The field of view: a point at 22.5 degrees above the axis lands on the top edge.
        var edge = Vector4.Transform(new Vector4(0, MathF.Tan(22.5f * MathF.PI / 180), -1, 1), p);
        Assert.Equal(1, edge.Y / edge.W, 4);
    }

    [Fact]
    public void ViewLookingStraightDownIsStillValid()
    {
        var view = RenderMath.View(new Vector3(0, 0, 3), Vector3.Zero);
        Assert.False(float.IsNaN(view.M11));
        var pixel = RenderMath.ToPixel(view * RenderMath.Projection(45, 1), Vector3.Zero, 100, 100);
        Assert.Equal(50, pixel!.Value.X, 3);
    }

    [Theory]
    [InlineData("pool-9ft", 1280, 720)]
    [InlineData("pool-7ft", 800, 800)]
    [InlineData("thesis", 640, 1000)]
    public void DefaultCameraShowsTheWholeTableFromBehindTheHeadRail(string preset, int width, int height)
    {
        var table = TableSpec.FromPreset(preset);
        var (eye, target) = RenderMath.DefaultCamera(table, (float)width / height, 45);
        Assert.True(eye.X < -(float)table.HalfLength, "the eye is behind the head rail");
        Assert.True(eye.Z > 0.5f, "the eye is above the table");
        var vp = RenderMath.View(eye, target) * RenderMath.Projection(45, (float)width / height);
        float hx = (float)table.HalfLength + 0.18f, hy = (float)table.HalfWidth + 0.18f;
        foreach (var corner in new[] { new Vector3(-hx, -hy, 0), new Vector3(hx, -hy, 0), new Vector3(hx, hy, 0), new Vector3(-hx, hy, 0) })
        {
            var p = RenderMath.ToPixel(vp, corner, width, height)!.Value;
            Assert.InRange(p.X, 0, width);
            Assert.InRange(p.Y, 0, height);
        }
    }

    [Fact]
    public void CuePlacementPutsTheTipPullBackBehindTheContactPoint()
    {
        const float R = 0.028575f;
        var ball = new Vector3(0.2f, 0.1f, R);
        var cue = new CueVisual(true, ball, Vector3.UnitY, 0, 0.05f, Vector2.Zero);
        var m = Primitives.CuePlacement(cue, R);
        var tip = Vector3.Transform(Vector3.Zero, m);
        var butt = Vector3.Transform(new Vector3(-Primitives.CueLength, 0, 0), m);
        Assert.Equal(ball.Y - R - 0.05f, tip.Y, 5);
        Assert.Equal(ball.X, tip.X, 5);
        Assert.Equal(ball.Z, tip.Z, 5);
        Assert.Equal(tip.Y - Primitives.CueLength, butt.Y, 4);

        // Elevated 30 degrees with top spin: the butt rises, the tip touches above the centre.
        var raised = Primitives.CuePlacement(cue with { ElevationDegrees = 30, PullBack = 0, TipOffset = new Vector2(0, 0.5f) }, R);
        var raisedTip = Vector3.Transform(Vector3.Zero, raised);
        var raisedButt = Vector3.Transform(new Vector3(-Primitives.CueLength, 0, 0), raised);
        Assert.Equal(R, Vector3.Distance(raisedTip, ball), 5);
        Assert.True(raisedTip.Z > ball.Z);
        Assert.Equal(ball.Z + (Primitives.CueLength * 0.5f), raisedButt.Z, 1);
    }
}
