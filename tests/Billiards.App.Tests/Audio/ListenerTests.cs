using Billiards.App.Audio;
using Billiards.Core.Mathematics;

namespace Billiards.App.Tests.Audio;

public sealed class ListenerTests
{
    // Looking along +x from x = -1: +y is on the left, -y on the right.
    private static readonly Listener Player = new(new Vec3(-1, 0, 0), new Vec3(0, 0, 0));

    [Fact]
    public void ASoundAheadIsCentredAtEqualPower()
    {
        var (left, right) = Player.Gains(new Vec3(0, 0, 0));
        Assert.Equal(left, right, 6);
        Assert.Equal(1, (left * left) + (right * right), 5);
    }

    [Fact]
    public void ASoundToTheRightIsLouderOnTheRight()
    {
        var (left, right) = Player.Gains(new Vec3(-1, -1, 0));
        Assert.Equal(0, left, 5);
        Assert.Equal(1, right, 5);
        var (l2, r2) = Player.Gains(new Vec3(-1, 1, 0));
        Assert.Equal(1, l2, 5);
        Assert.Equal(0, r2, 5);
    }

    [Fact]
    public void DistanceBeyondTheReferenceTurnsItDownAsOneOverDistance()
    {
        double Power(Vec3 p)
        {
            var (l, r) = Player.Gains(p);
            return Math.Sqrt((l * l) + (r * r));
        }
        Assert.Equal(1, Power(new Vec3(0, 0, 0)), 5);
        Assert.Equal(Listener.ReferenceDistance / 3, Power(new Vec3(2, 0, 0)), 5);
        Assert.Equal(Listener.ReferenceDistance / 6, Power(new Vec3(5, 0, 0)), 5);
    }
}
