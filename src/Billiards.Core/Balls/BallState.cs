using System.Numerics;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Balls;

/// <summary>
/// The public, SI state of one ball: what results, rules, the renderer and tests read.
/// Models may keep their own internal units (the thesis model keeps centimetres) but expose this.
/// </summary>
public struct BallState
{
    /// <summary>Centre of the ball (m); x along the table towards the foot rail, y across, z up; z = R on the bed.</summary>
    public Vec3 Position;

    /// <summary>Linear velocity of the centre (m/s).</summary>
    public Vec3 Velocity;

    /// <summary>Angular velocity (rad/s).</summary>
    public Vec3 Spin;

    /// <summary>Orientation, for drawing; only kept up to date when a simulation is asked to.</summary>
    public Quaternion Orientation;

    /// <summary>Motion state.</summary>
    public MotionState State;

    /// <summary>Index of the pocket the ball fell into, or -1.</summary>
    public int Pocket;

    /// <summary>True once the ball is in a pocket.</summary>
    public readonly bool IsPocketed => State == MotionState.Pocketed;

    /// <summary>True once the ball is out of play: in a pocket, or off the table over a rail.</summary>
    public readonly bool IsOutOfPlay => State is MotionState.Pocketed or MotionState.OffTable;
}
