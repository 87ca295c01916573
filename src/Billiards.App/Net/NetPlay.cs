using System.Security.Cryptography;
using System.Text;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Net;

/// <summary>What the peer did, for the game loop to carry out: a shot to strike as the remote seat's, or a choice.</summary>
public sealed record RemoteAction(GameShot? Shot, RefereeOption? Choice);

/// <summary>
/// A networked game over one <see cref="Session"/>: the local seat's shots and choices go out as
/// messages (a placement and a call before their stroke), the peer's are checked against the
/// session (the shot's number, the seat to play, the options offered) and handed to the game loop
/// one at a time by <see cref="Poll"/>, which never waits. After every judged shot each side sends
/// the hash of the balls at rest and of the ruling; on a mismatch the host's game wins: it sends
/// its record and the joiner replays it and takes its state. A message that makes no sense for the
/// game (a stroke out of turn, for a shot already played, an option not offered, a resync from the
/// joiner) is one log line and a closed connection.
/// </summary>
public sealed class NetPlay
{
    private readonly Action<string> _log;
    private readonly Dictionary<int, (string Balls, string Ruling)> _mine = [], _theirs = [];
    // The peer's moves not yet carried out here, in the order they came: a fast peer may be
    // several shots ahead of a side still showing an earlier one.
    private readonly Queue<Message> _moves = new();
    private int _lastStroke = -1;
    private bool _refused;
    // The parts of the host's game come so far (the joiner), and the resync they belong to.
    private readonly System.Text.StringBuilder _parts = new();
    private (int Shot, int Parts, int Next)? _resync;

    /// <summary>The peer's moves that came and wait to be carried out here.</summary>
    public int MovesWaiting => _moves.Count;

    /// <summary>Most moves of the peer waiting here at once (more is a flood of moves, not a game).</summary>
    public const int MaxMovesAhead = 64;

