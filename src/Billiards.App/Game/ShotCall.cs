using Billiards.App.Camera;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// The call being picked for the shot a match composes: the ball and pocket chosen (B and C, a
/// click, a plan's call), else the aimed ball and its easiest pocket, else the nearest legal
/// target; in snooker the nomination. The ruleset says which balls are legal: never the
/// opponent's group. Part of <see cref="MatchNode"/>, which reads it for the strike.
/// </summary>
public sealed class ShotCall
{
    private readonly MatchNode _match;
    private PhysicsNode? _physics;
    private BallId? _calledBall;
    private PocketId? _calledPocket;

    internal ShotCall(MatchNode match) => _match = match;

    // The call asks the game's constraints only: which balls may be hit first and called.
    private IShotConstraints Constraints => _match.Session.Ruleset;

    /// <summary>The table's geometry (pocket circles), once the match is in the tree.</summary>
    public TableGeometry? Geometry { get; private set; }

    internal void Ready(PhysicsNode physics)
    {
        _physics = physics;
        Geometry = TableGeometry.Build(physics.Table, physics.BallRadius);
    }

    /// <summary>Forgets the ball and the pocket chosen (a strike, a new table).</summary>
    public void Clear()
    {
        _calledBall = null;
        _calledPocket = null;
    }

    /// <summary>Takes a plan's call (not a safety's).</summary>
    public void Take(Call? call)
    {
        _calledBall = call is { IsSafety: false } c ? c.Ball : null;
        _calledPocket = call is { IsSafety: false } c2 ? c2.Pocket : null;
    }

    /// <summary>Calls a ball: its easiest pocket until a pocket is called; in snooker it nominates the ball where the shooter may nominate it.</summary>
    public void CallBall(BallId ball)
    {
        if (_match.CanShoot && (!_match.NeedsNomination || Constraints.MayCall(_match.Session.State, ball)))
        {
            _calledBall = ball;
            _calledPocket = null;
        }
    }

    /// <summary>Calls a pocket for the called ball, or for the aimed one.</summary>
    public void CallPocket(PocketId pocket)
    {
        if (_match.CanShoot)
        {
            _calledBall ??= DefaultBall(_match.Aim);
            _calledPocket = pocket;
        }
    }

    /// <summary>
    /// The call the shooter makes now: the chosen ball (else the aimed one when it is a legal
    /// target, else the legal target nearest the cue ball) and the chosen pocket (else that
    /// ball's easiest pocket).
    /// </summary>
    public Call? CurrentCall
    {
        get
        {
            var aim = _match.Aim;
            var ball = _calledBall ?? DefaultBall(aim);
            if (ball is not { } b || PocketFor(b, aim) is not { } pocket || pocket == PocketId.None)
            {
                return null;
            }
            return new Call(b, pocket);
        }
    }

    /// <summary>
    /// The nomination the shooter makes now: the ball chosen (B, or a click), else the aimed ball,
    /// else the nearest ball, among those the shooter may nominate; null where nothing is nominated.
    /// </summary>
    public Call? CurrentNomination
    {
        get
        {
            if (!_match.NeedsNomination || _physics is null)
            {
                return null;
            }
            var may = Nominatable();
            var aimed = _match.Aim?.Ball;
            // A free ball while on the reds is nominated as a colour (rules.md): the default is a colour.
            List<BallId> byDefault = SnookerPart.Of(_match.Session.State).FreeBall && _match.Session.Ruleset is SnookerRuleset && SnookerRuleset.BallOnOf(_match.Session.State) == SnookerRuleset.Red && may.Any(SnookerRuleset.IsColour)
                ? [.. may.Where(SnookerRuleset.IsColour)]
                : may;
            var ball = _calledBall is { } c && may.Contains(c) ? c
                : aimed is { } a && byDefault.Contains(a) ? a
                : Nearest(_physics.CueBallPosition with { Z = 0 }, byDefault);
            return ball is { } b ? Call.Nominate(b) : null;
        }
    }

