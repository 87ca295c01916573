using Billiards.App.Cli;
using Billiards.App.Net;
using Billiards.Core.Cue;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Net;

/// <summary>A networked game on loopback: the same game on both sides, the refusals of the handshake on both sides, a forced mismatch resynced.</summary>
[Collection("Network")]
public class NetPlayTests
{
    private static string Record(Session s) => System.Text.Encoding.UTF8.GetString(GameRecordFile.ToJsonLines(s.RecordedGames));

    [Fact]
    public void BothSidesPlayTheSameGameAndTheirRecordsAreTheSameBytes()
    {
        using var game = new LoopbackGame();
        game.Connect();
        game.Play(12);
        Assert.True(game.HostSession.Shots.Count >= 12 || game.HostSession.IsOver);
        Assert.Equal(Record(game.HostSession), Record(game.JoinSession!));
        LoopbackGame.Until(() => game.Join!.Poll() is null && game.Host.Poll() is null && game.Host.Mismatches == 0, "poll");
        Assert.Equal(0, game.Host.Mismatches);
        Assert.Equal(0, game.Join!.Mismatches);
        Assert.NotNull(game.Host.Connection!.RoundTripMs ?? WaitForPing(game.Host.Connection));
    }

    // A peer that connects and says nothing past the hello's time is refused, and the line before
    // the refusal says how the host's reader stood: started, still waiting, nothing read.
    [Fact]
    public void ASilentPeerIsRefusedWithTheReadersState()
    {
        var log = new System.Collections.Concurrent.ConcurrentQueue<string>();
        var limits = NetLimits.Default with { HelloWithin = TimeSpan.FromSeconds(1) };
        using var host = new NetHost(System.Net.IPAddress.Loopback, 0, () => throw new InvalidOperationException("no peer is admitted"), log.Enqueue, limits);
        using var client = new System.Net.Sockets.TcpClient();
        client.Connect(System.Net.IPAddress.Loopback, host.Port);
        string port = ((System.Net.IPEndPoint)client.Client.LocalEndPoint!).Port.ToString(System.Globalization.CultureInfo.InvariantCulture);
        LoopbackGame.Until(() => log.Any(l => l.Contains("refused: no hello within 1 s", StringComparison.Ordinal)), "refused");
        string state = Assert.Single(log, l => l.StartsWith($"net: 127.0.0.1:{port}: no hello within 1 s: ", StringComparison.Ordinal));
        Assert.Matches(@"reader started at \d+ ms, running, 0 messages read; pool: \d+ threads, \d+ queued$", state);
    }

    [Theory]
    [InlineData("eight-ball")]
    [InlineData("snooker")]
    [InlineData("three-cushion")]
    public void TheJoinersSceneHasTheGamesBallSetAndRack(string rules)
    {
        var setup = GameSetup.Of(rules, seed: 5);
        var scene = NetCommands.SceneOf(setup);
        var ruleset = Ruleset.For(rules);
        Assert.Same(ruleset.BallSet, scene.BallSet);
        Assert.Equal(setup.Racked(0), scene.Layout);
        Assert.Equal(rules, scene.Rules);
        Assert.Equal($"{ruleset.Title} online", scene.Name);
    }

    private static double? WaitForPing(Connection c)
    {
        LoopbackGame.Until(() => c.RoundTripMs is not null, "no ping was answered");
        return c.RoundTripMs;
    }

    [Fact]
    public void AWrongCodeIsRefusedWithOneLineOnBothSides()
    {
        using var game = new LoopbackGame();
        var e = Assert.Throws<CliException>(() => game.Connect("ZZZZZZ"));
        Assert.Equal("join: the host refused: wrong code \"ZZZZZZ\"", e.Message);
        LoopbackGame.Until(() => game.HostLog.Any(l => l.EndsWith("refused: wrong code \"ZZZZZZ\"", StringComparison.Ordinal)), "the host logged no refusal");
    }

