using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Setup;

/// <summary>The one placement test that the scene loader and the simulation's placing calls share.</summary>
public class PlacementTests
{
    private const double R = 0.028575;
    private static readonly TableSpec Pool9 = TableSpec.FromPreset("pool-9ft");
    private static readonly BallId Three = new(3);

    [Fact]
    public void ABallTouchingTheCushionsIsOnTheTableAndOneBeyondThemIsNot()
    {
        double maxX = Pool9.HalfLength - R;
        double maxY = Pool9.HalfWidth - R;
        Assert.Null(Placement.OnTable(Pool9, R, Three, new Vec3(0, maxY, R)));
        Assert.Null(Placement.OnTable(Pool9, R, Three, new Vec3(-maxX, 0, R)));
        Assert.Contains("ball \"3\" at [0, 0.62] is off the table", Placement.OnTable(Pool9, R, Three, new Vec3(0, 0.62, R)));
        Assert.Contains("no finite position", Placement.OnTable(Pool9, R, Three, new Vec3(double.NaN, 0, R)));
    }

    [Fact]
    public void ABallWhoseCentreIsInACaptureCircleIsOverThatPocket()
    {
        // Each capture circle (radius R) lies R beyond the middle of the mouth; the corner of the
        // cushion rectangle, (L/2 - R, W/2 - R), is inside the foot-left one on a 9 ft table.
        var corner = new Vec3(Pool9.HalfLength - R, Pool9.HalfWidth - R, R);
        var foot = TableGeometry.Build(Pool9, R).Pockets[PoolPockets.FootLeft.Index];
        Assert.True((corner - foot.Centre).XY.Length < foot.Radius);
        Assert.Contains("is over the foot-left pocket", Placement.OnTable(Pool9, R, Three, corner));
        Assert.Contains("is over the head-right pocket", Placement.OnTable(Pool9, R, Three, new Vec3(-corner.X, -corner.Y, R)));
        // A pocketless table has no pockets to be over.
        Assert.Null(Placement.OnTable(TableSpec.FromPreset("pocketless"), R, Three, corner));
    }

    [Fact]
    public void TheKitchenEndsAtTheHeadStringAQuarterOfTheLengthFromTheCentre()
    {
        double headString = -Pool9.Length / 4;
        Assert.Equal(headString, Placement.HeadString(Pool9));
        Assert.Null(Placement.OnTable(Pool9, R, PoolBalls.Cue, new Vec3(headString, 0.1, R), PlacementRegion.Kitchen));
        Assert.Contains("is outside the kitchen", Placement.OnTable(Pool9, R, PoolBalls.Cue, new Vec3(headString + 0.001, 0.1, R), PlacementRegion.Kitchen));
        Assert.Null(Placement.OnTable(Pool9, R, PoolBalls.Cue, new Vec3(headString + 0.001, 0.1, R), PlacementRegion.Table));
    }

    [Fact]
    public void BallsOverlapWhenTheirCentresAreLessThanTwoRadiiApart()
    {
        var a = new Vec3(0, 0, R);
        Assert.Null(Placement.Overlap(R, Three, new Vec3(2 * R, 0, R), PoolBalls.Cue, a));
        Assert.Equal("ball \"3\" overlaps ball \"cue\" (centres 0.05 m apart, less than 2R = 0.05715 m)",
            Placement.Overlap(R, Three, new Vec3(0.03, 0.04, R), PoolBalls.Cue, a));
    }

    [Fact]
    public void ASetReportsItsFirstProblemOnTheBallAtFault()
    {
        var balls = new List<(BallId, Vec3)> { (PoolBalls.Cue, new Vec3(0, 0, R)), (Three, new Vec3(0.5, 0, R)), (new BallId(4), new Vec3(0.5, 0.01, R)) };
        Assert.Contains("ball \"4\" overlaps ball \"3\"", Placement.Check(Pool9, R, balls, out int culprit));
        Assert.Equal(2, culprit);
        balls[2] = (new BallId(4), new Vec3(0.5, 0.1, R));
        Assert.Null(Placement.Check(Pool9, R, balls, out culprit));
        Assert.Equal(-1, culprit);
    }

