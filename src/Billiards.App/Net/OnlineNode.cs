using System.Globalization;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Rules;

namespace Billiards.App.Net;

/// <summary>How a window takes part in a networked game: as the host (its listener) or as the joiner (its connection).</summary>
/// <param name="IsHost">True on the host, whose seat is player 0.</param>
/// <param name="Code">The game's code.</param>
/// <param name="Log">Where the network's log lines go (any thread).</param>
public sealed record OnlineLink(bool IsHost, string Code, Action<string> Log)
{
    /// <summary>The host's listener (the host only).</summary>
    public NetHost? Listener { get; init; }

    /// <summary>The joiner's connection, open after its handshake (the joiner only).</summary>
    public Connection? Connection { get; init; }

    /// <summary>Shots the host's game had when this joiner was admitted: more than 0 for a joiner coming back, who waits for the game so far.</summary>
    public int ShotsAtJoin { get; init; }

    /// <summary>How long a dropped peer may take to come back (<see cref="PeerWatch.DefaultComeBack"/> when null).</summary>
    public TimeSpan? ComeBack { get; init; }

    /// <summary>What the HUD says of the other end while no one joined (the host's address and code).</summary>
    public string? WaitingLine { get; init; }

    /// <summary>
    /// The joiner's way back to a host it lost (the same address, the same code): a new
    /// connection and the host's shots so far; it throws when the host is not there (yet) or
    /// refuses. Null on the host.
    /// </summary>
    public Func<(Connection Connection, int Shots)>? Rejoin { get; init; }
}

/// <summary>
/// The network at the table: the local seat's shots and choices go out, the peer's come in. The
/// connection reads and writes on its own tasks; each frame this node takes what arrived
/// (<see cref="NetPlay.Poll"/>, which never waits), and carries the peer's stroke out as the
/// computer's is shown (the cue turns to its aim, holds it, strikes). A dropped connection
/// holds the game (<see cref="PeerWatch"/>); a joiner coming back gets the host's game so far
/// and the game resumes at the same shot; a peer that does not come back in time loses by
/// forfeit. The HUD shows the connection's state and round-trip time.
/// </summary>
public sealed class OnlineNode : Node
{
    private readonly OnlineLink _link;
    private MatchNode? _match;
    private PhysicsNode? _physics;
    private NetPlay? _net;
    private GameShot? _peerShot;
    private double _aimFrom, _aimTime;
    private bool _sendGame;
    private bool _awaitGame;
    private int _shots;
    // The joiner trying its host again after a drop, and the seconds since the last try.
    private Task<(Connection Connection, int Shots)>? _rejoining;
    private double _sinceRejoin;
    private bool _rejoinFailed;

    /// <summary>Seconds between a joiner's tries to reach a host it lost.</summary>
    public const double RejoinSeconds = 3;

    // True while this node carries out what came from the network (the peer's moves, the host's game):
    // the session's signals of those shots and choices are not sent back.
    private bool _carrying;

    /// <summary>The network side of a window's game.</summary>
    public OnlineNode(OnlineLink link) : base("Online")
    {
        ArgumentNullException.ThrowIfNull(link);
        _link = link;
        Watch = new PeerWatch(link.ComeBack);
    }

    /// <summary>The pause and forfeit state.</summary>
    public PeerWatch Watch { get; }

    /// <summary>The game over the wire, once the tree is ready.</summary>
    public NetPlay? Play => _net;

    /// <summary>True for the peer's stroke shown at a quarter of the computer's pace (a scripted game).</summary>
    public bool Fast { get; set; }

    /// <summary>Shots played so far (read by the listener's thread for its hello).</summary>
    public int ShotsSoFar => Volatile.Read(ref _shots);

    /// <summary>The winner by forfeit (0 or 1), or null.</summary>
    public int? ForfeitWinner => _match?.Session.ForfeitWinner;

    /// <summary>What the HUD says of the connection now.</summary>
    public string StatusLine { get; private set; } = "";

    private double Share => Fast ? ComputerPlayerNode.FastShare : 1;

    private int LocalSeat => _link.IsHost ? 0 : 1;

    /// <inheritdoc />
    protected override void Ready()
    {
        _match = GetInTree<MatchNode>();
        _physics = GetInTree<PhysicsNode>();
        var session = _match.Session;
        session.TakeBacks = false;
        _net = new NetPlay(session, LocalSeat, _link.IsHost, _link.Log);
        session.Submitted += (shot, source) =>
        {
            if (source != SeatKind.Remote && !_carrying)
            {
                _net.SendShot(shot);
                _link.Log($"net: shot {_net.NextShot - 1}: stroke sent at {Stamp()}");
            }
        };
        session.Chosen += option =>
        {
            if (!_carrying)
            {
                _net.SendChoice(option);
            }
        };
        session.Ruled += _ => _net.Judged(session.Game.Shots[^1]);
        _net.Resynced += () =>
        {
            _awaitGame = false;
            _peerShot = null;
        };
        if (_link.Connection is { } connection)
        {
            _net.Connection = connection;
            _awaitGame = _link.ShotsAtJoin > 0;
        }
        Update(0);
    }

