using Billiards.App.Platform;

namespace Billiards.App.Tests.Platform;

public class FramePacerTests
{
    [Fact]
    public void FramesStartOnePeriodApartWhateverEachTook()
    {
        var pacer = new FramePacer(50);   // 20 ms
        double now = 0;
        var starts = new List<double>();
        foreach (double work in new[] { 0.005, 0.012, 0.001, 0.0199, 0.0 })
        {
            starts.Add(now);
            now += work;
            now += pacer.WaitAfter(now);
        }
        // The first frame sets the schedule; each later one starts 20 ms after the one before.
        Assert.Equal(0.005, starts[1], 12);
        for (int i = 2; i < starts.Count; i++)
        {
            Assert.Equal(0.02, starts[i] - starts[i - 1], 12);
        }
    }

    [Fact]
    public void AFrameThatRunsOverDoesNotMakeTheNextOnesHurry()
    {
        var pacer = new FramePacer(60);
        Assert.Equal(0, pacer.WaitAfter(1.0));
        Assert.Equal(1.0 / 60, pacer.WaitAfter(1.0), 12);        // due at 1 + 1/60
        Assert.Equal(0, pacer.WaitAfter(1.2));                  // ran far over: starts at once
        Assert.Equal(1.0 / 60 - 0.001, pacer.WaitAfter(1.201), 12); // and the schedule goes on from 1.2
    }

    [Fact]
    public void NoCapNeverWaits()
    {
        var pacer = new FramePacer(0);
        Assert.Equal(0, pacer.WaitAfter(0));
        Assert.Equal(0, pacer.WaitAfter(0.0001));
    }
}
