using Billiards.Core.Mathematics;

namespace Billiards.App.Audio;

/// <summary>
/// Where the player hears from: the camera's eye, looking at its target, z up. Gives a sound's
/// stereo gains: equal-power pan by the direction's share along the listener's right, and
/// 1/distance beyond <see cref="ReferenceDistance"/>. Sound travel time is left out: 3 m is 9 ms,
/// and the picture shows the collision without it.
/// </summary>
public readonly record struct Listener(Vec3 Eye, Vec3 Target)
{
    /// <summary>Distance (m) within which a sound is not turned down: about where a player stands from the balls.</summary>
    public const double ReferenceDistance = 1.5;

    /// <summary>Left and right gains for a sound at <paramref name="position"/> (m).</summary>
    public (float Left, float Right) Gains(Vec3 position)
    {
        var toSound = position - Eye;
        double distance = toSound.Length;
        var forward = Target - Eye;
        var right = Vec3.Cross(forward, Vec3.UnitZ);
        double side = 0;
        if (distance > 1e-9 && right.Length > 1e-9)
        {
            side = Math.Clamp(Vec3.Dot(toSound / distance, right.Normalized()), -1, 1);
        }
        double angle = (side + 1) * Math.PI / 4;
        double attenuation = ReferenceDistance / Math.Max(ReferenceDistance, distance);
        return ((float)(Math.Cos(angle) * attenuation), (float)(Math.Sin(angle) * attenuation));
    }
}
