using Billiards.Core.Balls;

namespace Billiards.Core.Tests.Balls;

/// <summary>Snooker's ball set (rules.md "Snooker").</summary>
public class SnookerBallSetTests
{
    [Fact]
    public void TheBallSetHasTheWhiteFifteenRedsAndTheSixColoursWithTheirValuesWithoutNumbers()
    {
        var set = BallSet.Snooker;
        Assert.Equal(22, set.Count);
        Assert.Equal(["cue", .. Enumerable.Range(1, 15).Select(k => $"red-{k}"), "yellow", "green", "brown", "blue", "pink", "black"], set.Balls.Select(b => b.Name));
        Assert.Equal([0, .. Enumerable.Repeat(1, 15), 2, 3, 4, 5, 6, 7], set.Balls.Select(b => b.Value));
        Assert.All(set.Balls, b => Assert.False(b.Look.Numbered || b.Look.Striped));
        Assert.Equal([set.Ids[0]], set.CueBalls);
        Assert.Equal(0.0525 / 2, set.Radius);
        Assert.Equal(0.142, set.Mass);
        // Names are unique across the sets: an id writes and reads as its ball's name.
        Assert.True(BallSet.Snooker.TryParse("pink", out var pink));
        Assert.Equal("pink", pink.ToString());
        Assert.Equal("7", new BallId(7).ToString());
        var red = BallSet.Snooker.Kind(BallSet.Snooker.Group("reds")[0]).Look;
        var pinkLook = BallSet.Snooker.Kind(pink).Look;
        Assert.True(red.Red > 0.5f && red.Green < 0.2f && pinkLook.Red > 0.8f && pinkLook.Blue > 0.4f);
    }
}
