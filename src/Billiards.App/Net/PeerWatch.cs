namespace Billiards.App.Net;

/// <summary>Where a networked game stands with its peer.</summary>
public enum LinkState
{
    /// <summary>No peer yet (the host waits for a player to join).</summary>
    Waiting,
    /// <summary>The peer is connected: the game goes on.</summary>
    Connected,
    /// <summary>The connection dropped: the game is paused until the peer comes back or the time runs out.</summary>
    Lost,
    /// <summary>The peer did not come back in time: the waiting player won by forfeit.</summary>
    Forfeit,
    /// <summary>The game ended at the table; the connection no longer matters.</summary>
    Ended,
}

/// <summary>
/// The pause and the forfeit of a networked game: a dropped connection pauses it; the peer may
/// come back within <see cref="ComeBack"/> and the game resumes where it stood; after that the
/// waiting player wins by forfeit. Time is what the game loop hands to <see cref="Tick"/> (the
/// frames' seconds), so a test drives it without a clock.
/// </summary>
public sealed class PeerWatch
{
    /// <summary>How long a dropped peer may take to come back: 2 minutes.</summary>
    public static readonly TimeSpan DefaultComeBack = TimeSpan.FromMinutes(2);

    /// <summary>A watch that waits <paramref name="comeBack"/> for a dropped peer (<see cref="DefaultComeBack"/> when null).</summary>
    public PeerWatch(TimeSpan? comeBack = null)
    {
        ComeBack = comeBack ?? DefaultComeBack;
        if (ComeBack <= TimeSpan.Zero)
        {
            throw new ArgumentOutOfRangeException(nameof(comeBack), "the time to come back must be positive");
        }
    }

    /// <summary>How long a dropped peer may take to come back.</summary>
    public TimeSpan ComeBack { get; }

    /// <summary>Where the game stands with its peer.</summary>
    public LinkState State { get; private set; } = LinkState.Waiting;

    /// <summary>Seconds since the connection dropped (0 unless <see cref="LinkState.Lost"/> or <see cref="LinkState.Forfeit"/>).</summary>
    public double LostFor { get; private set; }

    /// <summary>Seconds left for the peer to come back (while <see cref="LinkState.Lost"/>).</summary>
    public double Left => Math.Max(0, ComeBack.TotalSeconds - LostFor);

    /// <summary>Times the peer came back after a drop.</summary>
    public int Returns { get; private set; }

    /// <summary>True while the game must not go on (no peer, or a dropped one).</summary>
    public bool Holds => State is LinkState.Waiting or LinkState.Lost;

    private (LinkState State, double LostFor) _beforeJoin;

    /// <summary>The peer is connected (first joined, or came back in time). False when it is too late.</summary>
    public bool Joined()
    {
        switch (State)
        {
            case LinkState.Waiting:
                _beforeJoin = (State, LostFor);
                State = LinkState.Connected;
                return true;
            case LinkState.Lost:
                _beforeJoin = (State, LostFor);
                State = LinkState.Connected;
                LostFor = 0;
                Returns++;
                return true;
            default:
                return State == LinkState.Connected;
        }
    }

    /// <summary>The peer that just joined refused the game in its handshake (other physics): the watch stands as before it came.</summary>
    public void Withdrawn()
    {
        if (State == LinkState.Connected)
        {
            if (_beforeJoin.State == LinkState.Lost)
            {
                Returns--;
            }
            (State, LostFor) = _beforeJoin;
        }
    }

    /// <summary>The connection dropped: the game pauses and the time to come back starts.</summary>
    public void Dropped()
    {
        if (State == LinkState.Connected)
        {
            State = LinkState.Lost;
            LostFor = 0;
        }
    }

    /// <summary>The game ended at the table: nothing is waited for any more.</summary>
    public void GameOver()
    {
        if (State != LinkState.Forfeit)
        {
            State = LinkState.Ended;
        }
    }

    /// <summary>Lets <paramref name="seconds"/> pass; true at the moment the peer's time runs out (the forfeit).</summary>
    public bool Tick(double seconds)
    {
        if (State != LinkState.Lost || !(seconds > 0))
        {
            return false;
        }
        LostFor += seconds;
        if (LostFor < ComeBack.TotalSeconds)
        {
            return false;
        }
        State = LinkState.Forfeit;
        return true;
    }
}
