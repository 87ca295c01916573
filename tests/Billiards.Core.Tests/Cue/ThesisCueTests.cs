using Billiards.Core.Cue;

namespace Billiards.Core.Tests.Cue;

/// <summary>Formel 31 (stroke speed) and the reset of the cue.</summary>
public class ThesisCueTests
{
    [Theory]
    [InlineData(100f, 50f, 500f)]   // 100 px / 50 ms * 250 = 500 cm/s
    [InlineData(20f, 100f, 50f)]    // 20 / 100 * 250 = 50
    [InlineData(400f, 100f, 800f)]  // 1000, capped at 800
    [InlineData(10f, 0f, 800f)]     // no time at all: the cap
    [InlineData(0f, 10f, 0f)]       // no forward travel: no strike speed
    public void StrokeSpeedIsDistanceOverTimeTimes250CappedAt800(float pixels, float ms, float expected)
    {
        Assert.Equal(expected, ThesisCue.StrokeSpeed(pixels, ms), 1e-4f);
    }

    [Fact]
    public void ResetCentresTheTipAndLevelsTheCue()
    {
        var queue = new ThesisCue { EX = 1, EY = 2, Grade = 10 };
        queue.Reset();
        Assert.Equal(0, queue.EX);
        Assert.Equal(0, queue.EY);
        Assert.Equal(0, queue.Grade);
    }
}