    /// <summary>A UTC time stamp to the tenth of a millisecond, for the latency read from the two sides' logs.</summary>
    public static string Stamp() => DateTime.UtcNow.ToString("HH:mm:ss.ffff", CultureInfo.InvariantCulture);

    /// <inheritdoc />
    protected override void Process(double dt) => Update(dt);

    private void Update(double dt)
    {
        if (_match is null || _net is null)
        {
            return;
        }
        var session = _match.Session;
        Volatile.Write(ref _shots, session.Shots.Count);
        // The listener's peer, admitted on its own task (perhaps before this window's first frame), or a new one coming back.
        if (_link.Listener?.Peer is { } connection && !ReferenceEquals(connection, _net.Connection))
        {
            _net.Connection = connection;
            _peerShot = null;
            _sendGame = session.Shots.Count > 0;
        }
        if (_sendGame && _net.SendGame())
        {
            _sendGame = false;
        }
        bool open = _net.Connection is { IsOpen: true };
        if (session.IsOver)
        {
            Watch.GameOver();
        }
        else if (open && !Watch.Joined() && Watch.State == LinkState.Forfeit)
        {
            // Too late: the game was lost by forfeit.
            _net.Connection!.Close("the game ended by forfeit");
        }
        else if (!open && Watch.State == LinkState.Connected && _net.Connection?.ClosedBecause is { } why && why.StartsWith("the peer said bye: refused: ", StringComparison.Ordinal))
        {
            // A joiner that refused the host's game (other physics) in its handshake never joined.
            Watch.Withdrawn();
        }
        else if (!open && Watch.State == LinkState.Connected)
        {
            // A stroke that came before the drop is carried out: the peer played it.
            Watch.Dropped();
            _link.Log($"net: the connection to {PeerName} dropped: the game waits {Watch.ComeBack.TotalSeconds:0} s for them to come back");
        }
        Rejoin(dt);
        if (Watch.Tick(dt))
        {
            session.Forfeit(LocalSeat, $"{PeerName} did not come back: {session.State.Players[LocalSeat]} wins by forfeit.");
            _link.Log($"net: {PeerName} did not come back within {Watch.ComeBack.TotalSeconds:0} s: {session.State.Players[LocalSeat]} wins by forfeit");
        }
        session.Held = Watch.State switch
        {
            LinkState.Waiting => _link.WaitingLine ?? "Waiting for the other player.",
            LinkState.Lost => $"Connection lost: waiting for {PeerName} to come back ({Clock(Watch.Left)}).",
            LinkState.Connected when _awaitGame || _sendGame => "Taking the game so far...",
            _ => null,
        };
        StatusLine = Watch.State switch
        {
            LinkState.Connected or LinkState.Ended when _net.Connection is { IsOpen: true } c =>
                string.Create(CultureInfo.InvariantCulture, $"Online: {PeerName} connected, {(c.RoundTripMs is double rtt ? $"{rtt:0} ms" : "-- ms")}"),
            LinkState.Ended => "Online: the game is over.",
            LinkState.Forfeit => $"Online: {PeerName} forfeits.",
            _ => $"Online: {session.Held}",
        };
        if ((session.Held is null || (_awaitGame && open) || _peerShot is not null || _net.MovesWaiting > 0) && session.ForfeitWinner is null)
        {
            // A joiner coming back takes the host's game from the wire too.
            PeerMoves(dt);
        }
    }

    private string PeerName => _match!.Session.State.Players[1 - LocalSeat];

    // A joiner whose host dropped tries it again every few seconds, on its own task: a host still
    // there (the connection lost, not the host's game) admits it as a joiner coming back and sends
    // its game, and the game resumes where it stood. A host that started again has a new game:
    // that is not this one, and the joiner goes on waiting (then wins by forfeit).
    private void Rejoin(double dt)
    {
        if (_link.Rejoin is not { } rejoin || Watch.State != LinkState.Lost)
        {
            return;
        }
        if (_rejoining is { IsCompleted: true } done)
        {
            _rejoining = null;
            if (!done.IsCompletedSuccessfully)
            {
                if (!_rejoinFailed)
                {
                    _link.Log($"net: the host is not there yet ({done.Exception!.InnerException!.Message}); trying every {RejoinSeconds:0} s");
                    _rejoinFailed = true;
                }
            }
            else if (done.Result is var (connection, shots) && shots == 0 && _match!.Session.Shots.Count > 0)
            {
                connection.Close("a new game is not this one");
                _link.Log("net: the host came back with a new game: this one is not resumed there");
            }
            else
            {
                _net!.Connection = done.Result.Connection;
                _peerShot = null;
                _awaitGame = done.Result.Shots > 0;
                _rejoinFailed = false;
                _link.Log($"net: back with the host ({done.Result.Shots} shots there): the game resumes");
            }
        }
        _sinceRejoin += dt;
        if (_rejoining is null && _sinceRejoin >= RejoinSeconds)
        {
            _sinceRejoin = 0;
            _rejoining = BackgroundWork.RunBlocking(rejoin);
        }
    }

