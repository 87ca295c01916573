using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Table;

/// <summary>The snooker table: its playing area, pockets, baulk line, D and spots (rules.md "Snooker").</summary>
public class SnookerTableTests
{
    private static readonly TableSpec Table = TableSpec.FromPreset("snooker-12ft");
    private const double R = 0.02625;

    [Fact]
    public void TheTableHasTheWPBSAPlayingAreaAndSnookersTighterRoundedPockets()
    {
        Assert.Equal(3.569, Table.Length);
        Assert.Equal(1.778, Table.Width);
        Assert.Equal(6, Table.Pockets.Count);
        Assert.All(Table.Pockets, p => Assert.Equal(p.IsCorner ? 0.086 : 0.092, p.Mouth));
        var pool = TableSpec.FromPreset("pool-9ft");
        Assert.All(Table.Pockets.Zip(pool.Pockets), p => Assert.True(p.First.Mouth < p.Second.Mouth));
        // Rounded: the noses at the jaws are four times pool's.
        Assert.All(TableGeometry.Build(Table, R).Noses.ToArray(), n => Assert.Equal(0.02, n.Radius));
    }

    [Fact]
    public void SnookersBallsAreHeldBySnookersTable()
    {
        Assert.Null(RadiusLimits.Problem(Table, R));
        Assert.True(RadiusLimits.CaptureSpansJaws(Table, R));
    }

    [Fact]
    public void TheBaulkLineTheDAndTheSixSpotsStandWhereTheRulesPutThem()
    {
        double baulk = -3.569 / 2 + 0.737;
        Assert.Equal(baulk, SnookerTable.BaulkLineX(Table), 12);
        Assert.Equal(new Vec3(baulk, -0.292, R), SnookerTable.Spot(Table, "yellow", R));
        Assert.Equal(new Vec3(baulk, 0.292, R), SnookerTable.Spot(Table, "green", R));
        Assert.Equal(new Vec3(baulk, 0, R), SnookerTable.Spot(Table, "brown", R));
        Assert.Equal(new Vec3(0, 0, R), SnookerTable.Spot(Table, "blue", R));
        Assert.Equal(new Vec3(3.569 / 4, 0, R), SnookerTable.Spot(Table, "pink", R));
        Assert.Equal(3.569 / 2 - 0.324, SnookerTable.Spot(Table, "black", R).X, 12);
        Assert.True(SnookerTable.InD(Table, new Vec3(baulk - 0.2, 0.2, R)));
        Assert.False(SnookerTable.InD(Table, new Vec3(baulk + 0.01, 0, R)));     // in front of the line
        Assert.False(SnookerTable.InD(Table, new Vec3(baulk - 0.25, 0.2, R)));   // in baulk, outside the arc
    }
}
