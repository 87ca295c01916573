using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Setup;

/// <summary>The 10-ball triangle, the 14.1 triangle and 14.1's rerack of 14 with the apex empty.</summary>
public class TenBallAndStraightPoolRackTests
{
    private const double R = 0.028575;
    private static readonly TableSpec Table = TableSpec.FromPreset("pool-9ft");
    private const double Spacing = 2 * R + 0.002;
    private static readonly double RowStep = Spacing * Math.Sqrt(3) / 2;
    private const double Jitter = 0.001;

    // Row k, column j of a triangle, the apex on the foot spot (x = L/4 = 0.635 m).
    private static Vec3 Ideal(int row, int j) => new(2.54 / 4 + row * RowStep, (j - row / 2.0) * Spacing, R);

    private static List<Vec3> Triangle(int rows) =>
        [.. Enumerable.Range(0, rows).SelectMany(row => Enumerable.Range(0, row + 1).Select(j => Ideal(row, j)))];

    private static bool Near(Vec3 a, Vec3 b) => Math.Abs(a.X - b.X) <= Jitter && Math.Abs(a.Y - b.Y) <= Jitter;

    [Theory]
    [InlineData(1)]
    [InlineData(7)]
    [InlineData(4242)]
    public void TenBallIsATriangleOfTenWithTheOneAtTheApexAndTheTenInTheCentre(int seed)
    {
        var rack = Initializer.Rack(new RackSpec(RackGame.TenBall, seed), Table, R);
        Assert.Equal(Enumerable.Range(1, 10), rack.Select(b => b.Id.Value).Order());
        var spots = Triangle(4);
        Assert.All(rack, b => Assert.Contains(spots, s => Near(s, b.Position)));
        Assert.True(Near(Ideal(0, 0), rack.Single(b => b.Id.Value == 1).Position));
        Assert.True(Near(Ideal(2, 1), rack.Single(b => b.Id.Value == 10).Position)); // the middle of the third row
        AssertApart(rack);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(99)]
    public void StraightPoolIsAFullTriangleOfFifteen(int seed)
    {
        var rack = Initializer.Rack(new RackSpec(RackGame.StraightPool, seed), Table, R);
        Assert.Equal(Enumerable.Range(1, 15), rack.Select(b => b.Id.Value).Order());
        var spots = Triangle(5);
        Assert.All(rack, b => Assert.Contains(spots, s => Near(s, b.Position)));
        AssertApart(rack);
    }

    [Fact]
    public void TheRerackOfFourteenLeavesTheApexEmpty()
    {
        var fourteen = Enumerable.Range(1, 15).Where(n => n != 6).Select(n => new BallId(n)).ToList();
        var rack = Initializer.Rerack(fourteen, Table, R, seed: 3);
        Assert.Equal(fourteen, rack.Select(b => b.Id).OrderBy(id => id.Value));
        var spots = Triangle(5);
        Assert.All(rack, b => Assert.Contains(spots.Skip(1), s => Near(s, b.Position)));
        Assert.DoesNotContain(rack, b => Near(Ideal(0, 0), b.Position));
        AssertApart(rack);
    }

    [Fact]
    public void ARerackOfFifteenFillsTheApexToo()
    {
        var all = Enumerable.Range(1, 15).Select(n => new BallId(n)).ToList();
        var rack = Initializer.Rerack(all, Table, R, seed: 3);
        Assert.Contains(rack, b => Near(Ideal(0, 0), b.Position));
        Assert.Equal(15, rack.Count);
    }

    private static void AssertApart(IReadOnlyList<(BallId Id, Vec3 Position)> rack)
    {
        for (int i = 0; i < rack.Count; i++)
        {
            Assert.Equal(R, rack[i].Position.Z);
            for (int j = 0; j < i; j++)
            {
                Assert.True((rack[i].Position - rack[j].Position).Length >= 2 * R);
            }
        }
    }
}
