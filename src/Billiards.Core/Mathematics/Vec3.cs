using System.Runtime.CompilerServices;

namespace Billiards.Core.Mathematics;

/// <summary>
/// A double-precision 3-vector. The standard model keeps its whole state in double precision
/// so that the fixed-step and event-based solvers agree to round-off; System.Numerics only
/// offers single-precision vectors, which the thesis model and the renderer use.
/// </summary>
public readonly record struct Vec3(double X, double Y, double Z)
{
    /// <summary>The zero vector.</summary>
    public static Vec3 Zero => default;

    /// <summary>The unit vector along +z (up, away from the bed).</summary>
    public static Vec3 UnitZ => new(0, 0, 1);

    /// <summary>Sum.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 operator +(Vec3 a, Vec3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    /// <summary>Difference.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 operator -(Vec3 a, Vec3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    /// <summary>Negation.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 operator -(Vec3 a) => new(-a.X, -a.Y, -a.Z);

    /// <summary>Scaling.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 operator *(Vec3 a, double s) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Scaling.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 operator *(double s, Vec3 a) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Division by a scalar.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 operator /(Vec3 a, double s) => new(a.X / s, a.Y / s, a.Z / s);

    /// <summary>Dot product.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Dot(Vec3 a, Vec3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    /// <summary>Cross product a x b.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 Cross(Vec3 a, Vec3 b) =>
        new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

    /// <summary>Euclidean length.</summary>
    public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);

    /// <summary>Squared length.</summary>
    public double LengthSquared => X * X + Y * Y + Z * Z;

    /// <summary>Length of the projection onto the bed (the xy plane).</summary>
    public double LengthXY => Math.Sqrt(X * X + Y * Y);

    /// <summary>This vector with z set to 0.</summary>
    public Vec3 XY => new(X, Y, 0);

    /// <summary>The unit vector along this one, or zero for the zero vector.</summary>
    public Vec3 Normalized()
    {
        double l = Length;
        return l > 0 ? this / l : Zero;
    }

    /// <summary>True when every component is finite (no NaN, no infinity).</summary>
    public bool IsFinite => double.IsFinite(X) && double.IsFinite(Y) && double.IsFinite(Z);

    /// <summary>"(x, y, z)" with round-trip numbers. (A record struct's own ToString would print
    /// <see cref="XY"/>, itself a Vec3, and recurse without end.)</summary>
    public override string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"({X:R}, {Y:R}, {Z:R})");

    /// <summary>A single-precision copy, for the renderer.</summary>
    public System.Numerics.Vector3 ToVector3() => new((float)X, (float)Y, (float)Z);
}
