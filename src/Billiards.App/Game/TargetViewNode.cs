using Billiards.App.Nodes;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.App.Game;

/// <summary>
/// After each shot, and when a new game starts, turns the view (and with it the cue) from the cue
/// ball to the nearest ball the shooter may play (<see cref="Billiards.Core.Rules.Ruleset.LegalTargets"/>),
/// rather than leaving the last shot's aim, which often looks at an empty rail. It turns the moment
/// the shooter may play (<see cref="Core.Rules.Session.ShooterToPlay"/>: the ruling, the choice after a
/// foul, the new rack), not in a later frame: a key pressed in the same frame as the choice then
/// turns from the new view, as it does a frame later, so a script plays the same at any frame rate.
/// The first rack's view turns in the first frame, once every node is ready.
/// </summary>
public sealed class TargetViewNode : Node
{
    private MatchNode? _match;
    private PhysicsNode? _physics;
    private bool _pending;

    /// <summary>The ball the view last turned to, or null.</summary>
    public BallId? LastTarget { get; private set; }

    /// <inheritdoc />
    protected override void Ready()
    {
        _match = GetInTree<MatchNode>();
        _physics = GetInTree<PhysicsNode>();
        _match.Session.ShooterToPlay += Turn;
        _pending = true; // the first game's break
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_pending && _match is { CanShoot: true })
        {
            Turn();
        }
    }

    private void Turn()
    {
        _pending = false;
        if (_match is { Session.Ruleset.HasSnookers: true } && _physics is not null && ReachableAim(_match, _physics) is { } reachable)
        {
            LastTarget = reachable.Id;
            _match.AimAt(reachable.AimDegrees);
            return;
        }
        if (_match is not null && _physics is not null && NearestTarget(_match, _physics) is { } target)
        {
            LastTarget = target.Id;
            var to = target.Position - _physics.CueBallPosition;
            _match.AimAt(DeterministicMath.Atan2(to.Y, to.X) * 180 / Math.PI);
        }
    }

    /// <summary>The shooter's legal target nearest the cue ball (its id and centre), or null when there is none on the table.</summary>
    public static (BallId Id, Vec3 Position)? NearestTarget(MatchNode match, PhysicsNode physics)
    {
        ArgumentNullException.ThrowIfNull(match);
        ArgumentNullException.ThrowIfNull(physics);
        var sim = physics.Simulation;
        var onTable = physics.ObjectBallsOnTable();
        var cue = physics.CueBallPosition;
        (BallId Id, Vec3 Position)? best = null;
        double nearest = double.PositiveInfinity;
        foreach (var id in match.Session.Ruleset.LegalTargets(match.Session.State, onTable))
        {
            var p = sim.Balls[sim.IndexOf(id)].Position;
            double d = (p - cue).LengthXY;
            if (d < nearest)
            {
                (nearest, best) = (d, (id, p));
            }
        }
        return best;
    }

    /// <summary>Lateral offsets tried at a ball on, in radii from its centre: full ball first, then thinner to either side.</summary>
    private static readonly double[] Offsets = [0, 0.5, -0.5, 1.0, -1.0, 1.5, -1.5, 1.9, -1.9];

    /// <summary>
    /// The view in the games with snookers (<see cref="Billiards.Core.Rules.Ruleset.HasSnookers"/>): the aim (deg) at the nearest ball on whose centre, or a thinner contact on
    /// it, the cue ball meets before any other ball: the colours on their spots hide reds (the pink
    /// in front of the pack at the break-off, where the aim is then thin on an end red), and a
    /// stranger's first Space should be no foul. Null when no ball on can be struck first in a
    /// straight line (snookered): the view then turns to the nearest, as in pool.
    /// </summary>
    public static (BallId Id, double AimDegrees)? ReachableAim(MatchNode match, PhysicsNode physics)
    {
        ArgumentNullException.ThrowIfNull(match);
        ArgumentNullException.ThrowIfNull(physics);
        var sim = physics.Simulation;
        var onTable = physics.ObjectBallsOnTable();
        var legal = match.Session.Ruleset.LegalTargets(match.Session.State, onTable);
        var cue = physics.CueBallPosition with { Z = 0 };
        int cueIndex = sim.IndexOf(physics.CueBall);
        foreach (var id in legal.OrderBy(b => ((sim.Balls[sim.IndexOf(b)].Position with { Z = 0 }) - cue).LengthXY))
        {
            var centre = sim.Balls[sim.IndexOf(id)].Position with { Z = 0 };
            var to = centre - cue;
            var side = new Vec3(-to.Y, to.X, 0).Normalized();
            foreach (double k in Offsets)
            {
                var aim = centre + (k * physics.BallRadius * side) - cue;
                if (AimPreview.Compute(sim.Balls, sim.Ids, cueIndex, aim, physics.BallRadius, [], physics.Table.Pockets).Ball is { } first && legal.Contains(first))
                {
                    return (first, DeterministicMath.Atan2(aim.Y, aim.X) * 180 / Math.PI);
                }
            }
        }
        return null;
    }
}
