using Billiards.App.Net;

namespace Billiards.App.Tests.Net;

/// <summary>
/// The pause and forfeit of a networked game (<see cref="PeerWatch"/>), driven by the seconds a
/// game loop hands it, with the 2 minutes shortened to a few seconds: no clock is read.
/// </summary>
public class PeerWatchTests
{
    [Fact]
    public void ItWaitsForTheFirstPeerAndHoldsTheGameUntilThen()
    {
        var watch = new PeerWatch(TimeSpan.FromSeconds(3));
        Assert.Equal(LinkState.Waiting, watch.State);
        Assert.True(watch.Holds);
        // No one yet: time passing is no forfeit.
        Assert.False(watch.Tick(10));
        Assert.True(watch.Joined());
        Assert.Equal(LinkState.Connected, watch.State);
        Assert.False(watch.Holds);
    }

    [Fact]
    public void APeerComingBackInTimeResumesTheGame()
    {
        var watch = new PeerWatch(TimeSpan.FromSeconds(3));
        watch.Joined();
        watch.Dropped();
        Assert.Equal(LinkState.Lost, watch.State);
        Assert.True(watch.Holds);
        Assert.False(watch.Tick(1.5));
        Assert.False(watch.Tick(1.4));
        Assert.Equal(0.1, watch.Left, 9);
        Assert.True(watch.Joined());
        Assert.Equal(LinkState.Connected, watch.State);
        Assert.Equal(1, watch.Returns);
        // A second drop starts a new wait of the whole time.
        watch.Dropped();
        Assert.Equal(3, watch.Left, 9);
    }

    [Fact]
    public void APeerNotBackInTimeLosesByForfeitOnceAndCannotComeBack()
    {
        var watch = new PeerWatch(TimeSpan.FromSeconds(3));
        watch.Joined();
        watch.Dropped();
        Assert.False(watch.Tick(2.9));
        Assert.True(watch.Tick(0.1));
        Assert.Equal(LinkState.Forfeit, watch.State);
        // The forfeit is told once; it stands.
        Assert.False(watch.Tick(5));
        Assert.False(watch.Joined());
        watch.GameOver();
        Assert.Equal(LinkState.Forfeit, watch.State);
    }

    [Fact]
    public void APeerThatRefusedTheGameInItsHandshakeNeverJoined()
    {
        var watch = new PeerWatch(TimeSpan.FromSeconds(3));
        watch.Joined();
        watch.Withdrawn();
        Assert.Equal(LinkState.Waiting, watch.State);
        // While a dropped peer is awaited, another that refuses leaves the clock running on.
        watch.Joined();
        watch.Dropped();
        watch.Tick(1);
        watch.Joined();
        watch.Withdrawn();
        Assert.Equal(LinkState.Lost, watch.State);
        Assert.Equal(0, watch.Returns);
        Assert.True(watch.Tick(2));
    }

    [Fact]
    public void AGameOverAtTheTableWaitsForNoOne()
    {
        var watch = new PeerWatch(TimeSpan.FromSeconds(3));
        watch.Joined();
        watch.GameOver();
        watch.Dropped();
        Assert.Equal(LinkState.Ended, watch.State);
        Assert.False(watch.Tick(10));
        Assert.False(watch.Holds);
    }

    [Fact]
    public void TheDefaultIsTwoMinutesAndATimeMustBePositive()
    {
        Assert.Equal(TimeSpan.FromMinutes(2), new PeerWatch().ComeBack);
        Assert.Throws<ArgumentOutOfRangeException>(() => new PeerWatch(TimeSpan.Zero));
    }
}
