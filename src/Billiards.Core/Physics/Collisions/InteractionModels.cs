using Billiards.Core.Physics.Collisions.BallBall;
using Billiards.Core.Physics.Collisions.BallCushion;

namespace Billiards.Core.Physics.Collisions;

/// <summary>
/// Which resolver each interaction of the standard model uses (a scene's <c>physics.models</c>).
/// The resolvers keep no state; <see cref="ModelRegistry"/> finds them by name.
/// </summary>
/// <param name="BallCushion">The ball-cushion (and jaw) model.</param>
/// <param name="BallBall">The ball-ball model.</param>
public sealed record InteractionModels(IBallCushionModel BallCushion, IBallBallModel BallBall)
{
    /// <summary>The defaults: <see cref="Han2005"/> and <see cref="FrictionalInelastic"/>.</summary>
    public static InteractionModels Default { get; } = new(Han2005.Instance, FrictionalInelastic.Instance);
}
