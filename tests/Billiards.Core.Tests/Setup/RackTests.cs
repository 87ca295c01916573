using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Setup;

public class RackTests
{
    private const double R = 0.028575;
    private static readonly TableSpec Table = TableSpec.FromPreset("pool-9ft");

    // Spacing before jitter: 2R + 2 mm; rows are sqrt(3)/2 of that apart.
    private const double Spacing = 2 * R + 0.002;
    private static readonly double RowStep = Spacing * Math.Sqrt(3) / 2;

    private static Dictionary<int, Vec3> Place(RackGame game, int seed) =>
        Initializer.Rack(new RackSpec(game, seed), Table, R).ToDictionary(b => b.Id.Value, b => b.Position);

    // The ideal (unjittered) spot of row k, column j of a rack whose row has n balls.
    private static Vec3 Ideal(int row, int j, int n) =>
        new(2.54 / 4 + row * RowStep, (j - (n - 1) / 2.0) * Spacing, R);

    private static int BallAt(Dictionary<int, Vec3> rack, Vec3 spot) =>
        rack.Single(b => (b.Value - spot).LengthXY <= Math.Sqrt(2) * 0.001 + 1e-12).Key;

    [Theory]
    [InlineData(1)]
    [InlineData(7)]
    [InlineData(12345)]
    public void EightBallRackHasTheEightInTheCentreAndASolidAndAStripeOnTheBackCorners(int seed)
    {
        var rack = Place(RackGame.EightBall, seed);
        Assert.Equal(Enumerable.Range(1, 15), rack.Keys.Order());
        Assert.Equal(1, BallAt(rack, Ideal(0, 0, 1)));    // apex on the foot spot
        Assert.Equal(8, BallAt(rack, Ideal(2, 1, 3)));    // centre of the triangle
        var corners = new[] { BallAt(rack, Ideal(4, 0, 5)), BallAt(rack, Ideal(4, 4, 5)) };
        Assert.Single(corners, n => !BallSet.Pool.Group("stripes").Contains(new BallId(n)) && n != 8);
        Assert.Single(corners, n => BallSet.Pool.Group("stripes").Contains(new BallId(n)));
    }

    [Theory]
    [InlineData(1)]
    [InlineData(7)]
    [InlineData(99)]
    public void NineBallRackIsADiamondWithTheOneAtTheApexAndTheNineInTheCentre(int seed)
    {
        var rack = Place(RackGame.NineBall, seed);
        Assert.Equal(Enumerable.Range(1, 9), rack.Keys.Order());
        Assert.Equal(1, BallAt(rack, Ideal(0, 0, 1)));
        Assert.Equal(9, BallAt(rack, Ideal(2, 1, 3)));
        // Diamond rows 1, 2, 3, 2, 1: every ball sits on one of the nine ideal spots.
        int[] rows = [1, 2, 3, 2, 1];
        var spots = rows.SelectMany((n, row) => Enumerable.Range(0, n).Select(j => Ideal(row, j, n))).ToList();
        Assert.All(rack.Values, p => Assert.Contains(spots, s => (s - p).LengthXY <= Math.Sqrt(2) * 0.001 + 1e-12));
    }

    [Theory]
    [InlineData(RackGame.EightBall)]
    [InlineData(RackGame.NineBall)]
    public void JitterStaysWithinOneMillimetrePerAxisAndNeverMakesBallsOverlap(RackGame game)
    {
        for (int seed = 0; seed < 200; seed++)
        {
            var rack = Initializer.Rack(new RackSpec(game, seed), Table, R);
            int[] rows = game == RackGame.EightBall ? [1, 2, 3, 4, 5] : [1, 2, 3, 2, 1];
            var spots = rows.SelectMany((n, row) => Enumerable.Range(0, n).Select(j => Ideal(row, j, n))).ToList();
            for (int i = 0; i < rack.Count; i++)
            {
                var d = rack[i].Position - spots[i];
                Assert.InRange(d.X, -0.001, 0.001);
                Assert.InRange(d.Y, -0.001, 0.001);
                Assert.Equal(R, rack[i].Position.Z);
                for (int j = 0; j < i; j++)
                {
                    Assert.True((rack[i].Position - rack[j].Position).Length >= 2 * R, $"seed {seed}: balls {rack[i].Id} and {rack[j].Id} overlap");
                }
            }
        }
    }

    [Fact]
    public void TheSameSeedGivesTheSameRackAndAnotherSeedAnother()
    {
        var a = Initializer.Rack(new RackSpec(RackGame.EightBall, 42), Table, R);
        var b = Initializer.Rack(new RackSpec(RackGame.EightBall, 42), Table, R);
        var c = Initializer.Rack(new RackSpec(RackGame.EightBall, 43), Table, R);
        Assert.Equal(a, b);
        Assert.NotEqual(a.Select(x => x.Position), c.Select(x => x.Position));
    }

    [Fact]
    public void SpotsAreAQuarterOfTheLengthFromTheEnds()
    {
        Assert.Equal(new Vec3(0.635, 0, R), Initializer.FootSpot(Table, R));
        Assert.Equal(new Vec3(-0.635, 0, R), Initializer.HeadSpot(Table, R));
    }
}
