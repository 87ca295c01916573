using Billiards.Core.Cue;

namespace Billiards.Core.Tests.Thesis;

/// <summary>Formel 31 (stroke speed) and Formel 32-33 (tip point) of the cue.</summary>
public class QueueTests
{
    [Theory]
    [InlineData(100f, 50f, 500f)]   // 100 px / 50 ms * 250 = 500 cm/s
    [InlineData(20f, 100f, 50f)]    // 20 / 100 * 250 = 50
    [InlineData(400f, 100f, 800f)]  // 1000, capped at 800
    [InlineData(10f, 0f, 800f)]     // no time at all: the cap
    [InlineData(0f, 10f, 0f)]       // no forward travel: no strike speed
    public void Stroke_speed_is_distance_over_time_times_250_capped_at_800(float pixels, float ms, float expected)
    {
        Assert.Equal(expected, Queue.StrokeSpeed(pixels, ms), 1e-4f);
    }

    [Fact]
    public void The_tip_moves_a_hundredth_per_pixel_with_screen_y_down()
    {
        var queue = new Queue();
        queue.MoveTipPoint(100, 0);   // e_x = 0 + 100 * 0.01
        queue.MoveTipPoint(0, 50);    // e_y = 0 - 50 * 0.01
        Assert.Equal(1f, queue.EX, 1e-6f);
        Assert.Equal(-0.5f, queue.EY, 1e-6f);
    }

    [Fact]
    public void The_tip_is_pulled_back_onto_the_ball()
    {
        var queue = new Queue();
        queue.MoveTipPoint(300, -400);
        // (3, 4) has length 5 > 2.86: scaled by 2.86 / 5 to (1.716, 2.288).
        Assert.Equal(1.716f, queue.EX, 1e-5f);
        Assert.Equal(2.288f, queue.EY, 1e-5f);
    }

    [Fact]
    public void Reset_centres_the_tip_and_levels_the_cue()
    {
        var queue = new Queue { EX = 1, EY = 2, Grade = 10, Position = 40 };
        queue.Reset();
        Assert.Equal(0, queue.EX);
        Assert.Equal(0, queue.EY);
        Assert.Equal(0, queue.Grade);
        Assert.Equal(Queue.DefaultPosition, queue.Position);
    }
}
