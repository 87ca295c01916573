using Billiards.App.Rendering;

namespace Billiards.App.Tests.Rendering;

public class ResolutionGovernorTests
{
    [Fact]
    public void SlowFramesLowerTheScaleAtOnceToItsFloorAndQuickOnesRaiseItSlowlyToFull()
    {
        var governor = new ResolutionGovernor();
        Assert.Equal(ResolutionGovernor.Start, governor.Scale);
        governor.Report(0.030, 1.0 / 60);
        Assert.Equal(ResolutionGovernor.Start * ResolutionGovernor.Down, governor.Scale, 6);
        for (int i = 0; i < 100; i++)
        {
            governor.Report(0.030, 1.0 / 60);
        }
        Assert.Equal(ResolutionGovernor.Min, governor.Scale);
        governor.Report(0.005, 1.0 / 60);
        Assert.Equal(ResolutionGovernor.Min * ResolutionGovernor.Up, governor.Scale, 6);
        // Within the band (60-90 % of the budget) it stays.
        float held = governor.Scale;
        governor.Report(0.8 / 60, 1.0 / 60);
        Assert.Equal(held, governor.Scale);
        for (int i = 0; i < 1000; i++)
        {
            governor.Report(0.001, 1.0 / 60);
        }
        Assert.Equal(ResolutionGovernor.Max, governor.Scale);
    }
}
