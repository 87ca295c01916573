using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Ai;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// The computer at the table, and the hint for a person, both from Core's <see cref="ShotPlanner"/>.
/// A decision is searched on a background task (the frames go on: the search leaves one core to
/// the game), then the cue turns to the planned aim for <see cref="AimSeconds"/> and holds it
/// until <see cref="StrokeSeconds"/> have passed, the view behind its cue, before the strike: the
/// player sees what the computer plays. <see cref="Fast"/> (<c>play --fast-computer</c>) shortens both. A ruling's options are chosen the same way. The
/// computer's own error comes from <see cref="SkillLevel.Execute"/>; every seed derives from the
/// match's seed, the game and the shot, so the same game gets the same decisions.
/// <see cref="HintKey"/> asks the planner (at <see cref="HintLevel"/>) for a person's shot and
/// takes its placement, call, power and aim.
/// </summary>
public sealed class ComputerPlayerNode : Node
{
    /// <summary>How long the cue takes to turn to the computer's aim (s).</summary>
    public const double AimSeconds = 0.8;

    /// <summary>How long from the start of the computer's turn to its aim to its stroke (s): the turn, then the aim held.</summary>
    public const double StrokeSeconds = 1.5;

    /// <summary>The share of <see cref="AimSeconds"/> and <see cref="StrokeSeconds"/> a fast computer takes.</summary>
    public const double FastShare = 0.25;

    /// <summary>True for a fast computer: it turns and strikes in a quarter of the time.</summary>
    public bool Fast { get; set; }

    private double Share => Fast ? FastShare : 1;

    /// <summary>The key that asks for a hint.</summary>
    public const Key HintKey = Key.G;

    /// <summary>The planner's level for hints.</summary>
    public const int HintLevel = 3;

    private MatchNode? _match;
    private PhysicsNode? _physics;
    private SystemKeysNode? _keys;
    private InstantReplayNode? _replay;
    private ShotPlanner? _planner;
    private Task<Decision>? _thinking;
    private Task<RefereeOption>? _choosing;
    private Task<Decision>? _hinting;
    private Decision? _decision;
    private int _decisionLevel;
    private double _aimFrom;
    private double _aimTime;

    /// <summary>The planner's wall-clock cap per decision (ms); a script raises it so that no search is cut short by a slow machine.</summary>
    public int BudgetMs { get; set; } = PlannerBudget.DefaultMilliseconds;

    /// <summary>What the computer does now, for the HUD, or null.</summary>
    public string? Status { get; private set; }

    /// <summary>True while a hint is being searched.</summary>
    public bool IsHinting => _hinting is not null;

    /// <summary>The last hint taken, or null.</summary>
    public Decision? LastHint { get; private set; }

    /// <summary>
    /// What a hint says: the shot, its speed, and for a pot how often the planner saw it pot; a
    /// safety, a kick, a break or a push-out is not meant to pot, so no rate is given for it.
    /// </summary>
    public static string HintLine(Decision hint)
    {
        ArgumentNullException.ThrowIfNull(hint);
        var c = System.Globalization.CultureInfo.InvariantCulture;
        string what = hint.Call is { IsSafety: false } call ? Hud.BallWords.Pot(call.Ball, call.Pocket)
            : hint.Call is { IsSafety: true } ? "a safety"
            : $"{hint.Kind.ToString().ToLowerInvariant()} on the {Hud.BallWords.Of(hint.Target)}";
        // A carom with no pocket is a three-cushion point: it scores, it does not pot.
        string verb = hint.Kind == ShotKind.Carom && hint.Pocket == Billiards.Core.Table.PocketId.None ? "scores" : "pots";
        string rate = ShotKinds.IsPot(hint.Kind, hint.Pocket) ? string.Create(c, $" ({verb} {hint.ExpectedPot * 100:0} % of the time)") : "";
        return string.Create(c, $"Hint: {what} at {hint.Shot.Speed:0.0} m/s{rate}; Space shoots.");
    }

    // Leave a core to the game's frames: the search runs beside them, never in their way.
    private static PlannerBudget Budget(int ms) => new(ms, Math.Max(1, Environment.ProcessorCount - 1));

