using System.Numerics;
using Billiards.App.Camera;
using Billiards.App.Rendering;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.App.Input.Modes;

/// <summary>Moving the cue ball with the mouse (seed 4.4.5, Formel 34-35).</summary>
public static class CueBallMover
{
    /// <summary>
    /// Formel 34: f = bed-plane unit vector from the camera to the ball, s = f's perpendicular to
    /// the right, p = p_old - dy * f + dx * s (one seed unit, 1 cm, per pixel), then clamped to
    /// the bed so that the ball stays between the cushion noses.
    /// </summary>
    /// <param name="ball">The ball's centre (m).</param>
    /// <param name="eye">The camera's position (m).</param>
    /// <param name="dx">Mouse movement to the right (pixels).</param>
    /// <param name="dy">Mouse movement down (pixels); moving the mouse up pushes the ball away from the camera.</param>
    /// <param name="table">The table, for the clamp.</param>
    /// <param name="radius">Ball radius (m).</param>
    /// <returns>The new centre (m), at the same height.</returns>
    public static Vec3 Move(Vec3 ball, Vec3 eye, double dx, double dy, TableSpec table, double radius) =>
        MoveAlong(ball, ViewMath.BedForward(eye, ball), dx, dy, table, radius);

    /// <summary>As <see cref="Move"/>, with f given: the bed-plane unit vector the camera looks along.</summary>
    public static Vec3 MoveAlong(Vec3 ball, Vec3 f, double dx, double dy, TableSpec table, double radius)
    {
        var s = ViewMath.BedRight(f);
        var p = ball + (-dy * f + dx * s) * SeedControls.MoveMetresPerPixel;
        return ClampToBed(p, table, radius);
    }

    /// <summary>
    /// The drag in a view drawn: the ball moves as the bed under the pointer does, i.e. by the
    /// bed's points under the ball's pixel and under that pixel moved by (dx, dy), so that in any
    /// view (behind the ball or from above) it follows the pointer at the bed's own scale there
    /// (a few millimetres a pixel behind the ball rather than the seed's centimetre); clamped to the
    /// bed. Null when the ball or the moved pixel has no point of the bed in the view (above the horizon).
    /// </summary>
    /// <param name="ball">The ball's centre (m).</param>
    /// <param name="viewProjection">The view-projection the player sees.</param>
    /// <param name="width">Framebuffer width (pixels).</param>
    /// <param name="height">Framebuffer height (pixels).</param>
    /// <param name="dx">Pointer movement to the right (pixels).</param>
    /// <param name="dy">Pointer movement down (pixels).</param>
    /// <param name="table">The table, for the clamp.</param>
    /// <param name="radius">Ball radius (m).</param>
    public static Vec3? MoveOnBed(Vec3 ball, Matrix4x4 viewProjection, int width, int height, double dx, double dy, TableSpec table, double radius)
    {
        if (RenderMath.ToPixel(viewProjection, ball.ToVector3(), width, height) is not { } at
            || RenderMath.ToPlane(viewProjection, at, width, height, (float)ball.Z) is not { } from
            || RenderMath.ToPlane(viewProjection, at + new Vector2((float)dx, (float)dy), width, height, (float)ball.Z) is not { } to)
        {
            return null;
        }
        var shift = to - from;
        return ClampToBed(ball + new Vec3(shift.X, shift.Y, 0), table, radius);
    }

    /// <summary>Clamps a centre into the bed (m): |x| ≤ L/2 - R, |y| ≤ W/2 - R.</summary>
    public static Vec3 ClampToBed(Vec3 p, TableSpec table, double radius)
    {
        double maxX = table.HalfLength - radius;
        double maxY = table.HalfWidth - radius;
        return new Vec3(Math.Clamp(p.X, -maxX, maxX), Math.Clamp(p.Y, -maxY, maxY), p.Z);
    }
}
