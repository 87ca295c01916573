using Billiards.App.Platform;

namespace Billiards.App.Tests.Platform;

public class BackgroundWorkTests
{
    // Polled as the frame loop does, so that the checks after the work run on the calling thread.
    private static T Polled<T>(Task<T> task)
    {
        while (!task.IsCompleted)
        {
            Thread.Sleep(1);
        }
        return task.Result;
    }

    [Fact]
    public void BlockingWorkRunsOnAThreadOfItsOwnOffThePoolAtNormalPriority()
    {
        // The connections read and write on the thread pool: a join's handshake or a game loop
        // that blocked a pool thread would starve them on two busy cores.
        int? callerNice = BackgroundWork.Niceness();
        var (pooled, nice) = Polled(BackgroundWork.RunBlocking(() => (Thread.CurrentThread.IsThreadPoolThread, BackgroundWork.Niceness())));
        Assert.False(pooled);
        Assert.Equal(callerNice, nice);
        bool ranPooled = true;
        var done = BackgroundWork.RunBlocking(() => ranPooled = Thread.CurrentThread.IsThreadPoolThread);
        while (!done.IsCompleted)
        {
            Thread.Sleep(1);
        }
        Assert.True(done.IsCompletedSuccessfully);
        Assert.False(ranPooled);
    }

    [Fact]
    public void WorkRunsOnItsOwnThreadAtTheLowestPriorityAndLeavesTheCallerAlone()
    {
        int caller = Environment.CurrentManagedThreadId;
        int? callerNice = BackgroundWork.Niceness();
        var (thread, nice) = Polled(BackgroundWork.Run(() => (Environment.CurrentManagedThreadId, BackgroundWork.Niceness())));
        Assert.NotEqual(caller, thread);
        Assert.Equal(caller, Environment.CurrentManagedThreadId);
        if (OperatingSystem.IsLinux())
        {
            Assert.Equal(19, nice);
            Assert.Equal(callerNice, BackgroundWork.Niceness());
        }
    }

    [Fact]
    public void AParallelLoopInsideTheWorkRunsOnlyOnLowPriorityThreads()
    {
        var seen = Polled(BackgroundWork.Run(() =>
        {
            var nices = new System.Collections.Concurrent.ConcurrentBag<(int Thread, int? Nice)>();
            Parallel.For(0, 64, new ParallelOptions { MaxDegreeOfParallelism = 2, TaskScheduler = TaskScheduler.Current }, _ =>
            {
                nices.Add((Environment.CurrentManagedThreadId, BackgroundWork.Niceness()));
                Thread.SpinWait(20_000);
            });
            return nices.ToArray();
        }));
        Assert.Equal(64, seen.Length);
        if (OperatingSystem.IsLinux())
        {
            Assert.All(seen, s => Assert.Equal(19, s.Nice));
        }
    }

    [Fact]
    public async Task AnExceptionOfTheWorkReachesTheCaller()
    {
        var error = await Assert.ThrowsAsync<InvalidOperationException>(() => BackgroundWork.Run<int>(() => throw new InvalidOperationException("no shot")));
        Assert.Equal("no shot", error.Message);
    }
}
