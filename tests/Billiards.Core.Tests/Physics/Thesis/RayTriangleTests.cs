using System.Numerics;
using Billiards.Core.Physics.Thesis;

namespace Billiards.Core.Tests.Physics.Thesis;

/// <summary>Listing 2 (Formel 20): the seed's Moller-Trumbore test and its kinds of miss.</summary>
public class RayTriangleTests
{
    // The triangle p1 = 0, p2 = x, p3 = y in the z = 0 plane: u is the weight along edge1 = x,
    // r the weight along edge2 = y, so a ray along z through (a, b, .) has u = a and r = b.
    private static readonly Vector3 P1 = Vector3.Zero, P2 = Vector3.UnitX, P3 = Vector3.UnitY;

    private static RayHit Cast(float x, float y, out float t, out Vector3 point) =>
        CollisionGeometry.Intersect(P1, P2, P3, new Vector3(x, y, -1), new Vector3(0, 0, 2), out t, out point);

    [Fact]
    public void ARayThroughTheInsideHitsAtTheCrossing()
    {
        // From z = -1 with direction (0, 0, 2) the plane z = 0 is reached at t = 1/2.
        Assert.Equal(RayHit.Hit, Cast(0.25f, 0.25f, out float t, out var point));
        Assert.Equal(0.5f, t, 1e-6f);
        ThesisKit.AssertVector(new Vector3(0.25f, 0.25f, 0), point, 1e-6f);
    }

    [Fact]
    public void ACrossingBehindTheOriginStillCountsWithNegativeT()
    {
        // The listing never rejects t < 0: a ball that has passed the triangle finds it behind.
        var hit = CollisionGeometry.Intersect(P1, P2, P3, new Vector3(0.25f, 0.25f, 1), new Vector3(0, 0, 2), out float t, out var point);
        Assert.Equal(RayHit.Hit, hit);
        Assert.Equal(-0.5f, t, 1e-6f);
        ThesisKit.AssertVector(new Vector3(0.25f, 0.25f, 0), point, 1e-6f);
    }

    [Theory]
    [InlineData(-0.25f, 0.25f, RayHit.UBelowZero)]   // u = -0.25
    [InlineData(1.5f, 0.25f, RayHit.UAboveOne)]      // u = 1.5
    [InlineData(0.25f, -0.25f, RayHit.RBelowZero)]   // u = 0.25 fine, r = -0.25
    [InlineData(0.6f, 0.6f, RayHit.SumAboveOne)]     // u = r = 0.6, u + r = 1.2
    public void EachMissIsToldApart(float x, float y, RayHit expected)
    {
        Assert.Equal(expected, Cast(x, y, out float t, out var point));
        Assert.Equal(0, t);
        Assert.Equal(new Vector3(x, y, -1), point);
    }

    [Fact]
    public void ARayInThePlaneOfTheTriangleIsParallel()
    {
        // det = edge1 . (v x edge2) = x . (x x y) = x . z = 0.
        var hit = CollisionGeometry.Intersect(P1, P2, P3, new Vector3(-1, 0.25f, 0), Vector3.UnitX, out _, out _);
        Assert.Equal(RayHit.Parallel, hit);
    }

    [Fact]
    public void TheEdgesBelongToTheTriangle()
    {
        // u + r = 1 exactly (on the third edge) and u = 0 (on edge2) are hits: the listing uses <= and >=.
        Assert.Equal(RayHit.Hit, Cast(0.5f, 0.5f, out _, out _));
        Assert.Equal(RayHit.Hit, Cast(0, 0.5f, out _, out _));
    }

    [Fact]
    public void TheNormalFollowsTheCornerOrder()
    {
        // (p2 - p1) x (p3 - p1) = x x y = z.
        var triangle = new CollisionGeometry(0, P1, P2, P3, true, 0);
        Assert.Equal(Vector3.UnitZ, triangle.Normal);
        Assert.Equal(Vector3.UnitZ * -1, new CollisionGeometry(0, P1, P3, P2, true, 0).Normal);
    }
}