    private List<BallId> Nominatable() => [.. _physics!.ObjectBallsOnTable().Where(b => Constraints.MayCall(_match.Session.State, b)).OrderBy(b => b.Value)];

    /// <summary>
    /// X: the cue aims at the ghost ball that sends the called ball (or, with no call, the nearest
    /// ball) straight at its pocket's centre; geometry only, so cut shots still need the player's eye.
    /// </summary>
    public void AimAtCall()
    {
        if (_physics is null || Geometry is null)
        {
            return;
        }
        var sim = _physics.Simulation;
        var cue = _physics.CueBallPosition with { Z = 0 };
        var aim = _match.Aim;
        var ball = _calledBall ?? DefaultBall(aim);
        if (ball is not { } b || PocketFor(b, aim) is not { } pocket)
        {
            return;
        }
        var target = sim.Balls[sim.IndexOf(b)].Position with { Z = 0 };
        Vec3? centre = null;
        foreach (var circle in Geometry.Pockets)
        {
            if (circle.Pocket == pocket.Index)
            {
                centre = circle.Centre with { Z = 0 };
            }
        }
        if (centre is not { } c)
        {
            return;
        }
        _calledBall = b;
        _calledPocket = pocket;
        var ghost = target - 2 * _physics.BallRadius * (c - target).Normalized();
        double want = ViewMath.AimDegrees(ghost - cue);
        _match.Turn(Math.IEEERemainder(want - _match.AimDegrees, 360));
        // The camera's eye is not exactly behind the ball after recentring: one more pass corrects the rest.
        _match.Turn(Math.IEEERemainder(want - _match.AimDegrees, 360));
    }

    /// <summary>C: the next pocket round the table for the called (or aimed) ball.</summary>
    public void CyclePocket()
    {
        var pockets = _physics?.Table.Pockets.Ids ?? [];
        if (pockets.Count == 0)
        {
            return;
        }
        var current = CurrentCall?.Pocket ?? _calledPocket ?? PocketId.None;
        int at = -1;
        for (int i = 0; i < pockets.Count; i++)
        {
            at = pockets[i] == current ? i : at;
        }
        _calledPocket = pockets[(at + 1) % pockets.Count];
        _calledBall ??= DefaultBall(_match.Aim);
    }

    /// <summary>B: the next ball on the table (nominating, the next ball the shooter may nominate).</summary>
    public void CycleBall()
    {
        if (_physics is null)
        {
            return;
        }
        var onTable = _match.NeedsNomination ? Nominatable() : _physics.ObjectBallsOnTable();
        if (onTable.Count == 0)
        {
            return;
        }
        var current = _match.NeedsNomination ? CurrentNomination?.Ball : _calledBall ?? _match.Aim?.Ball;
        int k = current is { } c ? onTable.IndexOf(c) : -1;
        _calledBall = onTable[(k + 1) % onTable.Count];
    }

    // The pocket called for a ball: the one chosen with C, else the aimed ball's easiest pocket
    // along its line from the ghost ball, else (a ball chosen with B) the easiest pocket along the
    // line from the cue ball through it.
    private PocketId? PocketFor(BallId ball, AimPreview? aim)
    {
        if (_calledPocket is { } chosen)
        {
            return chosen;
        }
        if (aim is not null && aim.Ball == ball && (!_match.NeedsCall || IsOpen(ball, aim.Pocket)))
        {
            return aim.Pocket;
        }
        return (_match.NeedsCall ? OpenPocket(ball) : null) ?? (aim is not null && aim.Ball == ball ? aim.Pocket : EasiestPocket(ball, null));
    }

    // The easiest pocket along the line from the cue ball through the ball, among those allowed.
    private PocketId? EasiestPocket(BallId ball, Func<PocketId, bool>? allowed)
    {
        if (_physics is null || Geometry is null || _physics.Simulation.IndexOf(ball) is not (>= 0 and var i))
        {
            return null;
        }
        var target = _physics.Simulation.Balls[i].Position with { Z = 0 };
        var cue = _physics.CueBallPosition with { Z = 0 };
        var pocket = AimPreview.EasiestPocket(target, (target - cue).Normalized(), Geometry.Pockets, Geometry.Spec.Pockets, allowed);
        return pocket == PocketId.None ? null : pocket;
    }

