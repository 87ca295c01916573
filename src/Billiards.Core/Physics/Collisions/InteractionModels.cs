using Billiards.Core.Physics.Collisions.BallBall;
using Billiards.Core.Physics.Collisions.BallCushion;
using Billiards.Core.Physics.Collisions.BallPocket;
using Billiards.Core.Physics.Collisions.BallTable;

namespace Billiards.Core.Physics.Collisions;

/// <summary>
/// Which resolver each interaction of the standard model uses: the cushion and ball-ball ones
/// are a scene's <c>physics.models</c>; the ball-table landing and the pocket drop have one model
/// each so far. The resolvers keep no state; <see cref="ModelRegistry"/> finds them by name.
/// </summary>
/// <param name="BallCushion">The ball-cushion (and jaw) model.</param>
/// <param name="BallBall">The ball-ball model, on the bed and in the air.</param>
public sealed record InteractionModels(IBallCushionModel BallCushion, IBallBallModel BallBall)
{
    /// <summary>The ball-table model: a landing on the bed or a rail's top, the slate's return of an elevated cue.</summary>
    public IBallTableModel BallTable { get; init; } = FrictionalLanding.Instance;

    /// <summary>The ball-pocket model: a ball dropping into a pocket's hole, off the bed or from the air.</summary>
    public IBallPocketModel BallPocket { get; init; } = CanonicalPocket.Instance;

    /// <summary>The defaults: <see cref="Han2005"/>, <see cref="FrictionalInelastic"/>, <see cref="FrictionalLanding"/> and <see cref="CanonicalPocket"/>.</summary>
    public static InteractionModels Default { get; } = new(Han2005.Instance, FrictionalInelastic.Instance);
}
