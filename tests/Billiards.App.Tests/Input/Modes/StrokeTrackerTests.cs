using Billiards.App.Input.Modes;

namespace Billiards.App.Tests.Input.Modes;

/// <summary>Formel 31, s = d / t * 250 (d pixels, t ms, s cm/s capped at 800), worked by hand per case.</summary>
public class StrokeTrackerTests
{
    [Fact]
    public void PullBackThenPushThroughTheLineStrikesWithFormel31()
    {
        var stroke = new StrokeTracker();
        stroke.Begin(300, 0.000);                 // start line y = 300
        Assert.Null(stroke.Move(320, 0.010));     // back
        Assert.Null(stroke.Move(360, 0.030));     // back: 60 px behind the line
        Assert.Equal(60, stroke.PullBackPixels);
        Assert.Null(stroke.Move(350, 0.100));     // first forward move: d = 350 - 300 = 50 px, timer starts at 100 ms
        Assert.Equal(50, stroke.MeasuredDistance);
        Assert.Null(stroke.Move(320, 0.120));
        double? s = stroke.Move(290, 0.150);      // passes y = 300 at 150 ms: t = 50 ms
        Assert.Equal(50.0 / 50.0 * 250, s!.Value, 9); // 250 cm/s (times in s carry rounding)
        Assert.False(stroke.IsActive);
        Assert.Equal(2.5, SeedControls.ToMetresPerSecond(s.Value), 9);
    }

    [Fact]
    public void ABackwardMoveResetsDistanceAndTime()
    {
        var stroke = new StrokeTracker();
        stroke.Begin(300, 0.000);
        stroke.Move(360, 0.010);
        stroke.Move(340, 0.050);                  // forward: d = 40, timer at 50 ms
        Assert.Equal(40, stroke.MeasuredDistance);
        stroke.Move(380, 0.060);                  // back again: both cleared
        Assert.Equal(0, stroke.MeasuredDistance);
        stroke.Move(370, 0.100);                  // forward: d = 70, timer at 100 ms
        double? s = stroke.Move(295, 0.135);      // t = 35 ms
        Assert.Equal(70.0 / 35.0 * 250, s!.Value, 9); // 500 cm/s
    }

    [Fact]
    public void SpeedIsCappedAt800()
    {
        var stroke = new StrokeTracker();
        stroke.Begin(100, 0);
        stroke.Move(300, 0.5);
        stroke.Move(299, 1.0);                    // d = 199
        Assert.Equal(800, stroke.Move(90, 1.010)); // 199 / 10 * 250 = 4975 -> 800
    }

    [Fact]
    public void OneEventFromBehindToPastTheLineIsMeasuredFromThePreviousEvent()
    {
        var stroke = new StrokeTracker();
        stroke.Begin(300, 0.000);
        stroke.Move(340, 0.010);
        double? s = stroke.Move(290, 0.030);      // d = 340 - 300 = 40, t = 20 ms
        Assert.Equal(40.0 / 20.0 * 250, s!.Value, 9); // 500 cm/s
    }

    [Fact]
    public void PushingWithoutABackswingMovesTheLineInsteadOfStriking()
    {
        var stroke = new StrokeTracker();
        stroke.Begin(300, 0.000);
        Assert.Null(stroke.Move(280, 0.010));     // the tip is on the ball: the line follows to 280
        Assert.Equal(0, stroke.PullBackPixels);
        stroke.Move(300, 0.020);                  // 20 px behind the new line
        Assert.Equal(20, stroke.PullBackPixels);
        stroke.Move(290, 0.040);                  // d = 10, timer at 40 ms
        Assert.Equal(10.0 / 10.0 * 250, stroke.Move(279, 0.050)!.Value, 9); // t = 10 ms
    }

    [Fact]
    public void SidewaysMovesChangeNothingAndAnInactiveTrackerIgnoresMoves()
    {
        var stroke = new StrokeTracker();
        Assert.Null(stroke.Move(10, 0));
        stroke.Begin(300, 0);
        stroke.Move(340, 0.01);
        Assert.Null(stroke.Move(340, 0.5));       // same y: not a forward move, the timer has not started
        Assert.Equal(0, stroke.MeasuredDistance);
        stroke.Cancel();
        Assert.Null(stroke.Move(200, 0.6));
        Assert.Equal(0, stroke.PullBackPixels);
    }
}

public class TipOffsetTests
{
    [Fact]
    public void Formel3233MovesRightWithDxAndUpAgainstDy()
    {
        var tip = new TipOffset();
        tip.Move(100, -50);                       // e_x = 100 * 0.01 = 1 cm, e_y = -(-50) * 0.01 = 0.5 cm
        Assert.Equal(1.0, tip.X, 12);
        Assert.Equal(0.5, tip.Y, 12);
        Assert.Equal(1.0 / 2.86, tip.SideFraction, 12);
        Assert.Equal(0.5 / 2.86, tip.HeightFraction, 12);
    }

    [Fact]
    public void TheTipIsClampedRadiallyInsideTheBall()
    {
        var tip = new TipOffset();
        tip.Move(300, -400);                      // (3, 4) cm, length 5 > 0.9 * 2.86 = 2.574
        double max = 0.9 * 2.86;
        Assert.Equal(3.0 / 5 * max, tip.X, 12);
        Assert.Equal(4.0 / 5 * max, tip.Y, 12);
        Assert.Equal(0.9, Math.Sqrt(tip.SideFraction * tip.SideFraction + tip.HeightFraction * tip.HeightFraction), 12);
        tip.Move(-10_000, 0);                     // pushed far left: on the edge, still inside Core's unit disc
        Assert.True(tip.SideFraction * tip.SideFraction + tip.HeightFraction * tip.HeightFraction < 1);
    }
}
