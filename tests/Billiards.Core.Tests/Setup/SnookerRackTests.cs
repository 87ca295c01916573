using Billiards.Core.Balls;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Setup;

/// <summary>Snooker's rack (rules.md "Snooker").</summary>
public class SnookerRackTests
{
    private static readonly TableSpec Table = TableSpec.FromPreset("snooker-12ft");
    private const double R = 0.02625;

    [Theory]
    [InlineData(1)]
    [InlineData(99)]
    public void TheRackPlacesAll22BallsTheColoursOnTheirSpotsTheRedsBehindThePinkTheCueBallInTheD(int seed)
    {
        var rack = Initializer.Rack(new RackSpec(RackGame.Snooker, seed), Table, R);
        Assert.Equal(BallSet.Snooker.Ids.Select(b => b.Value).Order(), rack.Select(b => b.Id.Value).Order());
        Assert.Null(Placement.Check(Table, R, rack, out _));
        foreach (string colour in BallSet.Colours)
        {
            Assert.Equal(SnookerTable.Spot(Table, colour, R), rack.Single(b => b.Id == BallSet.Colour(colour)).Position);
        }
        Assert.True(SnookerTable.InD(Table, rack.Single(b => b.Id == BallSet.Snooker.CueBalls[0]).Position));
        var pink = SnookerTable.Spot(Table, "pink", R);
        var reds = rack.Where(b => BallSet.Snooker.Group("reds").Contains(b.Id)).Select(b => b.Position).ToList();
        Assert.Equal(15, reds.Count);
        Assert.All(reds, p => Assert.True(p.X > pink.X && p.X < SnookerTable.Spot(Table, "black", R).X - 2 * R));
        // The apex red is as close to the pink as the jitter allows without touching: under 3 mm.
        double gap = reds.Min(p => (p - pink).Length) - 2 * R;
        Assert.InRange(gap, 0, 0.003);
    }
}