    // The ball's easiest open pocket, or null where every pocket is blocked.
    private PocketId? OpenPocket(BallId ball) => EasiestPocket(ball, p => IsOpen(ball, p));

    /// <summary>
    /// True when the ball is an open pot into the pocket: no other ball lies across the object
    /// ball's line to the pocket's centre, nor across the cue ball's line to the ghost ball.
    /// </summary>
    public bool IsOpen(BallId ball, PocketId pocket)
    {
        if (_physics is null || Geometry is null || _physics.Simulation.IndexOf(ball) is not (>= 0 and var i))
        {
            return false;
        }
        Vec3? centre = null;
        foreach (var circle in Geometry.Pockets)
        {
            centre = circle.Pocket == pocket.Index ? circle.Centre with { Z = 0 } : centre;
        }
        if (centre is not { } c)
        {
            return false;
        }
        var sim = _physics.Simulation;
        double r = _physics.BallRadius;
        var target = sim.Balls[i].Position with { Z = 0 };
        var cue = _physics.CueBallPosition with { Z = 0 };
        var ghost = target - 2 * r * (c - target).Normalized();
        for (int k = 0; k < sim.Ids.Count; k++)
        {
            if (k == i || sim.Balls[k].IsPocketed)
            {
                continue;
            }
            var at = sim.Balls[k].Position with { Z = 0 };
            bool isCue = sim.Ids[k] == _physics.CueBall;
            if (DistanceToSegment(at, target, c) < 2 * r || (!isCue && DistanceToSegment(at, cue, ghost) < 2 * r))
            {
                return false;
            }
        }
        return true;
    }

    private static double DistanceToSegment(Vec3 p, Vec3 a, Vec3 b)
    {
        var ab = b - a;
        double length2 = Vec3.Dot(ab, ab);
        double t = length2 < 1e-18 ? 0 : Math.Clamp(Vec3.Dot(p - a, ab) / length2, 0, 1);
        return (p - (a + (t * ab))).Length;
    }

    // The aimed ball when the shooter may hit it first and it has an open pot, else the nearest such
    // ball; with no open pot anywhere, or in a game that calls no pocket, the aimed legal ball, else
    // the nearest legal ball.
    private BallId? DefaultBall(AimPreview? aim)
    {
        if (_physics is null)
        {
            return null;
        }
        var legal = Constraints.LegalTargets(_match.Session.State, _physics.ObjectBallsOnTable());
        var cue = _physics.CueBallPosition with { Z = 0 };
        if (!_match.NeedsCall)
        {
            return aim?.Ball is { } any && legal.Contains(any) ? any : Nearest(cue, legal);
        }
        if (aim?.Ball is { } aimed && legal.Contains(aimed) && (IsOpen(aimed, aim.Pocket) || OpenPocket(aimed) is not null))
        {
            return aimed;
        }
        // An open pot first: the nearest legal ball that some pocket takes with no ball in the way.
        var open = legal.Where(b => OpenPocket(b) is not null).ToList();
        return Nearest(cue, open) ?? (aim?.Ball is { } a && legal.Contains(a) ? a : Nearest(cue, legal));
    }

    private BallId? Nearest(Vec3 from, IReadOnlyList<BallId> among)
    {
        var sim = _physics!.Simulation;
        BallId? best = null;
        double bestDistance = double.PositiveInfinity;
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            if (sim.Ids[i] == _physics.CueBall || sim.Balls[i].IsPocketed || !among.Contains(sim.Ids[i]))
            {
                continue;
            }
            double d = ((sim.Balls[i].Position with { Z = 0 }) - from).Length;
            if (d < bestDistance)
            {
                bestDistance = d;
                best = sim.Ids[i];
            }
        }
        return best;
    }
}
