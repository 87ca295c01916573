using Billiards.Core.Table;

namespace Billiards.Core.Tests.Table;

/// <summary>A thread reuses the geometry it built last only for the same table and radius, to the bit.</summary>
public class TableGeometryReuseTests
{
    private static readonly TableSpec Nine = TableSpec.FromPreset("pool-9ft");
    private const double R = 0.028575;

    private static double[] Numbers(TableGeometry g) =>
        [.. g.Segments.ToArray().SelectMany(s => new[] { s.Start.X, s.Start.Y, s.End.X, s.End.Y, s.Normal.X, s.Normal.Y }),
         .. g.Pockets.ToArray().SelectMany(p => new[] { p.Centre.X, p.Centre.Y, p.Radius }),
         .. g.Noses.ToArray().SelectMany(n => new[] { n.Centre.X, n.Centre.Y, n.Radius })];

    [Fact]
    public void TheSameTableAndRadiusGiveTheThreadsLastGeometryAndAnythingElseANewOne()
    {
        var first = TableGeometry.Build(Nine, R);
        // An equal spec (another instance) and radius: the same geometry, not rebuilt.
        Assert.Same(first, TableGeometry.Build(Nine with { }, R));

        var otherRadius = TableGeometry.Build(Nine, R * 1.01);
        Assert.NotSame(first, otherRadius);
        Assert.NotEqual(Numbers(first), Numbers(otherRadius));
        var wider = TableGeometry.Build(Nine with { Width = Nine.Width + 0.1 }, R);
        Assert.NotEqual(Numbers(first), Numbers(wider));

        // 0 and -0 are equal numbers but not the same bits: a spec with -0 keeps its own.
        var zero = TableGeometry.Build(Nine with { CushionHeight = 0.0 }, R);
        var negativeZero = TableGeometry.Build(Nine with { CushionHeight = -0.0 }, R);
        Assert.NotSame(zero, negativeZero);
        Assert.True(double.IsNegative(negativeZero.CushionHeight));

        // A reused geometry is what a new build gives, number for number.
        var again = TableGeometry.Build(Nine, R);
        Assert.Equal(Numbers(first), Numbers(again));
        Assert.Same(again, TableGeometry.Build(Nine, R));
    }

    [Fact]
    public void EachThreadKeepsItsOwn()
    {
        var mine = TableGeometry.Build(Nine, R);
        TableGeometry? theirs = null;
        var thread = new Thread(() => theirs = TableGeometry.Build(Nine, R));
        thread.Start();
        thread.Join();
        Assert.NotNull(theirs);
        Assert.NotSame(mine, theirs);
        Assert.Equal(Numbers(mine), Numbers(theirs));
    }
}
