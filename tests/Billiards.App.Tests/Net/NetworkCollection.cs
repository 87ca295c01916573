namespace Billiards.App.Tests.Net;

/// <summary>
/// The tests that play over live loopback connections with timeouts of a few seconds (handshake,
/// frame deadlines, reconnects): they run alone, after the parallel tests, and whatever blocks
/// (their game loops, their own sockets) runs on threads of its own
/// (<see cref="Billiards.App.Platform.BackgroundWork.RunBlocking(System.Action)"/>), never on the
/// thread pool the connections read and write on. The pool starts with enough threads
/// (<see cref="PoolWithThreadsAtHand"/>).
/// </summary>
[CollectionDefinition("Network", DisableParallelization = true)]
public sealed class NetworkCollection : ICollectionFixture<PoolWithThreadsAtHand>;

/// <summary>
/// While the network tests run, the thread pool makes up to <see cref="AtHand"/> worker threads at
/// once when work waits, instead of adding one every half second or so. In full test runs on two
/// busy cores the host's readers were once in a few runs left waiting past their 5 s handshake
/// and even 20 s, after hundreds of other tests in the same process; a game's process, which runs
/// one connection, has no such crowd.
/// </summary>
public sealed class PoolWithThreadsAtHand : IDisposable
{
    /// <summary>Worker threads the pool makes without waiting.</summary>
    public const int AtHand = 32;

    private readonly int _workers, _ports;

    /// <summary>Raises the pool's minimum to <see cref="AtHand"/> worker threads.</summary>
    public PoolWithThreadsAtHand()
    {
        ThreadPool.GetMinThreads(out _workers, out _ports);
        Assert.True(ThreadPool.SetMinThreads(Math.Max(_workers, AtHand), _ports), "the thread pool's minimum was not taken");
    }

    /// <summary>Gives the pool its minimum back.</summary>
    public void Dispose() => ThreadPool.SetMinThreads(_workers, _ports);
}
