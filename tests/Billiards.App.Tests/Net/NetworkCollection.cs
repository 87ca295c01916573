namespace Billiards.App.Tests.Net;

/// <summary>
/// The tests that play over live loopback connections with timeouts of a few seconds (handshake,
/// frame deadlines, reconnects): they run alone, after the parallel tests, and with the thread
/// pool held to its floor (<see cref="ThreadPoolAtItsFloor"/>).
/// </summary>
[CollectionDefinition("Network", DisableParallelization = true)]
public sealed class NetworkCollection : ICollectionFixture<ThreadPoolAtItsFloor>;

/// <summary>
/// While the network tests run, the thread pool may have only two worker threads more than the
/// machine has cores (the test host's own messaging blocks up to two), as on a loaded two-core
/// machine where the pool adds none. The connections read and write on the pool, so anything that
/// blocks pool threads (game loops, blocking connects, a test's own socket calls) starves them past
/// their timeouts: with the pool held here it does so every time, not once in a few full runs.
/// Blocking work belongs on its own thread
/// (<see cref="Billiards.App.Platform.BackgroundWork.RunBlocking(System.Action)"/>).
/// </summary>
public sealed class ThreadPoolAtItsFloor : IDisposable
{
    /// <summary>Pool threads the test host's messaging may hold.</summary>
    public const int Spare = 2;

    private readonly int _workers, _ports;

    /// <summary>Holds the pool at <see cref="Environment.ProcessorCount"/> + <see cref="Spare"/> worker threads.</summary>
    public ThreadPoolAtItsFloor()
    {
        ThreadPool.GetMaxThreads(out _workers, out _ports);
        ThreadPool.GetMinThreads(out int minWorkers, out _);
        Assert.True(ThreadPool.SetMaxThreads(Math.Max(Environment.ProcessorCount, minWorkers) + Spare, _ports), "the thread pool's limit was not taken");
    }

    /// <summary>Gives the pool its limit back.</summary>
    public void Dispose() => ThreadPool.SetMaxThreads(_workers, _ports);
}
