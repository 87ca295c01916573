using System.Numerics;

namespace Billiards.App.Rendering;

/// <summary>A triangle mesh as refined: positions, normals and indices (three per triangle).</summary>
/// <param name="Positions">Vertex positions (m).</param>
/// <param name="Normals">Unit vertex normals.</param>
/// <param name="Indices">Triangles, counter-clockwise as in the input.</param>
public sealed record RefinedMesh(Vector3[] Positions, Vector3[] Normals, uint[] Indices);

/// <summary>
/// Splits a model's triangles until no edge is longer than a limit, so that lighting computed at
/// the vertices (cheap on a software rasteriser) varies smoothly across large faces. Longest-edge
/// bisection, kept conforming across all meshes of the model: an edge is split in every triangle
/// of every mesh that has it (edges are matched by their end positions), so no vertex ends up on
/// a neighbour's unsplit edge and no crack opens between faces.
/// </summary>
public static class MeshRefinement
{
    /// <summary>
    /// Refines the meshes together; each keeps its own vertices, normals and winding. An edge is
    /// split while it is longer than <paramref name="maxEdge"/> (m) at its midpoint
    /// (<see cref="Uniform"/> for a constant), so every mesh that has the edge makes the same decision.
    /// </summary>
    public static List<RefinedMesh> Refine(IReadOnlyList<RefinedMesh> meshes, Func<Vector3, float> maxEdge)
    {
        var work = meshes.Select(m => new Work(m)).ToList();
        // Each round halves the marked edges; a hard cap guards against a degenerate input.
        for (int round = 0; round < 64; round++)
        {
            var marked = new HashSet<(Vector3, Vector3)>();
            foreach (var w in work)
            {
                for (int t = 0; t < w.Triangles.Count; t++)
                {
                    var (a, b) = w.LongestEdge(t);
                    var (p, q) = (w.Positions[a], w.Positions[b]);
                    float limit = maxEdge((p + q) * 0.5f);
                    if (!(limit > 0))
                    {
                        throw new ArgumentOutOfRangeException(nameof(maxEdge), limit, "the longest edge must be positive");
                    }
                    if (Vector3.DistanceSquared(p, q) > limit * limit)
                    {
                        marked.Add(Key(w.Positions[a], w.Positions[b]));
                    }
                }
            }
            if (marked.Count == 0)
            {
                break;
            }
            // Closure: a triangle with a marked edge must split its longest edge first.
            bool grew = true;
            while (grew)
            {
                grew = false;
                foreach (var w in work)
                {
                    for (int t = 0; t < w.Triangles.Count; t++)
                    {
                        if (w.HasMarked(t, marked))
                        {
                            var (a, b) = w.LongestEdge(t);
                            grew |= marked.Add(Key(w.Positions[a], w.Positions[b]));
                        }
                    }
                }
            }
            foreach (var w in work)
            {
                w.Split(marked);
            }
        }
        return work.Select(w => w.ToMesh()).ToList();
    }

    /// <summary>The same longest edge everywhere (m).</summary>
    public static Func<Vector3, float> Uniform(float maxEdge) => _ => maxEdge;

    private static (Vector3, Vector3) Key(Vector3 a, Vector3 b) =>
        a.X < b.X || (a.X == b.X && (a.Y < b.Y || (a.Y == b.Y && a.Z <= b.Z))) ? (a, b) : (b, a);

    private sealed class Work
    {
        private readonly Dictionary<(int, int), int> _midpoints = [];

        public Work(RefinedMesh mesh)
        {
            Positions = [.. mesh.Positions];
            Normals = [.. mesh.Normals];
            for (int i = 0; i + 2 < mesh.Indices.Length; i += 3)
            {
                Triangles.Add(((int)mesh.Indices[i], (int)mesh.Indices[i + 1], (int)mesh.Indices[i + 2]));
            }
        }

        public List<Vector3> Positions { get; }

        public List<Vector3> Normals { get; }

        public List<(int A, int B, int C)> Triangles { get; } = [];

        public (int, int) LongestEdge(int t)
        {
            var (a, b, c) = Triangles[t];
            float ab = Vector3.DistanceSquared(Positions[a], Positions[b]);
            float bc = Vector3.DistanceSquared(Positions[b], Positions[c]);
            float ca = Vector3.DistanceSquared(Positions[c], Positions[a]);
            return ab >= bc && ab >= ca ? (a, b) : bc >= ca ? (b, c) : (c, a);
        }

        public bool HasMarked(int t, HashSet<(Vector3, Vector3)> marked)
        {
            var (a, b, c) = Triangles[t];
            return IsMarked(a, b, marked) || IsMarked(b, c, marked) || IsMarked(c, a, marked);
        }

        private bool IsMarked(int a, int b, HashSet<(Vector3, Vector3)> marked) => marked.Contains(Key(Positions[a], Positions[b]));

        public void Split(HashSet<(Vector3, Vector3)> marked)
        {
            var pending = new Stack<(int A, int B, int C)>(Triangles);
            Triangles.Clear();
            while (pending.Count > 0)
            {
                var tri = pending.Pop();
                var (a, b, c) = tri;
                // Bisect the longest marked edge; the halves are examined again for their other marked edges.
                (int P, int Q, int R)? edge = null;
                float best = -1;
                foreach (var (p, q, r) in new[] { (a, b, c), (b, c, a), (c, a, b) })
                {
                    float length = Vector3.DistanceSquared(Positions[p], Positions[q]);
                    if (IsMarked(p, q, marked) && length > best)
                    {
                        best = length;
                        edge = (p, q, r);
                    }
                }
                if (edge is not { } e)
                {
                    Triangles.Add(tri);
                    continue;
                }
                int m = Midpoint(e.P, e.Q);
                pending.Push((e.P, m, e.R));
                pending.Push((m, e.Q, e.R));
            }
        }

        private int Midpoint(int a, int b)
        {
            var key = a < b ? (a, b) : (b, a);
            if (_midpoints.TryGetValue(key, out int m))
            {
                return m;
            }
            // Summed in a fixed order of the end positions, so every mesh sharing the edge gets the same point.
            var (p, q) = Key(Positions[a], Positions[b]);
            Positions.Add((p + q) * 0.5f);
            var n = Normals[a] + Normals[b];
            Normals.Add(n.LengthSquared() > 1e-12f ? Vector3.Normalize(n) : Normals[a]);
            m = Positions.Count - 1;
            _midpoints[key] = m;
            return m;
        }

        public RefinedMesh ToMesh()
        {
            var indices = new uint[Triangles.Count * 3];
            for (int t = 0; t < Triangles.Count; t++)
            {
                (indices[3 * t], indices[(3 * t) + 1], indices[(3 * t) + 2]) = ((uint)Triangles[t].A, (uint)Triangles[t].B, (uint)Triangles[t].C);
            }
            return new RefinedMesh([.. Positions], [.. Normals], indices);
        }
    }
}
