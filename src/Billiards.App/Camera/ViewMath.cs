using System.Numerics;
using Billiards.Core.Mathematics;

namespace Billiards.App.Camera;

/// <summary>
/// View and projection helpers for a <see cref="Rendering.RenderFrame"/>'s Eye, Target and FovY:
/// the renderer and the game agree on them here (right-handed, z up, metres).
/// </summary>
public static class ViewMath
{
    /// <summary>World up: Core is z-up.</summary>
    public static Vector3 Up => Vector3.UnitZ;

    /// <summary>Near clipping plane (m): closer than the nearest zoom (0.1 m) less a ball radius.</summary>
    public const float Near = 0.02f;

    /// <summary>Far clipping plane (m): the farthest zoom (4 m) plus a 9 ft table's diagonal and margin.</summary>
    public const float Far = 20f;

    /// <summary>The view matrix of a camera looking from eye to target with z up (System.Numerics, row vectors).</summary>
    public static Matrix4x4 View(Vector3 eye, Vector3 target) => Matrix4x4.CreateLookAt(eye, target, Up);

    /// <summary>A perspective projection for a vertical field of view (deg) and a framebuffer size (pixels).</summary>
    public static Matrix4x4 Projection(float fovYDegrees, int width, int height) =>
        Matrix4x4.CreatePerspectiveFieldOfView(fovYDegrees * MathF.PI / 180f, width / (float)Math.Max(height, 1), Near, Far);

    /// <summary>
    /// The unit direction from the eye towards a point, flattened onto the bed (z = 0): the seed's
    /// "forward" for aiming (seed 4.4.3) and for moving the cue ball (Formel 34, f). Returns
    /// +x when the eye is straight above the point.
    /// </summary>
    public static Vec3 BedForward(Vec3 eye, Vec3 point)
    {
        var d = (point - eye).XY;
        double length = d.Length;
        return length > 1e-12 ? d / length : new Vec3(1, 0, 0);
    }

    /// <summary>The bed-plane unit vector to the right of <paramref name="forward"/> seen from above with z up (Formel 34, s).</summary>
    public static Vec3 BedRight(Vec3 forward) => new(forward.Y, -forward.X, 0);

    /// <summary>The aim angle of a bed-plane direction (deg, from +x counter-clockwise), as <see cref="Billiards.Core.Cue.ShotSpec"/> wants it.</summary>
    public static double AimDegrees(Vec3 direction) => DeterministicMath.Atan2(direction.Y, direction.X) * 180 / Math.PI;
}