    private static string Clock(double seconds)
    {
        int s = (int)Math.Ceiling(seconds);
        return $"{s / 60}:{s % 60:00}";
    }

    // The peer's choice at once; the peer's stroke as the computer's: the cue turns, holds, strikes.
    private void PeerMoves(double dt)
    {
        var match = _match!;
        if (_peerShot is null)
        {
            if (Carry(_net!.Poll) is not { } action)
            {
                return;
            }
            if (action.Choice is { } option)
            {
                Carry(() => match.Session.Choose(option));
                return;
            }
            _peerShot = action.Shot;
            _aimFrom = match.AimDegrees;
            _aimTime = 0;
            _link.Log($"net: shot {_net.NextShot}: stroke arrived, the cue turns at {Stamp()}");
            ShowPeerPlacement(_peerShot!.Place);
            match.Call.Take(_peerShot.Call);
        }
        var shot = _peerShot!;
        _aimTime += dt;
        double f = Math.Min(1, _aimTime / (ComputerPlayerNode.AimSeconds * Share));
        if (f < 1)
        {
            double smooth = f * f * (3 - (2 * f));
            match.AimAt(_aimFrom + (smooth * Math.IEEERemainder(shot.Shot.AimDeg - _aimFrom, 360)));
            return;
        }
        match.AimAt(shot.Shot.AimDeg);
        if (_aimTime < ComputerPlayerNode.StrokeSeconds * Share)
        {
            return;
        }
        _peerShot = null;
        ShowPeerPlacement(shot.Place);
        if (!match.StrikeGiven(shot, SeatKind.Remote))
        {
            _link.Log($"net: the peer's stroke for shot {_net!.NextShot} could not be struck here: {match.Session.Message}");
        }
    }

    private T Carry<T>(Func<T> what)
    {
        _carrying = true;
        try
        {
            return what();
        }
        finally
        {
            _carrying = false;
        }
    }

    private void Carry(Action what) => Carry(() =>
    {
        what();
        return 0;
    });

    // The peer's cue ball where they placed it (ball in hand), before their stroke: it is not in this player's hand.
    private void ShowPeerPlacement(Billiards.Core.Mathematics.Vec3? place)
    {
        var session = _match!.Session;
        if (place is not { } p || _physics is not { IsRolling: false } physics || session.BallInHand == BallInHand.None)
        {
            return;
        }
        physics.GiveBallInHand(session.BallInHand.Region());
        _match.PlaceCueBall(p);
        physics.EndBallInHand();
    }

    /// <summary>
    /// The game record with the forfeit when there was one: the last game's line gains
    /// <c>"forfeit": {"winner", "loser", "reason"}</c> (readers of the record ignore it; <c>replay --verify</c> checks the shots).
    /// </summary>
    public byte[] Annotate(byte[] records)
    {
        ArgumentNullException.ThrowIfNull(records);
        if (ForfeitWinner is not int w || _match is null)
        {
            return records;
        }
        string text = System.Text.Encoding.UTF8.GetString(records).TrimEnd('\n');
        int brace = text.LastIndexOf('}');
        var players = _match.Session.State.Players;
        string reason = $"{players[1 - w]} did not come back within {Watch.ComeBack.TotalSeconds:0} s of losing the connection";
        string forfeit = $",\"forfeit\":{{\"winner\":{Quote(players[w])},\"loser\":{Quote(players[1 - w])},\"reason\":{Quote(reason)}}}";
        return System.Text.Encoding.UTF8.GetBytes(text[..brace] + forfeit + text[brace..] + "\n");
    }

    private static string Quote(string s) => System.Text.Json.JsonSerializer.Serialize(s);

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        var f = frame.Frame;
        if (f.Hud is not { } hud || StatusLine.Length == 0 || FindInTree<Hud.MenuNode>() is { IsStartScreen: true })
        {
            return;
        }
        int scale = HudRenderer.Scale(f.Height);
        float line = HudFont.LineHeight * scale;
        // Above the power bar's label when the bar is shown, else where the bar would be.
        float y = f.Height - ((hud.Power is null ? 2.2f : 3.8f) * line);
        var labels = new List<HudLabel>(hud.Labels ?? []) { new(f.Width / 2f, y, StatusLine, Centred: true, Gold: _match?.Session.Held is not null) };
        f.Hud = hud with { Labels = labels };
    }
}
