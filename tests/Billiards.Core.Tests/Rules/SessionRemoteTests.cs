using Billiards.Core.Cue;
using Billiards.Core.Rules;

namespace Billiards.Core.Tests.Rules;

/// <summary>What the session keeps of a game over the network: a game held, a forfeit, a remote seat's turn, the host's game taken whole, and where each shot came from.</summary>
public class SessionRemoteTests
{
    private static Session Game() => new(GameSetup.Of(GameRules.EightBall, 1), [new Seat("Anna"), new Seat("Ben") { Kind = SeatKind.Remote }]);

    [Fact]
    public void AHeldGameAForfeitAndTheHostsGameTakenWhole()
    {
        var s = Game();
        var sources = new List<SeatKind>();
        s.Submitted += (_, source) => sources.Add(source);
        s.Held = "Waiting for a player.";
        Assert.True(s.IsHeld);
        s.Held = null;
        Assert.False(s.IsHeld);
        var before = s.Game.Snapshot();
        s.Play(new GameShot(new ShotSpec(8, 0)), SeatKind.Person, _ => null);
        Assert.Equal([SeatKind.Person], sources);
        Assert.Equal(s.Shooter.Kind == SeatKind.Remote && !s.IsOver, s.IsRemoteActing);
        // The host's game taken whole replaces the table.
        int replaced = 0;
        s.TableReplaced += () => replaced++;
        s.Restore(before);
        Assert.Equal(1, replaced);
        Assert.Empty(s.Game.Shots);
        Assert.False(s.IsRemoteActing);
        // A forfeit: no more shots, from anyone.
        s.Forfeit(0, "Ben did not come back: Anna wins by forfeit.");
        Assert.Equal(0, s.ForfeitWinner);
        Assert.True(s.IsHeld);
        Assert.False(s.IsRemoteActing);
        Assert.Equal("Ben did not come back: Anna wins by forfeit.", s.Message);
        Assert.Equal("The game ended by forfeit: no more shots.", s.WhyNot(SeatKind.Person));
        Assert.Null(s.Submit(new GameShot(new ShotSpec(3, 0)), SeatKind.Person));
        Assert.Single(sources);
    }

    [Fact]
    public void ARemoteSeatsShotIsItsOwnAndSaysWhereItCameFrom()
    {
        var s = Game();
        var sources = new List<SeatKind>();
        s.Submitted += (_, source) => sources.Add(source);
        // Anna breaks; her seat is not the remote one's.
        Assert.NotNull(s.WhyNot(SeatKind.Remote));
        Assert.Null(s.Submit(new GameShot(new ShotSpec(8, 0)), SeatKind.Remote));
        Assert.Empty(sources);
        s.Play(new GameShot(new ShotSpec(8, 0)), SeatKind.Person, _ => null);
        // Play soft shots until it is Ben's turn, then his shot from the network.
        for (int k = 0; k < 20 && s.Shooter.Kind != SeatKind.Remote && !s.IsOver; k++)
        {
            s.Play(new GameShot(new ShotSpec(0.5, 90)), SeatKind.Person, _ => null);
        }
        Assert.True(s.IsRemoteActing);
        s.Play(new GameShot(new ShotSpec(0.5, 90)), SeatKind.Remote, _ => null);
        Assert.Equal(SeatKind.Remote, sources[^1]);
    }
}
