using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallCushion;

/// <summary>
/// The frame of a cushion impact: x along the bed normal into the cushion, z up, y = z x x, and the
/// contact above the ball's centre at angle theta, sin(theta) = h / R - 1. Velocities and spins (a
/// pseudovector) transform alike under this proper rotation.
/// </summary>
internal readonly struct CushionFrame
{
    private readonly Vec3 _ex;
    private readonly Vec3 _ey;

    /// <summary>The frame of a cushion whose bed normal points from the cushion towards the ball, at contact height <paramref name="height"/> (m).</summary>
    public CushionFrame(Vec3 normal, double height, double radius)
    {
        _ex = -normal.XY.Normalized();
        _ey = new Vec3(-_ex.Y, _ex.X, 0);
        SinTheta = Math.Clamp(height / radius - 1, -1, 1);
        CosTheta = Math.Sqrt(1 - SinTheta * SinTheta);
    }

    /// <summary>sin(theta) of the contact above the centre.</summary>
    public double SinTheta { get; }

    /// <summary>cos(theta) of the contact above the centre.</summary>
    public double CosTheta { get; }

    /// <summary>Unit normal of the contact, from the ball's centre into the cushion, in the frame.</summary>
    public Vec3 ContactNormal => new(CosTheta, 0, SinTheta);

    /// <summary>A world vector in the frame.</summary>
    public Vec3 In(Vec3 world) => new(Vec3.Dot(world, _ex), Vec3.Dot(world, _ey), world.Z);

    /// <summary>A frame vector in the world.</summary>
    public Vec3 Out(Vec3 local) => _ex * local.X + _ey * local.Y + new Vec3(0, 0, local.Z);
}
