using System.Numerics;

namespace Billiards.App.Rendering;

/// <summary>
/// The camera matrices the renderer uses (System.Numerics row vectors: clip = p * View * Projection),
/// and the projection of a world point to pixels, so that tests aim exactly where the renderer draws.
/// </summary>
public static class RenderMath
{
    /// <summary>Near clipping distance (m).</summary>
    public const float Near = 0.02f;

    /// <summary>Far clipping distance (m).</summary>
    public const float Far = 40f;

    /// <summary>A right-handed look-at view with z up (x up when looking straight down or up).</summary>
    public static Matrix4x4 View(Vector3 eye, Vector3 target)
    {
        var forward = target - eye;
        if (forward.LengthSquared() < 1e-12f)
        {
            forward = Vector3.UnitX;
            target = eye + forward;
        }
        var dir = Vector3.Normalize(forward);
        var up = MathF.Abs(dir.Z) > 0.9999f ? Vector3.UnitX : Vector3.UnitZ;
        return Matrix4x4.CreateLookAt(eye, target, up);
    }

    /// <summary>An OpenGL perspective projection (clip z in [-w, w]) with vertical field of view in degrees.</summary>
    public static Matrix4x4 Projection(float fovYDegrees, float aspect, float near = Near, float far = Far)
    {
        float f = 1 / MathF.Tan(fovYDegrees * MathF.PI / 360);
        return new Matrix4x4(
            f / aspect, 0, 0, 0,
            0, f, 0, 0,
            0, 0, (far + near) / (near - far), -1,
            0, 0, 2 * far * near / (near - far), 0);
    }

    /// <summary>The view-projection of a frame.</summary>
    public static Matrix4x4 ViewProjection(RenderFrame frame) => ViewProjection(frame, frame.Width, frame.Height);

    /// <summary>The view-projection of a frame drawn on a target of <paramref name="width"/> x <paramref name="height"/> pixels.</summary>
    public static Matrix4x4 ViewProjection(RenderFrame frame, int width, int height)
    {
        ArgumentNullException.ThrowIfNull(frame);
        var vp = View(frame.Eye, frame.Target) * Projection(frame.FovYDegrees, (float)width / Math.Max(1, height));
        return frame.TopInset > 0 ? vp * BelowHud(frame.TopInset) : vp;
    }

    /// <summary>
    /// The share of a window's height (<paramref name="height"/> pixels) the scoreboard takes along
    /// the top edge: the camera frames its view below it, so that nothing the player plays lies under it.
    /// </summary>
    public static float HudInset(int height) => height <= 0 ? 0 : MathF.Min(0.3f, HudRenderer.BoardUnits * HudRenderer.Scale(height) / (float)height);

    /// <summary>
    /// Clip space squeezed below a band of <paramref name="inset"/> of the height at the top: the
    /// camera's whole view, shrunk by (1 - inset) about the bottom edge's middle, so that what the
    /// camera frames lies below the band and the band shows only more of the room.
    /// </summary>
    public static Matrix4x4 BelowHud(float inset)
    {
        float k = 1 - inset;
        return new Matrix4x4(
            k, 0, 0, 0,
            0, k, 0, 0,
            0, 0, 1, 0,
            0, -inset, 0, 1);
    }

    /// <summary>
    /// Pixel coordinates (x right, y down from the top-left corner) of a world point, or null
    /// when it is behind the camera.
    /// </summary>
    public static Vector2? ToPixel(Matrix4x4 viewProjection, Vector3 point, int width, int height)
    {
        var clip = Vector4.Transform(new Vector4(point, 1), viewProjection);
        if (clip.W <= 1e-6f)
        {
            return null;
        }
        float x = clip.X / clip.W, y = clip.Y / clip.W;
        return new Vector2((x + 1) / 2 * width, (1 - y) / 2 * height);
    }

