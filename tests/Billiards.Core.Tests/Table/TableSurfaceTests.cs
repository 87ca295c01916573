using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Table;

/// <summary>What a ball in the air comes down on (<see cref="TableGeometry.SurfaceUnder"/>), by where its centre is.</summary>
public class TableSurfaceTests
{
    private const double R = PhysicsParams.DefaultRadius;

    public static TheoryData<string> Presets()
    {
        var data = new TheoryData<string>();
        foreach (string preset in TableSpec.PresetNames)
        {
            data.Add(preset);
        }
        return data;
    }

    /// <summary>
    /// On every preset: the bed inside the noses (a ball's width from them), a cushion's top where
    /// a ball would overlap it (half a radius inside the nose, and behind it), the rail up to its
    /// outer edge, the floor beyond; each hole's capture circle and the hole behind it; the slate
    /// of a mouth where a ball fits between the jaws.
    /// </summary>
    [Theory]
    [MemberData(nameof(Presets))]
    public void EachPartOfTheTableIsWhatLiesThere(string preset)
    {
        var table = TableSpec.FromPreset(preset);
        var g = TableGeometry.Build(table, R);
        double hx = table.HalfLength, hy = table.HalfWidth, w = table.RailWidth;
        Assert.Equal(SurfaceKind.Bed, g.SurfaceUnder(new Vec3(0.2, -0.1, 0)).Kind);
        Assert.Equal(SurfaceKind.Bed, g.SurfaceUnder(new Vec3(hx - R, 0.2, 0)).Kind);
        foreach (var (p, rail) in new[] { (new Vec3(hx - R / 2, 0.2, 0), 1), (new Vec3(-hx - 0.05, 0.1, 0), 0), (new Vec3(0.4, hy + w - 0.01, 0), 3), (new Vec3(-0.4, -hy + R / 2, 0), 4) })
        {
            var s = g.SurfaceUnder(p);
            Assert.Equal(SurfaceKind.Rail, s.Kind);
            Assert.Equal(rail, s.Index);
        }
        Assert.Equal(SurfaceKind.Floor, g.SurfaceUnder(new Vec3(hx + w + 0.01, 0, 0)).Kind);
        Assert.Equal(SurfaceKind.Floor, g.SurfaceUnder(new Vec3(0, -hy - w - 0.01, 0)).Kind);
        foreach (var circle in g.Pockets)
        {
            var pocket = table.Pockets[circle.Pocket];
            Assert.Equal(new TableSurface(SurfaceKind.Pocket, circle.Pocket), g.SurfaceUnder(circle.Centre));
            Assert.Equal(new TableSurface(SurfaceKind.Pocket, circle.Pocket), g.SurfaceUnder(circle.Centre + pocket.Outward * (0.9 * pocket.Mouth / 2)));
            // The back of the pocket, a mouth behind its line, is the rail again.
            Assert.Equal(SurfaceKind.Rail, g.SurfaceUnder(pocket.MouthMiddle(table) + pocket.Outward * pocket.Mouth).Kind);
        }
    }

    /// <summary>
    /// Just past a corner's mouth line, beside the capture circle, a ball fits between the jaws: the
    /// mouth's slate is bed; on the axis it is the hole; past the jaw's face, over the jaw, the rail.
    /// </summary>
    [Fact]
    public void AMouthsSlateIsBedAndItsJawsAreRail()
    {
        var table = TableSpec.FromPreset("pool-9ft");
        var g = TableGeometry.Build(table, R);
        var pocket = table.Pockets[4];
        var middle = pocket.MouthMiddle(table);
        var across = new Vec3(-pocket.Outward.Y, pocket.Outward.X, 0);
        Assert.Equal(SurfaceKind.Bed, g.SurfaceUnder(middle + pocket.Outward * 0.002 + across * 0.025).Kind);
        Assert.Equal(SurfaceKind.Pocket, g.SurfaceUnder(middle + pocket.Outward * 0.002).Kind);
        Assert.Equal(SurfaceKind.Rail, g.SurfaceUnder(middle + pocket.Outward * 0.01 + across * (pocket.Mouth / 2 + 0.01)).Kind);
    }
}
