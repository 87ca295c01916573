using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallPocket;

/// <summary>
/// A ball over the hole is gone: it stops at once where its centre entered (velocity and spin
/// zero), pocketed, whether it rolled in off the bed or came down into the hole from the air.
/// </summary>
/// <remarks>
/// Source: pooltool's canonical ball-pocket model (<c>physics/resolve/ball_pocket</c>), which
/// takes the ball out of play at the capture; pooltool also moves it to the hole's centre, this
/// model leaves it where it entered, the position results report.
/// </remarks>
public sealed class CanonicalPocket : IBallPocketModel
{
    /// <summary>The shared instance (the model has no state).</summary>
    public static CanonicalPocket Instance { get; } = new();

    /// <inheritdoc />
    public string Name => "canonical";

    /// <inheritdoc />
    public double Drop(ref BallState ball, int pocket)
    {
        double speed = ball.Velocity.Length;
        ball.Velocity = Vec3.Zero;
        ball.Spin = Vec3.Zero;
        ball.State = MotionState.Pocketed;
        ball.Pocket = pocket;
        return speed;
    }
}
