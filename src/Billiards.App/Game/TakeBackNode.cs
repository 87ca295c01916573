using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;

namespace Billiards.App.Game;

/// <summary>
/// The take-back (<see cref="UndoKey"/>): back to the position and the game state before the last
/// shot, on the session's timeline. Always in practice (<see cref="PracticeNode.Retry"/>) and on a
/// scene without a game (<see cref="FreeTableNode.TakeBack"/>); in a match only when the players allow
/// take-backs (<see cref="Core.Rules.Session.TakeBacks"/>), through Core's match snapshot. Not while balls
/// roll or the instant replay is shown.
/// </summary>
public sealed class TakeBackNode : Node
{
    /// <summary>The key that takes the last shot back.</summary>
    public const Key UndoKey = Key.Z;

    private PhysicsNode? _physics;
    private MatchNode? _match;
    private PracticeNode? _practice;
    private FreeTableNode? _free;
    private InstantReplayNode? _replay;

    /// <summary>What the last press said when it could not take a shot back, or null.</summary>
    public string? Refusal { get; private set; }

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _match = FindInTree<MatchNode>();
        _practice = FindInTree<PracticeNode>();
        _free = FindInTree<FreeTableNode>();
        _replay = FindInTree<InstantReplayNode>();
        _physics.Struck += _ => Refusal = null;
    }

    /// <summary>Takes the last shot back; false (with <see cref="Refusal"/> saying why) when it cannot.</summary>
    public bool TakeBack()
    {
        if (_physics is null || _replay is { IsActive: true })
        {
            return false;
        }
        // Practice strikes through its session (no referee): its retry is the take-back, shot after shot.
        bool done = _match is not null ? _match.TakeBack() : _practice is not null ? _practice.Retry() : _free?.TakeBack() == true;
        Refusal = done ? null
            : _physics.IsRolling ? "No take-back while balls roll."
            : _match is { Session.TakeBacks: false } ? "Take-backs are off in this game (start menu, or play --take-backs)."
            : "No shot to take back.";
        return done;
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is KeyInput { Pressed: true, Key: UndoKey, IsRepeat: false })
        {
            TakeBack();
            return true;
        }
        return false;
    }
}
