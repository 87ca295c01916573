using System.Numerics;

namespace Billiards.App.Rendering;

/// <summary>A material of a generated model, in the terms of a Wavefront MTL file (colours in sRGB).</summary>
/// <param name="Name">Material name.</param>
/// <param name="Diffuse">Kd.</param>
/// <param name="Specular">Ks.</param>
/// <param name="Shininess">Ns (Phong exponent).</param>
public sealed record MeshMaterial(string Name, Vector3 Diffuse, Vector3 Specular, float Shininess);

/// <summary>
/// Collects triangles with per-vertex normals for one material. Triangles are wound
/// counter-clockwise around their normals whatever order they are given in.
/// </summary>
public sealed class MeshBuilder(MeshMaterial material)
{
    /// <summary>The material of every triangle here.</summary>
    public MeshMaterial Material { get; } = material;

    /// <summary>Vertex positions (m).</summary>
    public List<Vector3> Positions { get; } = [];

    /// <summary>Unit normals, one per position.</summary>
    public List<Vector3> Normals { get; } = [];

    /// <summary>Vertex colours, one per position (white unless given).</summary>
    public List<Vector3> Colors { get; } = [];

    /// <summary>Texture coordinates, one per position (zero unless given).</summary>
    public List<Vector2> TexCoords { get; } = [];

    /// <summary>Triangle corners, three per triangle.</summary>
    public List<uint> Indices { get; } = [];

    /// <summary>Adds a vertex and returns its index.</summary>
    public uint Vertex(Vector3 position, Vector3 normal, Vector2 uv = default, Vector3? color = null)
    {
        Positions.Add(position);
        Normals.Add(Vector3.Normalize(normal));
        TexCoords.Add(uv);
        Colors.Add(color ?? Vector3.One);
        return (uint)(Positions.Count - 1);
    }

    /// <summary>Adds a triangle of existing vertices, wound to face along their normals.</summary>
    public void Triangle(uint a, uint b, uint c)
    {
        Vector3 pa = Positions[(int)a], pb = Positions[(int)b], pc = Positions[(int)c];
        Vector3 facing = Vector3.Cross(pb - pa, pc - pa);
        if (facing.LengthSquared() < 1e-20f)
        {
            return;
        }
        Vector3 wanted = Normals[(int)a] + Normals[(int)b] + Normals[(int)c];
        if (Vector3.Dot(facing, wanted) < 0)
        {
            (b, c) = (c, b);
        }
        Indices.Add(a);
        Indices.Add(b);
        Indices.Add(c);
    }

    /// <summary>Adds a flat quad (corners in order around it) facing <paramref name="normal"/>.</summary>
    public void Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d, Vector3 normal)
    {
        uint ia = Vertex(a, normal), ib = Vertex(b, normal), ic = Vertex(c, normal), id = Vertex(d, normal);
        Triangle(ia, ib, ic);
        Triangle(ia, ic, id);
    }

    /// <summary>Adds a quad with a normal per corner (smooth shading).</summary>
    public void Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d, Vector3 na, Vector3 nb, Vector3 nc, Vector3 nd)
    {
        uint ia = Vertex(a, na), ib = Vertex(b, nb), ic = Vertex(c, nc), id = Vertex(d, nd);
        Triangle(ia, ib, ic);
        Triangle(ia, ic, id);
    }

    /// <summary>Adds a flat polygon at height z (any simple outline, either winding) facing up or down.</summary>
    public void Polygon(IReadOnlyList<Vector2> outline, float z, bool up = true)
    {
        var normal = up ? Vector3.UnitZ : -Vector3.UnitZ;
        uint first = (uint)Positions.Count;
        foreach (var p in outline)
        {
            Vertex(new Vector3(p, z), normal);
        }
        foreach (var (a, b, c) in Triangulation.EarClip(outline))
        {
            Triangle(first + (uint)a, first + (uint)b, first + (uint)c);
        }
    }

    /// <summary>Adds a planar convex polygon (corners in order) as a fan.</summary>
    public void ConvexPolygon(IReadOnlyList<Vector3> corners, Vector3 normal)
    {
        uint first = (uint)Positions.Count;
        foreach (var p in corners)
        {
            Vertex(p, normal);
        }
        for (int i = 1; i + 1 < corners.Count; i++)
        {
            Triangle(first, first + (uint)i, first + (uint)i + 1);
        }
    }
}

/// <summary>Triangulation of simple polygons by ear clipping (O(n^2), for outlines of a few hundred points).</summary>
public static class Triangulation
{
    /// <summary>Triangles (indices into <paramref name="outline"/>) covering a simple polygon given in either winding.</summary>
    public static List<(int A, int B, int C)> EarClip(IReadOnlyList<Vector2> outline)
    {
        var result = new List<(int, int, int)>();
        var remaining = Enumerable.Range(0, outline.Count).ToList();
        if (SignedArea(outline) < 0)
        {
            remaining.Reverse();
        }
        int guard = 0;
        while (remaining.Count > 3 && guard++ < outline.Count * outline.Count)
        {
            bool clipped = false;
            for (int i = 0; i < remaining.Count; i++)
            {
                int prev = remaining[(i + remaining.Count - 1) % remaining.Count];
                int cur = remaining[i];
                int next = remaining[(i + 1) % remaining.Count];
                Vector2 a = outline[prev], b = outline[cur], c = outline[next];
                float cross = Cross(b - a, c - b);
                if (cross <= 1e-12f)
                {
                    if (MathF.Abs(cross) <= 1e-12f && Vector2.DistanceSquared(a, c) > 0)
                    {
                        // Collinear point: drop it without a triangle.
                        remaining.RemoveAt(i);
                        clipped = true;
                        break;
                    }
                    continue;
                }
                bool empty = true;
                foreach (int other in remaining)
                {
                    if (other != prev && other != cur && other != next && InTriangle(outline[other], a, b, c))
                    {
                        empty = false;
                        break;
                    }
                }
                if (empty)
                {
                    result.Add((prev, cur, next));
                    remaining.RemoveAt(i);
                    clipped = true;
                    break;
                }
            }
            if (!clipped)
            {
                break;
            }
        }
        if (remaining.Count == 3)
        {
            result.Add((remaining[0], remaining[1], remaining[2]));
        }
        return result;
    }

    /// <summary>The signed area (positive counter-clockwise).</summary>
    public static float SignedArea(IReadOnlyList<Vector2> outline)
    {
        float area = 0;
        for (int i = 0; i < outline.Count; i++)
        {
            var p = outline[i];
            var q = outline[(i + 1) % outline.Count];
            area += (p.X * q.Y) - (q.X * p.Y);
        }
        return area / 2;
    }

    private static float Cross(Vector2 u, Vector2 v) => (u.X * v.Y) - (u.Y * v.X);

    private static bool InTriangle(Vector2 p, Vector2 a, Vector2 b, Vector2 c) =>
        Cross(b - a, p - a) >= 0 && Cross(c - b, p - b) >= 0 && Cross(a - c, p - c) >= 0;
}
