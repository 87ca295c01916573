using System.Numerics;

namespace Billiards.Core.Physics.Thesis;

/// <summary>The outcomes of the seed's ray-triangle test (Listing 2, seed figure 19).</summary>
public enum RayHit : byte
{
    /// <summary>The line of the ray crosses the triangle.</summary>
    Hit,
    /// <summary>det = 0: the ray runs parallel to the triangle's plane.</summary>
    Parallel,
    /// <summary>The barycentric u along edge 1 is below 0.</summary>
    UBelowZero,
    /// <summary>The barycentric u along edge 1 is above 1.</summary>
    UAboveOne,
    /// <summary>The barycentric r along edge 2 is below 0 (the seed's text calls it v).</summary>
    RBelowZero,
    /// <summary>u + r is above 1: the crossing lies beyond the third edge.</summary>
    SumAboveOne,
}

/// <summary>
/// One collision triangle (seed 4.1.2): three corners, the unit normal, whether balls bounce
/// off it (cushions and jaws) or are stopped by it (pocket back walls), and an id. The triangles
/// are placed one ball radius in front of the real cushion faces, so a ball collides when its
/// centre crosses a triangle. Seed units (cm), Y up.
/// </summary>
public sealed class CollisionGeometry
{
    /// <summary>
    /// Creates a triangle. The normal is normalize((p2 - p1) x (p3 - p1)): give the corners in the
    /// order that makes it point to the side the balls come from.
    /// </summary>
    /// <param name="id">Index of the triangle in its table's list.</param>
    /// <param name="p1">First corner (cm).</param>
    /// <param name="p2">Second corner (cm).</param>
    /// <param name="p3">Third corner (cm).</param>
    /// <param name="isBouncing">True for a cushion or jaw, false for a pocket back wall.</param>
    /// <param name="feature">The cushion, jaw or pocket back this triangle belongs to, for events (see <see cref="Setup.Initializer.CushionNames"/>).</param>
    public CollisionGeometry(int id, Vector3 p1, Vector3 p2, Vector3 p3, bool isBouncing, int feature)
    {
        Id = id;
        P1 = p1;
        P2 = p2;
        P3 = p3;
        Normal = Vector3.Normalize(Vector3.Cross(p2 - p1, p3 - p1));
        IsBouncing = isBouncing;
        Feature = feature;
    }

    /// <summary>Index of the triangle in its table's list.</summary>
    public int Id { get; }

    /// <summary>First corner (cm).</summary>
    public Vector3 P1 { get; }

    /// <summary>Second corner (cm).</summary>
    public Vector3 P2 { get; }

    /// <summary>Third corner (cm).</summary>
    public Vector3 P3 { get; }

    /// <summary>Unit normal, pointing towards the balls' side.</summary>
    public Vector3 Normal { get; }

    /// <summary>True for a cushion or jaw; false for a pocket back wall, which kills the horizontal speed (Listing 3).</summary>
    public bool IsBouncing { get; }

    /// <summary>Index of the named feature (cushion, jaw or pocket back) this triangle belongs to.</summary>
    public int Feature { get; }

    /// <summary>The seed's ray test (Listing 2) against this triangle.</summary>
    public RayHit Intersect(Vector3 origin, Vector3 direction, out float t, out Vector3 point) =>
        Intersect(P1, P2, P3, origin, direction, out t, out point);

    /// <summary>
    /// The seed's modified Moller-Trumbore test (Formel 20, Listing 2): does the line
    /// origin + t * direction cross the triangle p1 + u (p2 - p1) + r (p3 - p1), u, r >= 0,
    /// u + r &lt;= 1? The misses are told apart in the order the listing tests them.
    /// </summary>
    /// <remarks>
    /// As in the listing, t is not required to be positive: the ray is a whole line. That is
    /// what lets the engine find the triangle a ball has already passed in this step (t &lt; 0)
    /// and put the ball back onto it. Parallel means det is exactly 0, as in the listing's
    /// <c>det &gt; 0 || det &lt; 0</c>.
    /// </remarks>
    /// <param name="p1">First corner (cm).</param>
    /// <param name="p2">Second corner (cm).</param>
    /// <param name="p3">Third corner (cm).</param>
    /// <param name="origin">Start of the ray: the ball's centre (cm).</param>
    /// <param name="direction">Direction of the ray: the ball's velocity (cm/s, any length).</param>
    /// <param name="t">On a hit, the ray parameter of the crossing (s when direction is a velocity); 0 otherwise.</param>
    /// <param name="point">On a hit, origin + t * direction (cm); origin otherwise.</param>
    /// <returns>Whether the line crosses the triangle, and if not, why not.</returns>
    public static RayHit Intersect(Vector3 p1, Vector3 p2, Vector3 p3, Vector3 origin, Vector3 direction, out float t, out Vector3 point)
    {
        t = 0;
        point = origin;
        var edge1 = p2 - p1;
        var edge2 = p3 - p1;
        var pVector = Vector3.Cross(direction, edge2);
        float det = Vector3.Dot(edge1, pVector);
        if (det == 0)
        {
            return RayHit.Parallel;
        }
        float invDet = 1f / det;
        var tVector = origin - p1;
        float u = Vector3.Dot(tVector, pVector) * invDet;
        if (u < 0)
        {
            return RayHit.UBelowZero;
        }
        if (u > 1)
        {
            return RayHit.UAboveOne;
        }
        var qVector = Vector3.Cross(tVector, edge1);
        float r = Vector3.Dot(direction, qVector) * invDet;
        if (r < 0)
        {
            return RayHit.RBelowZero;
        }
        if (u + r > 1)
        {
            return RayHit.SumAboveOne;
        }
        t = Vector3.Dot(edge2, qVector) * invDet;
        point = origin + t * direction;
        return RayHit.Hit;
    }
}
