using System.Numerics;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace Billiards.Core.Physics.Thesis;

// The triangles' corners on the bed (x, z) in lanes of eight, for the level-line cull of
// FindNearestHit (structure of arrays, padded to whole lanes).
internal sealed class RailCull
{
    public const int Lanes = 8;

    private readonly float[] _x1, _z1, _x2, _z2, _x3, _z3;

    public RailCull(ReadOnlySpan<CollisionGeometry> rails)
    {
        Count = rails.Length;
        int padded = (Count + Lanes - 1) / Lanes * Lanes;
        _x1 = new float[padded];
        _z1 = new float[padded];
        _x2 = new float[padded];
        _z2 = new float[padded];
        _x3 = new float[padded];
        _z3 = new float[padded];
        for (int k = 0; k < Count; k++)
        {
            var g = rails[k];
            (_x1[k], _z1[k], _x2[k], _z2[k], _x3[k], _z3[k]) = (g.P1.X, g.P1.Z, g.P2.X, g.P2.Z, g.P3.X, g.P3.Z);
            Extent = MathF.Max(Extent, MathF.Max(MathF.Abs(g.P1.X) + MathF.Abs(g.P1.Z),
                MathF.Max(MathF.Abs(g.P2.X) + MathF.Abs(g.P2.Z), MathF.Abs(g.P3.X) + MathF.Abs(g.P3.Z))));
        }
    }

    public int Count { get; }

    // Largest |x| + |z| of any corner (cm).
    public float Extent { get; }

    // Bit b set: triangle k + b is not clearly beside the level line through p along v (its
    // three corners' sides, (c - p) x v, are not all beyond the margin with one sign).
    public uint Near(int k, Vector256<float> px, Vector256<float> pz, Vector256<float> vx, Vector256<float> vz,
        Vector256<float> above, Vector256<float> below)
    {
        var s1 = (Load(_x1, k) - px) * vz - (Load(_z1, k) - pz) * vx;
        var s2 = (Load(_x2, k) - px) * vz - (Load(_z2, k) - pz) * vx;
        var s3 = (Load(_x3, k) - px) * vz - (Load(_z3, k) - pz) * vx;
        var left = Vector256.GreaterThan(s1, above) & Vector256.GreaterThan(s2, above) & Vector256.GreaterThan(s3, above);
        var right = Vector256.LessThan(s1, below) & Vector256.LessThan(s2, below) & Vector256.LessThan(s3, below);
        return ~(left | right).ExtractMostSignificantBits() & 0xFFu;
    }

    private static Vector256<float> Load(float[] lane, int k) =>
        Vector256.LoadUnsafe(ref MemoryMarshal.GetArrayDataReference(lane), (nuint)k);
}
