using Billiards.App.Platform;

namespace Billiards.App.Tests.Platform;

public class BackgroundWorkTests
{
    [Fact]
    public async Task WorkRunsOnItsOwnThreadAtTheLowestPriorityAndLeavesTheCallerAlone()
    {
        int caller = Environment.CurrentManagedThreadId;
        int? callerNice = BackgroundWork.Niceness();
        var (thread, nice) = await BackgroundWork.Run(() => (Environment.CurrentManagedThreadId, BackgroundWork.Niceness()));
        Assert.NotEqual(caller, thread);
        if (OperatingSystem.IsLinux())
        {
            Assert.Equal(19, nice);
            Assert.Equal(callerNice, BackgroundWork.Niceness());
        }
    }

    [Fact]
    public async Task AnExceptionOfTheWorkReachesTheCaller()
    {
        var error = await Assert.ThrowsAsync<InvalidOperationException>(() => BackgroundWork.Run<int>(() => throw new InvalidOperationException("no shot")));
        Assert.Equal("no shot", error.Message);
    }
}