    [Fact]
    public void TheSceneLoaderRefusesABallOverAPocketWithThePlacementTestsWords()
    {
        double x = Pool9.HalfLength - R, y = Pool9.HalfWidth - R;
        string json = $$"""{ "format": "billiards-scene/1", "balls": [ { "id": "7", "position": [{{x.ToString(System.Globalization.CultureInfo.InvariantCulture)}}, {{y.ToString(System.Globalization.CultureInfo.InvariantCulture)}}] } ] }""";
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse(json, "t.json"));
        Assert.Equal("$.balls[0]", e.JsonPath);
        Assert.Contains("ball \"7\"", e.Problem);
        Assert.Contains("is over the foot-left pocket", e.Problem);
    }

    [Fact]
    public void RackSpotsAreTheUnjitteredRackAndTheRackStaysWithinAJitterOfThem()
    {
        var spots = Initializer.RackSpots(RackGame.EightBall, Pool9, R);
        Assert.Equal(15, spots.Count);
        Assert.Equal(Initializer.FootSpot(Pool9, R), spots[0]);
        double spacing = 2 * R + Initializer.RackGap;
        // The back row is four row steps of spacing * sqrt(3) / 2 behind the apex.
        Assert.Equal(spots[0].X + 4 * spacing * Math.Sqrt(3) / 2, spots[14].X, 12);
        Assert.Equal(2 * spacing, spots[14].Y, 12);
        var rack = Initializer.Rack(new RackSpec(RackGame.EightBall, 5), Pool9, R);
        for (int k = 0; k < spots.Count; k++)
        {
            Assert.InRange(Math.Abs(rack[k].Position.X - spots[k].X), 0, Initializer.RackJitter);
            Assert.InRange(Math.Abs(rack[k].Position.Y - spots[k].Y), 0, Initializer.RackJitter);
        }
    }

    [Fact]
    public void ThePlannersPlacementsAreThePlacementTestWithAMargin()
    {
        var table = TableSpec.FromPreset("pool-9ft");
        double r = 0.028575;
        var onString = new Vec3(Placement.HeadString(table), 0.2, r);
        // The referee takes a centre on the head string as behind it; the planner keeps 0.1 mm clear.
        Assert.True(Placement.FitsOnTable(table, r, onString, PlacementRegion.Kitchen));
        Assert.Null(Placement.OnTable(table, r, PoolBalls.Cue, onString, PlacementRegion.Kitchen));
        var position = new Billiards.Core.Ai.TablePosition([(new BallId(1), new Vec3(0.5, 0, r))], PoolBalls.Cue);
        Assert.False(position.CanPlace(onString, Billiards.Core.Rules.BallInHand.Kitchen, table, r, PoolBalls.Cue));
        Assert.True(position.CanPlace(onString with { X = onString.X - 0.001 }, Billiards.Core.Rules.BallInHand.Kitchen, table, r, PoolBalls.Cue));
        // Touching a ball is allowed; the planner wants its margin.
        var touching = new Vec3(0.5 - 2 * r, 0, r);
        Assert.False(Placement.Overlaps(r, touching, new Vec3(0.5, 0, r)));
        Assert.False(position.CanPlace(touching, Billiards.Core.Rules.BallInHand.Table, table, r, PoolBalls.Cue));
        Assert.True(position.CanPlace(touching with { X = touching.X - 0.001 }, Billiards.Core.Rules.BallInHand.Table, table, r, PoolBalls.Cue));
        // Over a pocket, for both.
        var corner = new Vec3(table.HalfLength - r, table.HalfWidth - r, r);
        Assert.False(Placement.FitsOnTable(table, r, corner, PlacementRegion.Table));
        Assert.False(position.CanPlace(corner, Billiards.Core.Rules.BallInHand.Table, table, r, PoolBalls.Cue));
    }

    [Fact]
    public void TheFreeSpotSearchFindsTheNearestPointClearOfEveryBall()
    {
        var table = TableSpec.FromPreset("pool-9ft");
        double r = 0.028575;
        var head = new Vec3(-table.HalfLength / 2, 0, r);
        Assert.Equal(head, Placement.FreeSpotNear(table, r, PoolBalls.Cue, head, []));
        // A ball on the head spot: the first free point is on the first ring that clears it (2R away), at angle 0.
        var spot = Placement.FreeSpotNear(table, r, PoolBalls.Cue, head, [(new BallId(1), head)]);
        Assert.Equal(2 * r, (spot - head).Length, 9);
        Assert.Equal(head.Y, spot.Y, 12);
        Assert.True(spot.X > head.X);
        // In the kitchen, the ring point ahead of the head string is refused: the first one behind it.
        var kitchen = Placement.FreeSpotNear(table, r, PoolBalls.Cue, head, [(new BallId(1), head)], PlacementRegion.Kitchen);
        Assert.True(kitchen.X <= Placement.HeadString(table) + Placement.Tolerance);
        Assert.True((kitchen - head).Length >= 2 * r - Placement.Tolerance);
    }
}