    /// <summary>A networked game of <paramref name="session"/>, this side playing seat <paramref name="localSeat"/>.</summary>
    public NetPlay(Session session, int localSeat, bool isHost, Action<string> log)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(log);
        Session = session;
        LocalSeat = localSeat;
        IsHost = isHost;
        _log = log;
    }

    /// <summary>The session played.</summary>
    public Session Session { get; }

    /// <summary>The seat this side plays (0 the host's).</summary>
    public int LocalSeat { get; }

    /// <summary>True on the host, whose game wins a mismatch.</summary>
    public bool IsHost { get; }

    /// <summary>
    /// The connection to the peer (replaced when a joiner comes back), or null while none. A new
    /// connection starts afresh: what the old one left half-said (a placement or call without its
    /// stroke, hashes of shots not compared, a refusal) is dropped.
    /// </summary>
    public Connection? Connection
    {
        get => _connection;
        set
        {
            _moves.Clear();
            _refused = false;
            _parts.Clear();
            _resync = null;
            _lastStroke = NextShot - 1;
            _theirs.Clear();
            _connection = value;
        }
    }

    private Connection? _connection;

    // True while the host's game is being taken (its shots are played here again).
    private bool _taking;

    /// <summary>Mismatches found so far.</summary>
    public int Mismatches { get; private set; }

    /// <summary>Resyncs taken (the joiner) or sent (the host).</summary>
    public int Resyncs { get; private set; }

    /// <summary>Messages the last resync sent took (the host): the record's parts.</summary>
    public int ResyncParts { get; private set; }

    /// <summary>Characters of the packed record per resync message (<see cref="ResyncPacking.PartChars"/>; tests send smaller parts).</summary>
    internal int PartChars { get; init; } = ResyncPacking.PartChars;

    /// <summary>Signal: the joiner took the host's game after a mismatch (the window shows the table again).</summary>
    public event Action? Resynced;

    /// <summary>The session's shot number of the next shot (every game's shots, in order).</summary>
    public int NextShot => Session.Shots.Count;

    /// <summary>Sends the local seat's shot just submitted (its placement and call first).</summary>
    public void SendShot(GameShot shot)
    {
        ArgumentNullException.ThrowIfNull(shot);
        int n = NextShot - 1;
        if (shot.Place is { } p)
        {
            Send(new Placement(n, p.X, p.Y));
        }
        if (shot.Call is { } c)
        {
            Send(new CallMessage(n, c.Ball == Core.Balls.BallId.None ? null : c.Ball.Value, c.Pocket.IsPocket ? c.Pocket.Name : null));
        }
        var s = shot.Shot;
        Send(new Stroke(n, s.Speed, s.AimDeg, s.TipSide, s.TipHeight, s.ElevationDeg, shot.PushOut));
    }

    /// <summary>The host sends its whole game (a joiner coming back takes it as a resync, an option still to be chosen included): false while a shot runs.</summary>
    public bool SendGame()
    {
        if (!IsHost || Session.IsShotRunning)
        {
            return false;
        }
        SendResync(NextShot);
        _log($"net: sent the game so far ({Session.Game.Shots.Count} shots) to the player coming back");
        return true;
    }

    // The host's whole game, packed and cut into messages of at most 64 KB (ResyncPacking).
    private void SendResync(int shot)
    {
        var record = Encoding.UTF8.GetString(GameRecordFile.ToUtf8(Session.Game, indented: false)).TrimEnd('\n');
        IReadOnlyList<string> parts;
        try
        {
            parts = ResyncPacking.Pack(record, PartChars);
        }
        catch (ArgumentException e)
        {
            _log($"net: the game is not sent: {e.Message}");
            return;
        }
        for (int k = 0; k < parts.Count; k++)
        {
            Send(new Resync(shot, k, parts.Count, parts[k]));
        }
        ResyncParts = parts.Count;
        _log($"net: the game ({record.Length} characters, {parts.Sum(p => p.Length)} packed) sent in {parts.Count} message{(parts.Count == 1 ? "" : "s")}");
    }

    /// <summary>Sends the local seat's choice after the last ruling.</summary>
    public void SendChoice(RefereeOption option) => Send(new Choice(NextShot - 1, option.ToName()));

    /// <summary>After a judged shot: sends its hashes and compares them with the peer's when both are in (not for the host's shots played again while its game is taken).</summary>
    public void Judged(MatchShot played)
    {
        ArgumentNullException.ThrowIfNull(played);
        if (_taking)
        {
            // The host's shots played again while its game is taken: the host has their hashes.
            return;
        }
        int n = NextShot - 1;
        var hashes = Hashes(played);
        _mine[n] = hashes;
        Send(new StateHash(n, hashes.Balls, hashes.Ruling));
        Compare(n);
    }

    /// <summary>The hash of the balls at rest after a shot (their ids and the bits of their positions) and of its ruling (the record's words for it).</summary>
    public static (string Balls, string Ruling) Hashes(MatchShot played)
    {
        ArgumentNullException.ThrowIfNull(played);
        var balls = new StringBuilder();
        foreach (var (id, pos) in played.After)
        {
            balls.Append(id.Value).Append(':').Append(BitConverter.DoubleToInt64Bits(pos.X)).Append(',')
                 .Append(BitConverter.DoubleToInt64Bits(pos.Y)).Append(',').Append(BitConverter.DoubleToInt64Bits(pos.Z)).Append(';');
        }
        var r = played.Ruling;
        string ruling = $"{r.Legal}|{string.Join(',', r.Fouls.Select(f => f.ToName()))}|{string.Join(',', r.Pocketed.Select(b => b.Value))}|{r.Continue}|{r.GameOver}|{r.Winner}|{r.Message}|{GameRecordFile.StateText(r.Next)}";
        return (Hex(balls.ToString()), Hex(ruling));
    }

    private static string Hex(string s) => Convert.ToHexStringLower(SHA256.HashData(Encoding.UTF8.GetBytes(s)));

    /// <summary>
    /// Takes the peer's messages that arrived and returns the next thing the peer did that may be
    /// carried out now (null when none): a choice among the options offered to the remote seat, or
    /// a stroke of the remote seat's turn once no shot runs. Never waits.
    /// </summary>
    public RemoteAction? Poll()
    {
        var connection = Connection;
        if (connection is null)
        {
            return null;
        }
        // What came before the peer left is still carried out (a last stroke, then its bye).
        while (!_refused && connection.TryReceive(out var m))
        {
            if (!Take(connection, m))
            {
                break;
            }
        }
        if (_refused || Session.IsShotRunning)
        {
            return null;
        }
        bool remoteToPlay = !Session.IsOver && Session.Shooter.Kind == SeatKind.Remote;
        if (!_moves.TryPeek(out var head))
        {
            return null;
        }
        if (head is Choice choice)
        {
            _moves.Dequeue();
            if (!remoteToPlay || Session.PendingOptions.Count == 0 || choice.Shot != NextShot - 1
                || !RuleNames.TryParseOption(choice.Option, out var option) || !Session.PendingOptions.Contains(option))
            {
                return Hostile(connection, $"choice \"{MessageCodec.Clip(choice.Option)}\" after shot {choice.Shot} is not offered to the peer now");
            }
            return new RemoteAction(null, option);
        }
        int shot = ShotOf(head);
        if (shot > NextShot)
        {
            // A move for a shot after one still to be played here waits for it.
            return null;
        }
        if (shot < NextShot)
        {
            return Hostile(connection, $"{head.Kind} for shot {shot}, already played (next is {NextShot})");
        }
        if (!_moves.Any(m => m is Stroke))
        {
            // The placement or call came; its stroke is on its way.
            return null;
        }
        Placement? p = null;
        CallMessage? c = null;
        Stroke? s = null;
        while (s is null)
        {
            switch (_moves.Dequeue())
            {
                case Placement placement:
                    p = placement;
                    break;
                case CallMessage call:
                    c = call;
                    break;
                case Stroke stroke:
                    s = stroke;
                    break;
                default:
                    return Hostile(connection, "a choice between a shot's call and its stroke");
            }
        }
        if (s.Shot != shot || (p is not null && p.Shot != shot) || (c is not null && c.Shot != shot))
        {
            return Hostile(connection, $"placement or call for shot {shot} without its stroke");
        }
        if (!remoteToPlay || Session.WhyNot(SeatKind.Remote) is not null)
        {
            return Hostile(connection, $"stroke out of turn: {(remoteToPlay ? Session.WhyNot(SeatKind.Remote) : $"it is {Session.State.ShooterName}'s turn")}");
        }
        Vec3? place = p is null ? null : new Vec3(p.X, p.Y, 0);
        Call? called = null;
        if (c is not null)
        {
            var pocket = Core.Table.PocketId.None;
            if (c.Pocket is { } name && !Session.Game.Setup.Table.Pockets.TryParse(name, out pocket))
            {
                return Hostile(connection, $"call of an unknown pocket \"{MessageCodec.Clip(name)}\"");
            }
            called = new Call(c.Ball is int b ? new Core.Balls.BallId(b) : Core.Balls.BallId.None, pocket);
        }
        if (place is not null && Session.BallInHand == BallInHand.None)
        {
            return Hostile(connection, $"placement for shot {s.Shot} without ball in hand");
        }
        return new RemoteAction(new GameShot(new ShotSpec(s.Speed, s.AimDeg, s.TipSide, s.TipHeight, s.ElevationDeg), called, place, s.PushOut), null);
    }

    // One message taken in; false when it closed the connection.
    private bool Take(Connection connection, Message m)
    {
        switch (m)
        {
            case Placement or CallMessage or Stroke when ShotOf(m) > _lastStroke && ShotOf(m) >= NextShot
                    && !_moves.Any(q => q.Kind == m.Kind && ShotOf(q) == ShotOf(m)) && _moves.Count < MaxMovesAhead:
                _moves.Enqueue(m);
                if (m is Stroke s)
                {
                    _lastStroke = s.Shot;
                }
                return true;
            case Choice c when c.Shot >= NextShot - 1 && _moves.Count < MaxMovesAhead:
                _moves.Enqueue(c);
                return true;
            case StateHash h when h.Shot < NextShot + MaxMovesAhead && !_theirs.ContainsKey(h.Shot):
                _theirs[h.Shot] = (h.Balls, h.Ruling);
                Compare(h.Shot);
                return true;
            case Resync r when !IsHost:
                TakePart(connection, r);
                return connection.IsOpen;
            case Bye:
                return false;
            default:
                Hostile(connection, m switch
                {
                    Hello => "a second hello",
                    Resync => "a resync from the joiner (the host's game wins)",
                    StateHash h => $"state hash for shot {h.Shot} twice or before it was played",
                    Placement or CallMessage or Stroke or Choice when _moves.Count >= MaxMovesAhead => $"more than {MaxMovesAhead} moves ahead",
                    Placement or CallMessage or Stroke or Choice => $"{m.Kind} for shot {ShotOf(m)} out of turn or twice (next is {NextShot})",
                    _ => $"{m.Kind} out of place",
                });
                return false;
        }
    }

    private static int ShotOf(Message m) => m switch { Placement p => p.Shot, CallMessage c => c.Shot, Stroke s => s.Shot, Choice c => c.Shot, _ => -1 };

    private void Compare(int shot)
    {
        if (!_mine.TryGetValue(shot, out var mine) || !_theirs.TryGetValue(shot, out var theirs) || mine == theirs)
        {
            return;
        }
        Mismatches++;
        string what = mine.Balls != theirs.Balls ? (mine.Ruling != theirs.Ruling ? "the balls at rest and the ruling" : "the balls at rest") : "the ruling";
        if (IsHost)
        {
            Resyncs++;
            _log($"net: desync after shot {shot}: {what} differ; the host's game wins and is sent whole");
            SendResync(shot);
        }
        else
        {
            _log($"net: desync after shot {shot}: {what} differ; waiting for the host's game");
        }
    }

    // A part of the host's game: the parts come in order, one resync at a time; the last one makes the game.
    private void TakePart(Connection connection, Resync r)
    {
        var expected = _resync ?? (r.Shot, r.Parts, 0);
        if (r.Shot != expected.Shot || r.Parts != expected.Parts || r.Part != expected.Next)
        {
            Hostile(connection, $"resync part {r.Part} of {r.Parts} for shot {r.Shot} out of order (expected part {expected.Next} of {expected.Parts} for shot {expected.Shot})");
            return;
        }
        _parts.Append(r.Record);
        _resync = expected with { Next = r.Part + 1 };
        if (r.Part + 1 < r.Parts)
        {
            return;
        }
        string joined = _parts.ToString();
        _parts.Clear();
        _resync = null;
        try
        {
            TakeResync(connection, r.Shot, ResyncPacking.Unpack(joined));
        }
        catch (ProtocolException e)
        {
            Hostile(connection, e.Message);
        }
    }

    private void TakeResync(Connection connection, int shot, string text)
    {
        GameRecord record;
        try
        {
            record = GameRecordFile.Parse(text, "the host's resync");
        }
        catch (SceneException e)
        {
            Hostile(connection, $"unreadable resync ({MessageCodec.Clip(e.Message)})");
            return;
        }
        // A record names its players in its shots' game blocks, not in its rack: the names are this side's.
        var mine = Session.Game.Setup;
        record = record with { Setup = record.Setup with { Start = record.Setup.Start with { Players = mine.Start.Players } } };
        if (!Equals(record.Setup, mine) || Session.IsShotRunning)
        {
            Hostile(connection, "resync of another game, or while a shot runs");
            return;
        }
        // The host's game is played on a game of its own first, so that a record that cannot be
        // played here leaves this side's game as it was. It is taken whole before its last shot,
        // and the last shot is played here again, so that an option it left to be chosen is
        // pending here too (a snapshot is taken between shots and holds none).
        int last = Math.Max(0, record.Shots.Count - 1);
        MatchSnapshot before;
        try
        {
            var host = new Session(record.Setup, Session.Seats);
            PlayAll(host, record, 0, last);
            before = host.Game.Snapshot();
            PlayAll(host, record, last, record.Shots.Count);
        }
        catch (Exception e) when (e is InvalidOperationException or ArgumentException)
        {
            // A record that reads but cannot be played (a placement where no ball is in hand).
            Hostile(connection, $"a resync that cannot be played here ({MessageCodec.Clip(e.Message)})");
            return;
        }
        _taking = true;
        try
        {
            Session.Restore(before);
            PlayAll(Session, record, last, record.Shots.Count);
        }
        finally
        {
            _taking = false;
        }
        // The hashes after the resync are the host's.
        foreach (int k in _mine.Keys.Where(k => k >= shot).ToList())
        {
            _mine.Remove(k);
        }
        Resyncs++;
        _log($"net: resync: took the host's game ({record.Shots.Count} shots)");
        Resynced?.Invoke();
    }

    // Plays the record's shots [from, to) into the session, each from the seat to play, each option the record's choice.
    private static void PlayAll(Session session, GameRecord record, int from, int to)
    {
        for (int k = from; k < to; k++)
        {
            int shot = k;
            session.Play(record.Shots[k], session.Shooter.Kind, judged => record.ChoiceAfter(shot, judged.Ruling));
        }
    }

    private RemoteAction? Hostile(Connection connection, string why)
    {
        _log($"net: {connection.Name}: refused: {why}");
        _refused = true;
        _moves.Clear();
        connection.Close(why);
        return null;
    }

    private void Send(Message m) => Connection?.Send(m);
}
