using System.Globalization;
using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Input.Modes;
using Billiards.App.Nodes;
using Billiards.App.Rendering;

namespace Billiards.App.Hud;

/// <summary>
/// The HUD: in a match the scoreboard (<see cref="ScoreboardBuilder"/>), the cue's gauges, the
/// called ball and pocket marked on the table and the result panel at game over; the developer
/// lines (mode, last shot's speed, spin, elevation, frame rate (Formel 4), pause state) behind
/// F2, and always outside a match; the help overlay. It only reads other nodes.
/// </summary>
public sealed class HudNode : Node
{
    private readonly List<string> _lines = [];
    private readonly List<HudIcon> _icons = [];
    private PhysicsNode? _physics;
    private InputModeNode? _modes;
    private CueNode? _cue;
    private SystemKeysNode? _keys;
    private MatchNode? _match;
    private Game.ReplayNode? _replay;
    private ComputerPlayerNode? _computer;
    private AimLineNode? _aimLine;
    private InstantReplayNode? _instant;
    private DiamondAidNode? _diamonds;
    private TakeBackNode? _takeBack;
    private Audio.AudioNode? _audio;
    private PracticeNode? _practice;
    private MenuNode? _menu;

    /// <summary>The frame-rate meter, fed every frame.</summary>
    public FrameRateMeter FrameRate { get; } = new();

