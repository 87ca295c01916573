using System.Net;
using Billiards.App.Net;
using Billiards.Core.Cue;
using Billiards.Core.Rules;

namespace Billiards.App.Tests.Net;

/// <summary>
/// A networked 8-ball game on loopback (127.0.0.1, a port the system chooses), headless: the host's
/// session with a listener, and a joiner connected through the real handshake. Each side plays its
/// own seat's shots through Session.Play and the other's from the wire, as the window does.
/// Every wait is bounded.
/// </summary>
internal sealed class LoopbackGame : IDisposable
{
    public const string Code = "K7PQ2M";
    private static readonly TimeSpan Wait = TimeSpan.FromSeconds(20);

    private readonly List<string> _hostLog = [], _joinLog = [];
    private readonly Random _random = new(38);

    public LoopbackGame(NetLimits? limits = null, string? hostProgram = null, Func<GameSetup, HostGame>? describe = null, GameRules? rules = null, int partChars = ResyncPacking.PartChars)
    {
        Setup = GameSetup.Of(rules ?? GameRules.EightBall, 1, new PerPlayer<string>("Anna", "Ben"));
        HostSession = new Session(Setup, [new Seat("Anna"), new Seat("Ben") { Kind = SeatKind.Remote }]);
        Host = new NetPlay(HostSession, 0, isHost: true, line => Log(_hostLog, line)) { PartChars = partChars };
        describe ??= Handshake.Describe;
        Listener = new NetHost(IPAddress.Loopback, 0, () => new Hello(hostProgram ?? Handshake.ProgramVersion, Code, describe(Setup), HostSession.Shots.Count), line => Log(_hostLog, line), limits);
        Listener.PeerAdmitted += (c, _) => Host.Connection = c;
        // Each ruling's hashes go out as the window sends them (OnlineNode).
        HostSession.Ruled += _ => Host.Judged(HostSession.Game.Shots[^1]);
    }

    public GameSetup Setup { get; }
    public Session HostSession { get; }
    public NetPlay Host { get; }
    public NetHost Listener { get; }
    public Session? JoinSession { get; private set; }
    public NetPlay? Join { get; private set; }

    public IReadOnlyList<string> HostLog { get { lock (_hostLog) { return [.. _hostLog]; } } }
    public IReadOnlyList<string> JoinLog { get { lock (_joinLog) { return [.. _joinLog]; } } }

    public void LogJoin(string line) => Log(_joinLog, line);

    private static void Log(List<string> log, string line)
    {
        lock (log)
        {
            log.Add(line);
        }
    }

    /// <summary>Joins with <paramref name="code"/> through the real handshake.</summary>
    public void Connect(string code = Code, string? program = null)
    {
        var (connection, setup, hello) = NetJoin.Connect("127.0.0.1", Listener.Port, code, LogJoin, program);
        var names = setup.Start.Players;
        JoinSession = new Session(setup, [new Seat(names.First) { Kind = SeatKind.Remote }, new Seat(names.Second)]);
        Join = new NetPlay(JoinSession, 1, isHost: false, LogJoin) { Connection = connection };
        JoinSession.Ruled += _ => Join.Judged(JoinSession.Game.Shots[^1]);
        Assert.Equal(0, hello.Shots);
        Until(() => Host.Connection is { IsOpen: true }, "the host never admitted the joiner");
    }

    /// <summary>Waits (bounded) for <paramref name="done"/>.</summary>
    public static void Until(Func<bool> done, string what)
    {
        var until = DateTime.UtcNow + Wait;
        while (!done())
        {
            Assert.True(DateTime.UtcNow < until, what);
            Thread.Sleep(2);
        }
    }

    /// <summary>
    /// Plays <paramref name="shots"/> shots (or to the end of the game): the seat to play strikes
    /// a seeded shot on its side and the other side carries it out from the wire; a ruling's
    /// option is the first one offered, chosen by the incoming player's side.
    /// </summary>
    public void Play(int shots)
    {
        var join = Join!;
        for (int k = 0; k < shots && !HostSession.IsOver; k++)
        {
            Choose();
            bool hostPlays = HostSession.Shooter.Kind != SeatKind.Remote;
            var (local, remote) = hostPlays ? (Host, join) : (join, Host);
            var shot = new GameShot(HostSession.Shots.Count == 0 ? new ShotSpec(8, 0) : new ShotSpec(1.5 + (_random.NextDouble() * 2), _random.NextDouble() * 360));
            local.Session.Play(shot, SeatKind.Person, _ => null);
            local.SendShot(shot);
            RemoteAction? action = null;
            Until(() => (action = remote.Poll()) is not null, $"shot {k} never arrived: host {string.Join(" / ", HostLog)} join {string.Join(" / ", JoinLog)}");
            remote.Session.Play(action!.Shot!, SeatKind.Remote, _ => null);
        }
        Choose();
    }

    private void Choose()
    {
        if (HostSession.PendingOptions.Count == 0)
        {
            return;
        }
        var option = HostSession.PendingOptions[0];
        bool hostChooses = HostSession.Shooter.Kind != SeatKind.Remote;
        var (local, remote) = hostChooses ? (Host, Join!) : (Join!, Host);
        local.Session.Choose(option);
        local.SendChoice(option);
        RemoteAction? action = null;
        Until(() => (action = remote.Poll()) is not null, "the choice never arrived");
        remote.Session.Choose(action!.Choice!.Value);
    }

    public void Dispose()
    {
        Join?.Connection?.Dispose();
        Listener.Dispose();
    }
}
