using Billiards.App.Nodes;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Game;

/// <summary>
/// Plays a game record back in the window, shot by shot, on Core's <see cref="Match"/>: the shots
/// before <see cref="FirstShot"/> are played at once, headless; from there each recorded shot is
/// struck after <see cref="PauseSeconds"/> on the table the match keeps, runs in the physics node
/// and is judged when the balls rest, with the option the record took.
/// </summary>
public sealed class ReplayNode(GameRecord record, int firstShot) : Node
{
    /// <summary>Seconds the table stands still between two shots.</summary>
    public const double PauseSeconds = 1.0;

    private PhysicsNode? _physics;
    private Match? _match;
    private int _next;
    private double _wait;

    /// <summary>The first shot shown in the window (0 the break).</summary>
    public int FirstShot { get; } = firstShot;

    /// <summary>The rulings the window's shots got, in order.</summary>
    public List<Ruling> Rulings { get; } = [];

    /// <summary>The HUD's line: the shot shown of the record's shots and the last ruling's message.</summary>
    public string? Status => _match is null ? null
        : Finished ? $"Replay: all {record.Shots.Count} shots. {_match.LastRuling?.Message}"
        : $"Replay: shot {_next + 1} of {record.Shots.Count}.{(_match.LastRuling is { } r ? " " + r.Message : "")}";

    /// <summary>True once the last shot came to rest.</summary>
    public bool Finished { get; private set; }

    /// <summary>Signal: the referee ruled on a replayed shot; the argument is the shot's index.</summary>
    public event Action<int, Ruling>? Ruled;

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _physics.HandOnly = true;
        _match = new Match(record.Setup, _physics.CreateSimulation);
        for (_next = 0; _next < Math.Min(FirstShot, record.Shots.Count); _next++)
        {
            _match.Play(record.Shots[_next]);
        }
        _physics.StrikeThrough = _ => _match.Strike(record.Shots[_next]);
        _physics.CameToRest += _ => OnRest();
        _physics.CueBall = _match.Ruleset.CueBall(_match.State);
        _physics.Load(_match.Layout());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || _match.IsOver;
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_physics is null || _match is null || Finished || _physics.IsRolling)
        {
            return;
        }
        _wait -= dt;
        if (_wait <= 0)
        {
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
        _physics.CueBall = _match.Ruleset.CueBall(_match.State);
        _physics.Load(_match.Layout());
        _wait = PauseSeconds;
        Finished = _next >= record.Shots.Count || _match.IsOver;
    }
}
