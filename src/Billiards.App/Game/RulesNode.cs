using Billiards.App.Nodes;
using Billiards.Core.Balls;
using Billiards.Core.Physics;

namespace Billiards.App.Game;

/// <summary>
/// Present only when the scene names <c>rules</c>. It gathers each shot's pocketed balls from the
/// event log and reports them when the balls rest. Judging the shot (fouls, turns, winner) belongs
/// to Core's rules, which are not written yet; this node is where they will be called.
/// </summary>
public sealed class RulesNode(string rules) : Node
{
    private readonly List<BallId> _pottedThisShot = [];
    private PhysicsNode? _physics;

    /// <summary>The rules the scene names, e.g. "eight-ball".</summary>
    public string Rules { get; } = rules;

    /// <summary>Balls pocketed by the last finished shot.</summary>
    public IReadOnlyList<BallId> LastShotPotted { get; private set; } = [];

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _physics.Struck += _ => _pottedThisShot.Clear();
        _physics.EventOccurred += e =>
        {
            if (e.Kind == EventKind.BallPocket)
            {
                _pottedThisShot.Add(e.A);
            }
        };
        _physics.CameToRest += _ =>
        {
            LastShotPotted = _pottedThisShot.ToArray();
        };
    }
}