    /// <inheritdoc />
    protected override void Ready()
    {
        _match = GetInTree<MatchNode>();
        _physics = GetInTree<PhysicsNode>();
        _keys = FindInTree<SystemKeysNode>();
        _replay = FindInTree<InstantReplayNode>();
        _planner = new ShotPlanner(_physics.Table, _physics.Params, _physics.Models);
        // A take-back, a restart, a new game: the search and the aim were for a table that is gone (their tasks end unread).
        _match.Session.TableReplaced += () =>
        {
            _thinking = null;
            _choosing = null;
            _hinting = null;
            _decision = null;
            Status = null;
        };
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true, Key: HintKey } || _match is null || _physics is null || _planner is null)
        {
            return false;
        }
        if (_match.Session.IsComputerActing || !_match.CanShoot || _hinting is not null)
        {
            return true;
        }
        var state = _match.Session.State;
        var position = TablePosition.Of(_physics.Simulation, _physics.CueBall);
        var planner = _planner;
        ulong seed = _match.ShotSeed(3);
        var budget = Budget(BudgetMs);
        _hinting = BackgroundWork.Run(() => planner.Decide(state, position, SkillLevel.Of(HintLevel), budget, seed));
        Status = "Looking for a shot...";
        return true;
    }

    /// <summary>What the computer is seen to do while it turns its cue and holds its aim: the shot it plays, so that one can watch for it.</summary>
    public static string AimStatus(string name, Decision decision)
    {
        ArgumentNullException.ThrowIfNull(decision);
        // Short: the scoreboard's status line holds some 45 characters.
        string target = Hud.BallWords.Of(decision.Target);
        string pot = decision.Pocket == Billiards.Core.Table.PocketId.None ? target : $"{target} in {decision.Pocket.ToName()}";
        return decision.Kind switch
        {
            ShotKind.Break => $"{name} aims its break.",
            ShotKind.Safety => $"{name} aims a safety on the {target}.",
            ShotKind.PushOut => $"{name} aims a push-out.",
            ShotKind.Bank => $"{name} aims: {pot}, bank.",
            ShotKind.Kick => $"{name} aims: kick, {pot}.",
            ShotKind.Combination => $"{name} aims: combination, {pot}.",
            ShotKind.Carom => $"{name} aims: carom, {pot}.",
            _ => $"{name} aims: {pot}.",
        };
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_match is null || _physics is null || _planner is null)
        {
            return;
        }
        if (_keys is { Loop.Paused: true } || _replay is { IsActive: true })
        {
            // Paused (P, or the menu), or an instant replay watched: the computer waits too; its search may finish meanwhile.
            return;
        }
        FinishHint();
        if (_match.Session.IsOver || !_match.Session.IsComputerActing)
        {
            _decision = null;
            if (_hinting is null)
            {
                Status = null;
            }
            return;
        }
        if (_physics.IsRolling)
        {
            Status = null;
            return;
        }
        int level = _match.Session.Shooter.ComputerLevel ?? HintLevel;
        if (_match.Session.PendingOptions.Count > 0)
        {
            ChooseOption();
            return;
        }
        if (!_match.CanShoot)
        {
            return;
        }
        if (_decision is null && _thinking is null)
        {
            var state = _match.Session.State;
            var position = TablePosition.Of(_physics.Simulation, _physics.CueBall);
            var planner = _planner;
            ulong seed = _match.ShotSeed(1);
            var budget = Budget(BudgetMs);
            _decisionLevel = level;
            _thinking = BackgroundWork.Run(() => planner.Decide(state, position, SkillLevel.Of(level), budget, seed));
            Status = $"{_match.Session.State.ShooterName} is thinking...";
            return;
        }
        if (_thinking is { IsCompleted: true } done)
        {
            _thinking = null;
            if (!done.IsCompletedSuccessfully)
            {
                // A planner that fails must not stop the game: the computer plays a plain shot along its cue.
                Status = null;
                _match.StrikeAsComputer(new Billiards.Core.Cue.ShotSpec(3, _match.AimDegrees));
                return;
            }
            _decision = done.Result;
            // Adopt turns the cue to the aim at once; the turn is shown from where it was.
            _aimFrom = _match.AimDegrees;
            _match.Adopt(_decision, exactCall: true);
            _aimTime = 0;
            Status = AimStatus(_match.Session.State.ShooterName, _decision);
        }
        if (_decision is { } d)
        {
            _aimTime += dt;
            double f = Math.Min(1, _aimTime / (AimSeconds * Share));
            if (f < 1)
            {
                double smooth = f * f * (3 - (2 * f));
                _match.AimAt(_aimFrom + (smooth * Math.IEEERemainder(d.Shot.AimDeg - _aimFrom, 360)));
                return;
            }
            _match.AimAt(d.Shot.AimDeg);
            if (_aimTime < StrokeSeconds * Share)
            {
                // The aim held a moment: the player sees the shot before it is struck.
                return;
            }
            var struck = SkillLevel.Of(_decisionLevel).Execute(d.Shot, new PlannerRandom(_match.ShotSeed(2)));
            _decision = null;
            Status = null;
            _match.StrikeAsComputer(struck);
        }
    }

    private void ChooseOption()
    {
        if (_choosing is null)
        {
            var ruling = _match!.Session.LastRuling!;
            // The table as the shot left it (a scratched cue ball is off it), as self-play chooses.
            var position = new TablePosition(_match.Session.Game!.Shots[^1].After, _physics!.CueBall);
            var planner = _planner!;
            _choosing = BackgroundWork.Run(() => planner.ChooseOption(ruling, position));
            Status = $"{_match.Session.State.ShooterName} chooses...";
            return;
        }
        if (_choosing.IsCompleted)
        {
            var option = _choosing.IsCompletedSuccessfully ? _choosing.Result : _match!.Session.PendingOptions[0];
            _choosing = null;
            Status = null;
            if (_match!.Session.PendingOptions.Contains(option))
            {
                _match.Choose(option);
            }
        }
    }

    private void FinishHint()
    {
        if (_hinting is not { IsCompleted: true } done)
        {
            return;
        }
        _hinting = null;
        Status = null;
        if (done.IsCompletedSuccessfully && _match is { Session.IsComputerActing: false, CanShoot: true })
        {
            LastHint = done.Result;
            _match.Adopt(done.Result, exactCall: false);
            _match.Session.Say(HintLine(done.Result));
        }
    }
}