    /// <summary>The lines of the last frame drawn.</summary>
    public IReadOnlyList<string> Lines => _lines;

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _modes = GetInTree<InputModeNode>();
        _keys = GetInTree<SystemKeysNode>();
        _cue = FindInTree<CueNode>();
        _physics.Struck += _ => _sinceShot = 0;
        _match = FindInTree<MatchNode>();
        _computer = FindInTree<ComputerPlayerNode>();
        _aimLine = FindInTree<AimLineNode>();
        _instant = FindInTree<InstantReplayNode>();
        _diamonds = FindInTree<DiamondAidNode>();
        _takeBack = FindInTree<TakeBackNode>();
        _practice = FindInTree<PracticeNode>();
        _help = HelpText.For(_match is not null, _practice is not null);
    }

    private IReadOnlyList<string> _help = HelpText.Lines;

    /// <summary>How long the meter keeps showing a shot's speed after the strike (s).</summary>
    public const double ShotShownSeconds = 2;

    /// <summary>The fastest stroke (m/s): Formel 31's cap.</summary>
    public const double MaxStrokeSpeed = Billiards.Core.Cue.ThesisCue.MaxStrokeSpeed / SeedControls.CentimetresPerMetre;

    private double _sinceShot = double.PositiveInfinity;

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        FrameRate.AddFrame(dt * 1000);
        _sinceShot += dt;
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        BuildLines();
        // A game file's shot rolling on its replay is shown as the instant replay is: no aim.
        bool replaying = _instant is { IsActive: true } || _replay is { IsShowing: true };
        // The tracking lines lie on the cloth, under the aim line; the replay shows no aim.
        var aids = new List<AidShape>(_instant?.Shapes(frame.Frame) ?? []);
        if (!replaying)
        {
            aids.AddRange(_aimLine?.Shapes(frame.Frame) ?? []);
            aids.AddRange(_diamonds?.Shapes(frame.Frame) ?? []);
            if (_aimLine?.CallShapes(frame.Frame) is { } call)
            {
                aids.AddRange(call);
            }
        }
        // Paused by P, not by a menu: the menu says so itself.
        _menu ??= FindInTree<MenuNode>();
        bool paused = _keys is { Loop.Paused: true } && _menu is not { Page: not MenuPage.None };
        var board = _match is not null && _physics is not null ? ScoreboardBuilder.Of(_match, _physics, _computer?.Status, paused, _audio?.StatusLine) : null;
        // Practice, drills and a record's replay show the match's scoreboard style, not the developer lines.
        board ??= _practice is not null ? ModeBoards.Of(_practice, _audio?.StatusLine)
            : _replay is not null && _physics is not null ? ModeBoards.Of(_replay, _physics, _audio?.StatusLine) : null;
        if (board is not null && _instant?.Status is { } replayLine)
        {
            // The scoreboard's status line tells the replay's time, speed and keys while it is shown.
            board = board with { Status = replayLine, Message = InstantReplayNode.KeysLine };
        }
        if (board is not null && _takeBack?.Refusal is { } refusal)
        {
            board = board with { Message = refusal };
        }
        frame.Frame.Hud = new HudInfo(_lines.ToArray(), _cue?.Tip.Fractions ?? Vector2.Zero, _keys?.ShowHelp ?? false, _help, Meter(), aids, _icons.ToArray())
        {
            Board = board,
            Developer = _keys?.ShowDeveloper ?? false,
            // Not at game over; the person's power not on the computer's turn.
            Gauges = _cue is { IsVisible: true } cue && _match is not { Session.IsOver: true } && !replaying
                ? new CueGauges(cue.Tip.Fractions, GaugeDegrees(cue.EffectiveElevationDegrees), KeyboardPower())
                : null,
            Result = _match is null ? null : ScoreboardBuilder.Result(_match),
            // Text on the cloth: the tracking lines' cushion counts, the diamond aid's numbers.
            Labels = [.. _instant?.Labels(frame.Frame) ?? [], .. replaying ? [] : _diamonds?.Labels(frame.Frame) ?? []],
        };
    }

    // The keyboard's power as a share of the strongest: the match's on a person's turn, practice's always.
    private float? KeyboardPower() => _match is { Session.IsComputerActing: false } m ? (float)(m.Power / MatchNode.MaxPower)
        : _match is null && _practice is not null ? (float)(_practice.Power / MatchNode.MaxPower) : null;

    /// <summary>Steps the elevation diagram is drawn in (degrees).</summary>
    public const double GaugeStepDegrees = 1;

    /// <summary>
    /// The elevation as the diagram draws it, in <see cref="GaugeStepDegrees"/>: the cue's lift
    /// over a rail or a ball changes by thousandths of a degree as the aim turns, which no one can
    /// see, but a diagram that changes in every frame keeps the HUD from its stored layer.
    /// </summary>
    public static float GaugeDegrees(double elevationDegrees) => (float)(Math.Round(elevationDegrees / GaugeStepDegrees) * GaugeStepDegrees);

    /// <summary>
    /// The power meter: while pushing, the push's speed (Formel 31) against the cap; while pulling
    /// back, the backswing; for two seconds after a strike, the shot's speed; otherwise none.
    /// </summary>
    public PowerMeter? Meter()
    {
        var c = CultureInfo.InvariantCulture;
        if (_modes is { IsStroking: true } modes)
        {
            double live = modes.LiveSpeed;
            if (live > 0)
            {
                return new PowerMeter((float)Math.Min(live / MaxStrokeSpeed, 1), string.Create(c, $"Power {live:0.00} m/s"), true);
            }
            double longest = SeedControls.MaxPullBack / SeedControls.PullBackMetresPerPixel;
            return new PowerMeter((float)Math.Min(modes.PullBackPixels / longest, 1), "Pull back, then push through", false);
        }
        if (_physics?.LastShot is { } shot && _sinceShot < ShotShownSeconds)
        {
            return new PowerMeter((float)Math.Min(shot.Speed / MaxStrokeSpeed, 1), string.Create(c, $"Shot {shot.Speed:0.00} m/s"), true);
        }
        return null;
    }

    private void BuildLines()
    {
        var c = CultureInfo.InvariantCulture;
        _lines.Clear();
        _icons.Clear();
        if (_modes is not null)
        {
            string locked = _modes.IsLocked ? " (balls rolling: view only)" : "";
            _lines.Add($"Mode: {ModeName(_modes.Mode)}{locked}");
        }
        if (_physics is { BallInHand: true } && _match is not { Session.IsComputerActing: true })
        {
            _lines.Add("Ball in hand: drag it (move mode, M), then S to shoot");
        }
        _lines.Add(_physics?.LastShot is { } shot
            ? string.Create(c, $"Last shot: {shot.Speed:0.00} m/s")
            : "Last shot: -");
        // The cue's settings only while it is there to be set: rolling balls would show stale ones.
        if (_cue is { IsVisible: true })
        {
            _lines.Add(string.Create(c, $"Spin: side {_cue.Tip.SideFraction:+0.00;-0.00;0.00} R, height {_cue.Tip.HeightFraction:+0.00;-0.00;0.00} R"));
            _lines.Add(_cue.EffectiveElevationDegrees > _cue.ElevationDegrees + 0.5
                ? string.Create(c, $"Elevation: {_cue.EffectiveElevationDegrees:0} deg ({(_cue.RailElevationDegrees >= _cue.ClearanceDegrees - 1e-9 ? "over the rail" : "over a ball")})")
                : string.Create(c, $"Elevation: {_cue.ElevationDegrees:0} deg"));
        }
        // A replay joins the tree after the HUD is ready: looked for while there is no match.
        _replay ??= _match is null ? FindInTree<Game.ReplayNode>() : null;
        if (_replay?.Status is { } replay)
        {
            _lines.Add(replay);
        }
        if (_instant?.Status is { } instant)
        {
            _lines.Add(instant);
            _lines.Add(InstantReplayNode.KeysLine);
        }
        if (_takeBack?.Refusal is { } refusal && _match is null)
        {
            _lines.Add(refusal);
        }
        if (_match is not null && _physics is not null)
        {
            MatchLines.Add(_lines, _match, _physics, _computer?.Status, _icons);
        }
        // The sound joins the tree after the game has started: looked for until found.
        _audio ??= FindInTree<Audio.AudioNode>();
        if (_audio?.StatusLine is { } sound)
        {
            _lines.Add(sound);
        }
        _lines.Add(string.Create(c, $"FPS: {FrameRate.Smoothed:0}"));
        if (_keys is { Loop.Paused: true })
        {
            _lines.Add("PAUSED (P resumes, N steps)");
        }
        _lines.Add("H or F1: help");
    }

    /// <summary>The HUD's name of a mode, with its key.</summary>
    public static string ModeName(InputMode mode) => mode switch
    {
        InputMode.View => "view [V]",
        InputMode.Shot => "shot [S]",
        InputMode.Spin => "spin [E]",
        InputMode.Move => "move cue ball [M]",
        _ => mode.ToString(),
    };
}
