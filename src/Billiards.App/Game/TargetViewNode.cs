using Billiards.App.Nodes;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.App.Game;

/// <summary>
/// After each shot, and when a new game starts, turns the view (and with it the cue) from the cue
/// ball to the nearest ball the shooter may play (<see cref="Billiards.Core.Rules.Ruleset.LegalTargets"/>),
/// rather than leaving the last shot's aim, which often looks at an empty rail. It turns the moment
/// the shooter may play (<see cref="MatchNode.ShooterToPlay"/>: the ruling, the choice after a
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
        _match.ShooterToPlay += Turn;
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
        if (_match is not null && _physics is not null && NearestTarget(_match, _physics) is { } target)
        {
            LastTarget = target.Id;
            var to = target.Position - _physics.CueBallPosition;
            _match.AimAt(Math.Atan2(to.Y, to.X) * 180 / Math.PI);
        }
    }

    /// <summary>The shooter's legal target nearest the cue ball (its id and centre), or null when there is none on the table.</summary>
    public static (BallId Id, Vec3 Position)? NearestTarget(MatchNode match, PhysicsNode physics)
    {
        ArgumentNullException.ThrowIfNull(match);
        ArgumentNullException.ThrowIfNull(physics);
        var sim = physics.Simulation;
        var onTable = new List<BallId>();
        for (int i = 0; i < sim.Balls.Length; i++)
        {
            if (!sim.Balls[i].IsPocketed && sim.Ids[i] != physics.CueBall)
            {
                onTable.Add(sim.Ids[i]);
            }
        }
        var cue = physics.CueBallPosition;
        (BallId Id, Vec3 Position)? best = null;
        double nearest = double.PositiveInfinity;
        foreach (var id in match.Ruleset.LegalTargets(match.State, onTable))
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
}
