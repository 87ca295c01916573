namespace Billiards.App.Tests.Net;

/// <summary>
/// The tests that play over live loopback connections with timeouts of a few seconds (handshake,
/// frame deadlines, reconnects): they run alone, after the parallel tests, so that a full test run
/// on two cores cannot starve their readers past those timeouts.
/// </summary>
[CollectionDefinition("Network", DisableParallelization = true)]
public sealed class NetworkCollection;
