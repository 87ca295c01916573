using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions;

/// <summary>
/// A ball-table model: changes a ball's velocity and spin when it lands on a fixed surface of the
/// table (the bed, or the top of a cushion or rail), or is driven into the bed by an elevated cue.
/// </summary>
public interface IBallTableModel
{
    /// <summary>The model's name in the registry (<see cref="ModelRegistry.BallTableNames"/>).</summary>
    string Name { get; }

    /// <summary>
    /// Resolves the impact of a ball on a fixed surface whose unit contact normal is
    /// <paramref name="normal"/> (in space, from the surface towards the ball's centre: +z for the
    /// bed and a rail's top). Changes only velocity and spin; the caller puts the ball on the
    /// surface and decides, from the rebound, whether it flies on. Returns the normal approach
    /// speed at impact (m/s, not negative). Allocates nothing.
    /// </summary>
    double Resolve(ref BallState ball, Vec3 normal, PhysicsParams p);
}

/// <summary>A ball-pocket model: what becomes of a ball whose centre drops into a pocket's hole.</summary>
public interface IBallPocketModel
{
    /// <summary>The model's name in the registry (<see cref="ModelRegistry.BallPocketNames"/>).</summary>
    string Name { get; }

    /// <summary>
    /// Takes the ball, arriving with its velocity in space (from the bed or from the air), into
    /// pocket <paramref name="pocket"/> (an index of the table's <see cref="Table.TableSpec.Pockets"/>):
    /// sets its state to <see cref="MotionState.Pocketed"/> and its pocket. Returns the ball's speed
    /// as it drops (m/s). Allocates nothing.
    /// </summary>
    double Drop(ref BallState ball, int pocket);
}
