using Billiards.App.Game;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Game;

public class AimPreviewTests
{
    private const double R = 0.028575;

    private static readonly PocketCircle[] Pockets =
    [
        new(new Vec3(1.27, 0.635, 0), 0.06, PoolPockets.FootLeft.Index),
        new(new Vec3(1.27, -0.635, 0), 0.06, PoolPockets.FootRight.Index),
        new(new Vec3(0, 0.66, 0), 0.06, PoolPockets.SideLeft.Index),
    ];

    private static BallState At(double x, double y) => new() { Position = new Vec3(x, y, R) };

    [Fact]
    public void TheGhostBallTouchesTheFirstBallOnThePathAndTheObjectBallLeavesAlongTheLineOfCentres()
    {
        // Cue at the origin aimed along +x; the 1 ball offset sideways by R (a half-ball hit), the 2 farther on.
        BallState[] balls = [At(0, 0), At(0.5, R), At(0.9, 0)];
        BallId[] ids = [PoolBalls.Cue, new(1), new(2)];
        var preview = AimPreview.Compute(balls, ids, 0, new Vec3(1, 0, 0), R, Pockets, PoolPockets.Set);
        Assert.Equal(new BallId(1), preview.Ball);
        // Contact when the centres are 2R apart: x = 0.5 - sqrt(4R^2 - R^2) = 0.5 - sqrt(3) R.
        Assert.Equal(0.5 - Math.Sqrt(3) * R, preview.Ghost.X, 12);
        Assert.Equal(0, preview.Ghost.Y, 12);
        // Half-ball hit: the object ball leaves 30 degrees off the aim line.
        Assert.Equal(30, Math.Atan2(preview.ObjectDirection.Y, preview.ObjectDirection.X) * 180 / Math.PI, 9);
    }

    [Fact]
    public void TheEasiestPocketIsTheOneTheObjectBallHeadsForAndAClearPathHasNoBall()
    {
        var heading = new Vec3(1, 1, 0).Normalized();
        Assert.Equal(PoolPockets.FootLeft, AimPreview.EasiestPocket(new Vec3(1.0, 0.365, 0), heading, Pockets, PoolPockets.Set));
        Assert.Equal(PoolPockets.FootRight, AimPreview.EasiestPocket(new Vec3(1.0, -0.365, 0), new Vec3(1, -1, 0).Normalized(), Pockets, PoolPockets.Set));

        BallState[] balls = [At(0, 0), At(0.5, 0.2)];
        var miss = AimPreview.Compute(balls, [PoolBalls.Cue, new(1)], 0, new Vec3(1, 0, 0), R, Pockets, PoolPockets.Set);
        Assert.Null(miss.Ball);
        Assert.Equal(PocketId.None, miss.Pocket);
    }

    [Theory]
    [InlineData("human", null)]
    [InlineData("computer:1", 1)]
    [InlineData("Computer:5", 5)]
    public void PlayersParseAsTheContractNamesThem(string text, int? level)
    {
        var player = Seat.Parse(text, 0);
        Assert.NotNull(player);
        Assert.Equal(level, player.ComputerLevel);
    }

    [Theory]
    [InlineData("cpu:9")]
    [InlineData("computer:0")]
    [InlineData("computer:6")]
    [InlineData("computer:")]
    public void OtherPlayersAreRefused(string text) => Assert.Null(Seat.Parse(text, 1));
}
