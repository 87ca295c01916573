using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Game;

/// <summary>
/// Plays a game record back in the window, shot by shot, on Core's <see cref="Match"/>: the shots
/// before <see cref="FirstShot"/> are played at once, headless; from there each recorded shot is
/// struck after <see cref="PauseSeconds"/> on the table the match keeps, run to rest and judged
/// as the record's writer ran it (<see cref="Match.RunToRest"/>, with the option the record took),
/// and shown by its replay (<see cref="ShotReplay"/>, run the same way, so the window shows the
/// very shot the record holds, whatever the integrator), at the playback's speed.
/// <see cref="NextShotKey"/> and <see cref="PreviousShotKey"/> go to the next and the previous
/// shot at any time (the match is restored from its snapshot before that shot, or played on to it
/// headless); the HUD shows the shot, its player and each shot's ruling once it has been seen. The
/// instant replay (R) and the tracking lines (K) work on each shot; the playback waits while the
/// instant replay is shown.
/// </summary>
public sealed class ReplayNode(GameRecord record, int firstShot, double timeScale = 1) : Node, IShowsShot
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
    private Session? _session;
    private int _next;
    private double _wait;
    private ShotReplay? _showing;
    private (Simulation Shot, SimulationSnapshot AtStrike)? _shown;
    private Ruling? _showingRuling;
    private string? _lastRuling;

    /// <summary>The first shot shown in the window (0 the break).</summary>
    public int FirstShot { get; } = firstShot;

    /// <summary>The rulings the window's shots got, in the order they were shown.</summary>
    public List<Ruling> Rulings { get; } = [];

    /// <summary>The shot shown now or next (0 the break).</summary>
    public int Shot => _next;

    /// <inheritdoc />
    public ShotReplay? ShownShot => _instant is { IsActive: true } ? null : _showing;

    /// <inheritdoc />
    public ShotSpec? ShownStrike => _showing is null ? null : record.Shots[_next].Shot;

    /// <inheritdoc />
    /// <remarks>A record's shot is always shown from its strike to its end: never.</remarks>
    public int ShownSeeks => 0;

    /// <summary>True while a shot is shown rolling.</summary>
    public bool IsShowing => _showing is not null;

    /// <summary>The HUD's line: the shot shown of the record's shots, its player, the last ruling seen and the keys.</summary>
    public string? Status
    {
        get
        {
            if (_session is null)
            {
                return null;
            }
            int n = record.Shots.Count;
            string ruling = _lastRuling is null ? "" : " " + _lastRuling;
            if (Finished)
            {
                return $"Replay: all {n} shots.{ruling}  [PageUp previous shot]";
            }
            string who = _showing is not null ? _shownState!.ShooterName : Game.State.ShooterName;
            // Counted from 1: the first of five shots is "shot 1 of 5".
            return $"Replay: shot {_next + 1} of {n} ({who}).{ruling}  [PageUp/PageDown shots]";
        }
    }

    private GameState? _shownState;

    // The game the session plays now.
    private Match Game => _session!.Game;

    /// <summary>The replayed match as it stands (the scoreboard reads it), or null before the node is ready.</summary>
    public Match? Match => _session?.Game;

    /// <summary>The shot shown or next, counted from 1, and the record's shots.</summary>
    public (int Shot, int Of) Counter => (Math.Min(_next + 1, record.Shots.Count), record.Shots.Count);

    /// <summary>The last ruling seen ("Shot 3: ..."), or null.</summary>
    public string? LastRuling => _lastRuling;

    /// <summary>True once the last shot has been shown.</summary>
    public bool Finished { get; private set; }

    /// <summary>Signal: a replayed shot has been shown and ruled on; the argument is the shot's index.</summary>
    public event Action<int, Ruling>? Ruled;

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _instant = FindInTree<InstantReplayNode>();
        _physics.HandOnly = true;
        _session = new Session(record.Setup, Seat.Of(record.Setup.Start.Players, SeatKind.Script), _physics.CreateSimulation);
        PlayTo(Math.Min(FirstShot, record.Shots.Count));
        _physics.CueBall = Game.Ruleset.CueBall(Game.State);
        _physics.Load(Game.Layout());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || Game.IsOver;
    }

    /// <summary>
    /// Shows shot <paramref name="shot"/> next (clamped to the record): the table as it stood before
    /// it, whether it lies before or after the one shown; it is struck after <see cref="PauseSeconds"/>.
    /// </summary>
    public void GoTo(int shot)
    {
        if (_physics is null || _session is null)
        {
            return;
        }
        int k = Math.Clamp(shot, 0, record.Shots.Count - 1);
        _instant?.Leave();
        _showing = null;
        if (_starts.TryGetValue(k, out var start))
        {
            Game.Restore(start);
            _next = k;
        }
        else
        {
            // Not reached yet: from the latest shot start known before it, played on headless.
            int from = _starts.Keys.Where(s => s <= k).DefaultIfEmpty(0).Max();
            Game.Restore(_starts[from]);
            _next = from;
            PlayTo(k);
        }
        _physics.CueBall = Game.Ruleset.CueBall(Game.State);
        _physics.Interrupt(Game.Layout());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || Game.IsOver;
    }

    // Plays the record's shots headless up to (not including) shot k, keeping each shot's start.
    private void PlayTo(int k)
    {
        _starts.TryAdd(_next, Game.Snapshot());
        for (; _next < k && !Game.IsOver; _next++)
        {
            _session!.Play(record.Shots[_next], SeatKind.Script);
            _starts.TryAdd(_next + 1, Game.Snapshot());
        }
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true } key || _session is null)
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
                // While a shot is shown, back to its start; between shots (or at the end), the one before.
                GoTo(_showing is not null ? _next : _next - 1);
                return true;
            default:
                return false;
        }
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_physics is null || _session is null || Finished || _instant is { IsActive: true })
        {
            return;
        }
        if (_showing is { } shown)
        {
            shown.Seek(shown.Time + (dt * timeScale));
            if (shown.Time >= shown.Duration)
            {
                EndShot();
            }
            return;
        }
        _wait -= dt;
        if (_wait <= 0)
        {
            Strike();
        }
    }

    // The shot as the record's writer played it: struck, run to rest in one go and judged; its
    // replay, run the same way, shows it.
    private void Strike()
    {
        var match = Game;
        _starts.TryAdd(_next, match.Snapshot());
        var input = record.Shots[_next];
        _shownState = match.State;
        int shot = _next;
        (Simulation Sim, SimulationSnapshot AtStrike, Billiards.Core.Mathematics.Vec3[] Positions)? struck = null;
        var played = _session!.Play(input, SeatKind.Script, judged => record.ChoiceAfter(shot, judged.Ruling) ?? judged.Ruling.Options[0],
            sim => struck = (sim, sim.CreateSnapshot(), ShotReplay.Positions(sim)));
        var (sim, atStrike, positions) = struck!.Value;
        _showing = new ShotReplay(sim.TableModel, sim.Ids, positions, sim.RefereeRules, atStrike, Match.MaxShotTime, ShotStepping.ToRest);
        _shown = (sim, atStrike);
        _showingRuling = played.Ruling;
    }

    private void EndShot()
    {
        var ruling = _showingRuling!;
        _showing = null;
        Rulings.Add(ruling);
        _lastRuling = $"Shot {_next + 1}: {ruling.Message}";
        // The next shooter's cue ball (a game may have one per player).
        _physics!.CueBall = Game.Ruleset.CueBall(Game.State);
        _physics.Load(Game.Layout());
        if (_shown is { } shown)
        {
            _physics.ShowStrike(shown.Shot, shown.AtStrike, ShotStepping.ToRest);
        }
        Ruled?.Invoke(_next, ruling);
        _next++;
        _starts.TryAdd(_next, Game.Snapshot());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || Game.IsOver;
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        if (_showing is not { } shown || _instant is { IsActive: true })
        {
            return;
        }
        // Drawn after the table: the shot's balls take its place.
        PhysicsNode.DrawInstead(frame, shown);
    }
}
