using Billiards.Core.Balls;

namespace Billiards.Core.Physics.Collisions;

/// <summary>A ball-ball collision model: changes the velocities and spins of two touching balls.</summary>
public interface IBallBallModel
{
    /// <summary>The model's name in scene and result files (<c>physics.models.ball_ball</c>).</summary>
    string Name { get; }

    /// <summary>
    /// Resolves the collision of two touching balls (centres 2R apart, approaching), in space: with
    /// both on the bed the line of centres is horizontal and they stay there (no z velocity); with
    /// one or both in the air (<see cref="MotionState.Airborne"/>) it leaves the bed plane, a ball
    /// in the air has no contact with the table, and the impulse may lift a ball or drive it into
    /// the bed. Changes only velocity and spin. Allocates nothing.
    /// </summary>
    void Resolve(ref BallState a, ref BallState b, PhysicsParams p);
}

/// <summary>A ball-cushion collision model: changes a ball's velocity and spin at a cushion or jaw.</summary>
public interface IBallCushionModel
{
    /// <summary>The model's name in scene and result files (<c>physics.models.ball_cushion</c>).</summary>
    string Name { get; }

    /// <summary>
    /// Resolves the impact of a ball on a cushion whose contact normal, in the bed plane, is
    /// <paramref name="normal"/> (unit, pointing from the cushion towards the ball's centre), at
    /// contact height <paramref name="height"/> (m) above the bed. Changes only velocity and spin;
    /// the ball stays on the bed. Allocates nothing.
    /// </summary>
    void Resolve(ref BallState ball, Mathematics.Vec3 normal, double height, PhysicsParams p);
}