    [Fact]
    public void AnotherVersionIsRefusedWithOneLineOnBothSides()
    {
        using var game = new LoopbackGame();
        var e = Assert.Throws<CliException>(() => game.Connect(program: "0.0.9"));
        Assert.Contains($"version differs: billiards 0.0.9 there, {Handshake.ProgramVersion} here", e.Message, StringComparison.Ordinal);
        LoopbackGame.Until(() => game.HostLog.Any(l => l.Contains("refused: version differs: billiards 0.0.9 there", StringComparison.Ordinal)), "the host logged no refusal");
        // The joiner's side of it: a host of another version is refused by the joiner's own check too.
        using var other = new LoopbackGame(hostProgram: "9.9.9");
        Assert.Contains("version differs", Assert.Throws<CliException>(() => other.Connect()).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void OtherPhysicsAreRefusedWithOneLineOnBothSides()
    {
        // A host whose build writes the physics otherwise: its hash is not the one the joiner computes.
        static HostGame Other(GameSetup setup) => Handshake.Describe(setup) with { Hash = new string('e', 64) };
        using var game = new LoopbackGame(describe: Other);
        var e = Assert.Throws<CliException>(() => game.Connect());
        Assert.StartsWith("join: refused: physics differ: the host's", e.Message, StringComparison.Ordinal);
        LoopbackGame.Until(() => game.HostLog.Any(l => l.Contains("the peer said bye: refused: physics differ", StringComparison.Ordinal)), "the host logged no refusal");
    }

    [Fact]
    public void AMismatchIsResyncedFromTheHostAndTheGameGoesOn()
    {
        using var game = new LoopbackGame();
        game.Connect();
        game.Play(2);
        ForceMismatch(game);
        Assert.Contains(game.HostLog, l => l.StartsWith("net: desync after shot", StringComparison.Ordinal) && l.Contains("the host's game wins", StringComparison.Ordinal));
        Assert.Contains(game.JoinLog, l => l.StartsWith("net: resync: took the host's game", StringComparison.Ordinal));
        game.Play(4);
        Assert.Equal(Record(game.HostSession), Record(game.JoinSession!));
    }

    // The host's game ends at a ruling whose option is still to be chosen (a soft break: the
    // incoming player may take the table or have it racked again) when the joiner, whose table
    // drifted, takes it: the joiner stands there too, the same options offered, and the game goes
    // on from the choice. (The joiner once threw here, its game's thread with it.)
    [Fact]
    public void AMismatchAtAPendingOptionIsResyncedWithTheOptionStillToBeChosen()
    {
        using var game = new LoopbackGame();
        game.Connect();
        ForceMismatch(game, new GameShot(new ShotSpec(0.6, 0)));
        Assert.NotEmpty(game.HostSession.PendingOptions);
        Assert.Equal(game.HostSession.PendingOptions, game.JoinSession!.PendingOptions);
        Assert.Equal(game.HostSession.Shooter.Name, game.JoinSession.Shooter.Name);
        Assert.Equal(NetPlay.Hashes(game.HostSession.Game.Shots[^1]), NetPlay.Hashes(game.JoinSession.Game.Shots[^1]));
        // The shot played again sent no second hash of it (the host would refuse the connection).
        LoopbackGame.Until(() => game.Host.Poll() is null && game.Join!.Poll() is null, "poll");
        Assert.True(game.Host.Connection!.IsOpen, string.Join(" / ", game.HostLog));
        int mismatches = game.Host.Mismatches;
        game.Play(3);
        Assert.Equal(Record(game.HostSession), Record(game.JoinSession));
        Assert.Equal(mismatches, game.Host.Mismatches);
    }

    // A host's record that reads but cannot be played here (its last shot places the cue ball
    // where no ball is in hand) closes the connection with one line and leaves the joiner's game
    // as it stood; the joiner's game thread goes on (it once threw).
    [Fact]
    public void AResyncThatCannotBePlayedClosesTheConnectionWithALine()
    {
        using var game = new LoopbackGame();
        game.Connect();
        game.Play(2);
        Assert.Empty(game.HostSession.PendingOptions);
        string record = System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(game.HostSession.Game, indented: false)).TrimEnd('\n');
        int last = record.LastIndexOf("\"place\":null", StringComparison.Ordinal);
        Assert.True(last > record.IndexOf("\"place\":", StringComparison.Ordinal), "the record's last shot places no ball");
        string placed = string.Concat(record.AsSpan(0, last), "\"place\":[0.3,0.1]", record.AsSpan(last + "\"place\":null".Length));
        string joinersBefore = Record(game.JoinSession!);
        var parts = ResyncPacking.Pack(placed);
        for (int k = 0; k < parts.Count; k++)
        {
            game.Host.Connection!.Send(new Resync(game.HostSession.Shots.Count, k, parts.Count, parts[k]));
        }
        LoopbackGame.Until(() => { game.Join!.Poll(); return game.Join.Connection is { IsOpen: false }; }, $"the joiner kept the connection: {string.Join(" / ", game.JoinLog)}");
        Assert.Contains(game.JoinLog, l => l.Contains("refused: a resync that cannot be played here (", StringComparison.Ordinal));
        Assert.Equal(0, game.Join!.Resyncs);
        Assert.Equal(joinersBefore, Record(game.JoinSession!));
    }

    [Fact]
    public void ALongGameIsResyncedInSeveralMessagesEachUnder64KB()
    {
        // Straight pool with soft random shots: no end in sight after 62 shots, and the record is
        // more than one message holds (it was one message of at most 64 KB once, and failed here).
        using var game = new LoopbackGame(rules: GameRules.StraightPool, partChars: 4_000);
        game.Connect();
        game.Play(62);
        Assert.False(game.HostSession.IsOver);
        Assert.True(game.HostSession.Shots.Count >= 62);
        Assert.True(Record(game.HostSession).Length > Framing.MaxMessageBytes, $"the record is {Record(game.HostSession).Length} bytes");
        ForceMismatch(game);
        Assert.True(game.Host.ResyncParts > 1, $"{game.Host.ResyncParts} part(s)");
        Assert.Contains(game.HostLog, l => l.Contains($"sent in {game.Host.ResyncParts} messages", StringComparison.Ordinal));
        game.Play(3);
        Assert.Equal(Record(game.HostSession), Record(game.JoinSession!));
    }

    // The joiner's table drifts: the stroke that arrives is struck there a hair harder than it was
    // sent; the host finds the mismatch and sends its game, the joiner takes it.
    private static void ForceMismatch(LoopbackGame game, GameShot? struck = null)
    {
        var join = game.Join!;
        var host = game.Host;
        var local = host.Session.Shooter.Kind == SeatKind.Remote ? join : host;
        var remote = local == host ? join : host;
        var shot = struck ?? new GameShot(new ShotSpec(2.5, 97));
        local.Session.Play(shot, SeatKind.Person, _ => null);
        local.SendShot(shot);
        RemoteAction? action = null;
        LoopbackGame.Until(() => (action = remote.Poll()) is not null, "the stroke never arrived");
        var drifted = action!.Shot! with { Shot = action.Shot!.Shot with { Speed = action.Shot.Shot.Speed + 1e-6 } };
        remote.Session.Play(drifted, SeatKind.Remote, _ => null);
        LoopbackGame.Until(() => { host.Poll(); join.Poll(); return join.Resyncs == 1; }, $"no resync came: {string.Join(" / ", game.JoinLog)}");
        Assert.Equal(1, host.Resyncs);
    }

    [Fact]
    public void AStrokeOutOfTurnClosesTheConnectionWithALine()
    {
        using var game = new LoopbackGame();
        game.Connect();
        // The host breaks: a stroke from the joiner now is out of turn.
        game.Join!.Connection!.Send(new Stroke(0, 3, 0, 0, 0, 0, false));
        LoopbackGame.Until(() => { game.Host.Poll(); return game.Host.Connection is { IsOpen: false }; }, "the host kept the connection");
        Assert.Contains(game.HostLog, l => l.Contains("refused: stroke out of turn: it is Anna's turn", StringComparison.Ordinal));
        Assert.Empty(game.HostSession.Shots);
    }
}
