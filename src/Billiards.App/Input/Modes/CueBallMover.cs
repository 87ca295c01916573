using Billiards.App.Camera;
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

    /// <summary>Clamps a centre into the bed (m): |x| ≤ L/2 - R, |y| ≤ W/2 - R.</summary>
    public static Vec3 ClampToBed(Vec3 p, TableSpec table, double radius)
    {
        double maxX = table.HalfLength - radius;
        double maxY = table.HalfWidth - radius;
        return new Vec3(Math.Clamp(p.X, -maxX, maxX), Math.Clamp(p.Y, -maxY, maxY), p.Z);
    }
}
