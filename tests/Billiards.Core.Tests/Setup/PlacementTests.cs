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
        var foot = TableGeometry.Build(Pool9, R).Pockets[(int)PocketId.FootLeft];
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
        Assert.Null(Placement.OnTable(Pool9, R, BallId.Cue, new Vec3(headString, 0.1, R), PlacementRegion.Kitchen));
        Assert.Contains("is outside the kitchen", Placement.OnTable(Pool9, R, BallId.Cue, new Vec3(headString + 0.001, 0.1, R), PlacementRegion.Kitchen));
        Assert.Null(Placement.OnTable(Pool9, R, BallId.Cue, new Vec3(headString + 0.001, 0.1, R), PlacementRegion.Table));
    }

    [Fact]
    public void BallsOverlapWhenTheirCentresAreLessThanTwoRadiiApart()
    {
        var a = new Vec3(0, 0, R);
        Assert.Null(Placement.Overlap(R, Three, new Vec3(2 * R, 0, R), BallId.Cue, a));
        Assert.Equal("ball \"3\" overlaps ball \"cue\" (centres 0.05 m apart, less than 2R = 0.05715 m)",
            Placement.Overlap(R, Three, new Vec3(0.03, 0.04, R), BallId.Cue, a));
    }

    [Fact]
    public void ASetReportsItsFirstProblemOnTheBallAtFault()
    {
        var balls = new List<(BallId, Vec3)> { (BallId.Cue, new Vec3(0, 0, R)), (Three, new Vec3(0.5, 0, R)), (new BallId(4), new Vec3(0.5, 0.01, R)) };
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
}
