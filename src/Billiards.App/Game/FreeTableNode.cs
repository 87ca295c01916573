using Billiards.App.Nodes;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Rules;

namespace Billiards.App.Game;

/// <summary>
/// A scene played without a game and without practice's tools (a break, a test position): its
/// shots, its own opening shot first, go through a session of <see cref="PracticeRuleset"/>
/// (Core's turn controller without a referee), so its take-back is the same timeline as a game's
/// and practice's: shot after shot, back to the scene.
/// </summary>
public sealed class FreeTableNode : Node
{
    private PhysicsNode? _physics;

    /// <summary>The session every shot goes through, or null before the node is ready.</summary>
    public Session? Session { get; private set; }

    /// <inheritdoc />
    protected override void Ready()
    {
        var physics = _physics = GetInTree<PhysicsNode>();
        var session = Session = Session.Practice(physics.Scene with { Shot = null }, physics.CreateSimulation);
        physics.StrikeThrough = OnStrike;
        physics.CameToRest += _ =>
        {
            if (session.RestWithCueBallInHand(physics.Simulation))
            {
                physics.ReturnCueBall();
            }
        };
        if (physics.IsRolling && physics.LastShot is { } opening && session.Submit(new GameShot(opening), SeatKind.Person) is { } sim)
        {
            // The scene's own shot is already on its way: the session plays it from the scene's position.
            physics.ReplaceShot(sim);
        }
    }

    /// <summary>Takes the last shot back: the table as it was before it, bit for bit; false when there is none or balls roll.</summary>
    public bool TakeBack()
    {
        if (_physics is not { IsRolling: false } physics || Session is not { } session || !session.TakeBack())
        {
            return false;
        }
        physics.TakeBackTo(session.Game.Layout(), session.BallInHand != BallInHand.None);
        return true;
    }

    private Simulation? OnStrike(ShotSpec shot) =>
        Session!.StrikeFrom(_physics!.Scene with { Balls = _physics.BallsAtRest(), Shot = null }, shot);
}
