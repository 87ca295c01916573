namespace Billiards.App.Tests.Net;

/// <summary>
/// The tests that play over live loopback connections with timeouts of a few seconds (handshake,
/// frame deadlines, reconnects): they run alone, after the parallel tests, and whatever blocks
/// (their game loops, their own sockets) runs on threads of its own
/// (<see cref="Billiards.App.Platform.BackgroundWork.RunBlocking(System.Action)"/>), never on the
/// thread pool the connections read and write on.
/// </summary>
[CollectionDefinition("Network", DisableParallelization = true)]
public sealed class NetworkCollection;
