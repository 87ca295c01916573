using Billiards.App.Nodes;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.App.Game;

/// <summary>
/// After each shot, and when a new game starts, turns the view (and with it the cue) from the cue
/// ball to the nearest ball the shooter may play (<see cref="Billiards.Core.Rules.Ruleset.LegalTargets"/>),
/// rather than leaving the last shot's aim, which often looks at an empty rail. It turns once the
/// balls rest and the shooter may shoot, on the frame after the ruling, so that the camera has
/// followed the cue ball first.
/// </summary>
public sealed class TargetViewNode : Node
{
    private MatchNode? _match;
    private PhysicsNode? _physics;
    private bool _pending;
    private bool _wasOver;

    /// <summary>The ball the view last turned to, or null.</summary>
    public BallId? LastTarget { get; private set; }

    /// <inheritdoc />
    protected override void Ready()
    {
        _match = GetInTree<MatchNode>();
        _physics = GetInTree<PhysicsNode>();
        _match.Ruled += _ => _pending = true;
        _pending = true; // the first game's break
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_match is null || _physics is null)
        {
            return;
        }
        // A rematch or a restart: the new rack.
        if (_wasOver && !_match.IsOver)
        {
            _pending = true;
        }
        _wasOver = _match.IsOver;
        if (!_pending || !_match.CanShoot)
        {
            return;
        }
        _pending = false;
        if (NearestTarget(_match, _physics) is { } target)
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
