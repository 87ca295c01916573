using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Game;

/// <summary>
/// Plays a game record back in the window, shot by shot, on Core's <see cref="Match"/>: the shots
/// before <see cref="FirstShot"/> are played at once, headless; from there each recorded shot is
/// struck after <see cref="PauseSeconds"/> on the table the match keeps, runs in the physics node
/// and is judged when the balls rest, with the option the record took. <see cref="NextShotKey"/>
/// and <see cref="PreviousShotKey"/> go to the next and the previous shot at any time (the match
/// is restored from its snapshot before that shot, or played on to it headless); the HUD shows
/// the shot, its player and each shot's ruling. The instant replay (R) works on each shot, and the
/// playback waits while it is shown.
/// </summary>
public sealed class ReplayNode(GameRecord record, int firstShot) : Node
{
    /// <summary>Seconds the table stands still between two shots.</summary>
    public const double PauseSeconds = 1.0;

    /// <summary>The key that goes to the next shot.</summary>
    public const Key NextShotKey = Key.PageDown;

    /// <summary>The key that goes back to the previous shot.</summary>
    public const Key PreviousShotKey = Key.PageUp;

    private readonly Dictionary<int, MatchSnapshot> _starts = [];
    private PhysicsNode? _physics;
    private InstantReplayNode? _instant;
    private Match? _match;
    private int _next;
    private double _wait;

    /// <summary>The first shot shown in the window (0 the break).</summary>
    public int FirstShot { get; } = firstShot;

    /// <summary>The rulings the window's shots got, in the order they were judged.</summary>
    public List<Ruling> Rulings { get; } = [];

    /// <summary>The shot shown now or next (0 the break).</summary>
    public int Shot => _next;

    /// <summary>The HUD's line: the shot shown of the record's shots, its player, the last ruling's message and the keys.</summary>
    public string? Status
    {
        get
        {
            if (_match is null)
            {
                return null;
            }
            int n = record.Shots.Count;
            string ruling = _match.Shots.Count > 0 ? $" Shot {_match.Shots.Count - 1}: {_match.LastRuling!.Message}" : "";
            if (Finished)
            {
                return $"Replay: all {n} shots.{ruling}  [PageUp previous shot]";
            }
            string who = _match.State.ShooterName;
            return $"Replay: shot {_next} of {n - 1} ({who}).{ruling}  [PageUp/PageDown shots]";
        }
    }

    /// <summary>True once the last shot came to rest.</summary>
    public bool Finished { get; private set; }

    /// <summary>Signal: the referee ruled on a replayed shot; the argument is the shot's index.</summary>
    public event Action<int, Ruling>? Ruled;

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _instant = FindInTree<InstantReplayNode>();
        _physics.HandOnly = true;
        _match = new Match(record.Setup, _physics.CreateSimulation);
        PlayTo(Math.Min(FirstShot, record.Shots.Count));
        _physics.StrikeThrough = _ => _match.Strike(record.Shots[_next]);
        _physics.CameToRest += _ => OnRest();
        _physics.Load(_match.Layout());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || _match.IsOver;
    }

    /// <summary>
    /// Shows shot <paramref name="shot"/> next (clamped to the record): the table as it stood before
    /// it, whether it lies before or after the one shown; it is struck after <see cref="PauseSeconds"/>.
    /// </summary>
    public void GoTo(int shot)
    {
        if (_physics is null || _match is null)
        {
            return;
        }
        int k = Math.Clamp(shot, 0, record.Shots.Count - 1);
        _instant?.Leave();
        if (_starts.TryGetValue(k, out var start))
        {
            _match.Restore(start);
            _next = k;
        }
        else
        {
            // Not reached yet: from the latest shot start known before it, played on headless.
            int from = _starts.Keys.Where(s => s <= k).DefaultIfEmpty(-1).Max();
            if (from >= 0)
            {
                _match.Restore(_starts[from]);
                _next = from;
            }
            else
            {
                _match.Restore(_starts[0]);
                _next = 0;
            }
            PlayTo(k);
        }
        _physics.Interrupt(_match.Layout());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || _match.IsOver;
    }

    // Plays the record's shots headless up to (not including) shot k, keeping each shot's start.
    private void PlayTo(int k)
    {
        _starts.TryAdd(_next, _match!.Snapshot());
        for (; _next < k && !_match.IsOver; _next++)
        {
            _match.Play(record.Shots[_next]);
            _starts.TryAdd(_next + 1, _match.Snapshot());
        }
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true } key || _match is null)
        {
            return false;
        }
        switch (key.Key)
        {
            case NextShotKey:
                if (_next + 1 < record.Shots.Count)
                {
                    GoTo(_next + 1);
                }
                return true;
            case PreviousShotKey:
                // While a shot rolls, back to its start; between shots (or at the end), the one before.
                GoTo(_physics is { IsRolling: true } ? _next : _next - 1);
                return true;
            default:
                return false;
        }
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_physics is null || _match is null || Finished || _physics.IsRolling || _instant is { IsActive: true })
        {
            return;
        }
        _wait -= dt;
        if (_wait <= 0)
        {
            _starts.TryAdd(_next, _match.Snapshot());
            _physics.Strike(record.Shots[_next].Shot);
        }
    }

    private void OnRest()
    {
        var played = _match!.Judge(_physics!.Simulation);
        if (_match.PendingOptions.Count > 0)
        {
            _match.Choose(record.Shots[_next].Choice ?? _match.PendingOptions[0]);
        }
        Rulings.Add(played.Ruling);
        Ruled?.Invoke(_next, played.Ruling);
        _next++;
        _starts.TryAdd(_next, _match.Snapshot());
        _physics.Load(_match.Layout());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || _match.IsOver;
    }
}