    /// <summary>
    /// The point of the horizontal plane at height <paramref name="z"/> (m) under a pixel (x right,
    /// y down), or null when the pixel's ray does not meet the plane in front of the camera: the
    /// inverse of <see cref="ToPixel"/> for points on the bed (dragging a ball under the cursor).
    /// </summary>
    public static Vector3? ToPlane(Matrix4x4 viewProjection, Vector2 pixel, int width, int height, float z)
    {
        if (width <= 0 || height <= 0 || !Matrix4x4.Invert(viewProjection, out var inverse))
        {
            return null;
        }
        float x = (2 * pixel.X / width) - 1, y = 1 - (2 * pixel.Y / height);
        var near = Vector4.Transform(new Vector4(x, y, -1, 1), inverse);
        var far = Vector4.Transform(new Vector4(x, y, 1, 1), inverse);
        if (MathF.Abs(near.W) < 1e-12f || MathF.Abs(far.W) < 1e-12f)
        {
            return null;
        }
        var a = new Vector3(near.X, near.Y, near.Z) / near.W;
        var b = new Vector3(far.X, far.Y, far.Z) / far.W;
        float dz = b.Z - a.Z;
        if (MathF.Abs(dz) < 1e-9f)
        {
            return null;
        }
        float t = (z - a.Z) / dz;
        return t < 0 ? null : a + (t * (b - a));
    }

    /// <summary>Converts an sRGB colour component to linear light.</summary>
    public static float ToLinear(float c) => c <= 0.04045f ? c / 12.92f : MathF.Pow((c + 0.055f) / 1.055f, 2.4f);

    /// <summary>Converts an sRGB colour to linear light.</summary>
    public static Vector3 ToLinear(Vector3 c) => new(ToLinear(c.X), ToLinear(c.Y), ToLinear(c.Z));

    /// <summary>
    /// The default camera for a table: behind the head rail, raised, looking down the table, as
    /// close as lets the rails fill 94% of the frame, the table centred in the picture.
    /// </summary>
    public static (Vector3 Eye, Vector3 Target) DefaultCamera(Billiards.Core.Table.TableSpec table, float aspect, float fovYDegrees)
    {
        float hx = (float)table.HalfLength + TableModelGenerator.CushionDepth + TableModelGenerator.RailWidth;
        float hy = (float)table.HalfWidth + TableModelGenerator.CushionDepth + TableModelGenerator.RailWidth;
        const float Elevation = 44 * MathF.PI / 180;
        var direction = new Vector3(-MathF.Cos(Elevation), 0, MathF.Sin(Elevation));
        Vector3[] corners = [new(-hx, -hy, 0.04f), new(hx, -hy, 0.04f), new(hx, hy, 0.04f), new(-hx, hy, 0.04f)];
        var target = Vector3.Zero;
        float distance = 3;
        for (int pass = 0; pass < 4; pass++)
        {
            float lo = 0.3f, hi = 40f;
            for (int iteration = 0; iteration < 40; iteration++)
            {
                float mid = (lo + hi) / 2;
                var (min, max) = NdcBounds(View(target + (mid * direction), target) * Projection(fovYDegrees, aspect), corners);
                bool fits = min.X > -0.94f && min.Y > -0.94f && max.X < 0.94f && max.Y < 0.94f;
                (lo, hi) = fits ? (lo, mid) : (mid, hi);
            }
            distance = hi;
            // Centre the table vertically: move the target along the bed by the picture's offset.
            var (low, high) = NdcBounds(View(target + (distance * direction), target) * Projection(fovYDegrees, aspect), corners);
            float offset = (low.Y + high.Y) / 2;
            target.X += offset * distance * MathF.Tan(fovYDegrees * MathF.PI / 360) / MathF.Sin(Elevation);
        }
        return (target + (distance * direction), target);
    }

    private static (Vector2 Min, Vector2 Max) NdcBounds(Matrix4x4 viewProjection, Vector3[] points)
    {
        var min = new Vector2(float.MaxValue);
        var max = new Vector2(float.MinValue);
        foreach (var p in points)
        {
            var clip = Vector4.Transform(new Vector4(p, 1), viewProjection);
            var ndc = clip.W > 1e-6f ? new Vector2(clip.X, clip.Y) / clip.W : new Vector2(float.MaxValue);
            min = Vector2.Min(min, ndc);
            max = Vector2.Max(max, ndc);
        }
        return (min, max);
    }
}
