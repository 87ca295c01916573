using System.Numerics;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Thesis;

/// <summary>
/// Between the scene's frame (SI: metres, x along the length towards the foot, y across to the
/// left, z up) and the seed's (centimetres, x the same, Y up, the bed in the XZ plane):
/// SI (x, y, z) = seed (x, -z, y) / 100. Both frames are right-handed, so the map is a rotation
/// (a quarter turn about x) and a scale; it applies to positions, velocities and the vector part
/// of orientation quaternions alike.
/// </summary>
public static class SeedFrame
{
    /// <summary>Centimetres per metre.</summary>
    public const double CentimetresPerMetre = 100;

    /// <summary>An SI position (m) or velocity (m/s) in the seed's frame (cm, cm/s).</summary>
    public static Vector3 FromSi(Vec3 v) =>
        new((float)(v.X * CentimetresPerMetre), (float)(v.Z * CentimetresPerMetre), (float)(-v.Y * CentimetresPerMetre));

    /// <summary>A seed position (cm) or velocity (cm/s) in SI (m, m/s).</summary>
    /// <remarks>Adding +0.0 turns the -0 that negating a zero gives into +0, so results do not print "-0".</remarks>
    public static Vec3 ToSi(Vector3 v) =>
        new(v.X / CentimetresPerMetre, -v.Z / CentimetresPerMetre + 0.0, v.Y / CentimetresPerMetre);

    /// <summary>A rotation in the seed's frame as the same rotation in the SI frame.</summary>
    public static Quaternion ToSi(Quaternion q) => new(q.X, -q.Z, q.Y, q.W);
}
