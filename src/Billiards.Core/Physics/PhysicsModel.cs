using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Physics;

/// <summary>A face of the geometry a model's balls collide with, for the debug view (m; the unit normal points onto the bed).</summary>
/// <param name="A">First corner (m).</param>
/// <param name="B">Second corner (m).</param>
/// <param name="C">Third corner (m).</param>
/// <param name="Normal">Unit normal, pointing to where the balls are.</param>
public readonly record struct CollisionFace(Vec3 A, Vec3 B, Vec3 C, Vec3 Normal);

/// <summary>
/// A physics model as a plug-in: what the scene loader, the factory, the game and the tools need
/// to know of a model. <see cref="ModelRegistry"/> holds them by name, so that nothing else looks
/// at a model's name.
/// </summary>
public abstract class PhysicsModel
{
    /// <summary>The model's name in scene and result files.</summary>
    public abstract string Name { get; }

    /// <summary>The integrators the model accepts; the first is its default.</summary>
    public abstract IReadOnlyList<IIntegrator> Integrators { get; }

    /// <summary>True when the model takes a resolver per interaction (<see cref="PhysicsConfig.Models"/>).</summary>
    public virtual bool TakesInteractionModels => false;

    /// <summary>True when the model's balls can leave the bed (a scene may then give [x, y, z] positions and [vx, vy, vz] velocities).</summary>
    public virtual bool HasFlight => false;

    /// <summary>The table preset of a scene that names none.</summary>
    public abstract string DefaultTablePreset { get; }

    /// <summary>Radius of the model's balls (m) under the scene's parameters (a model may keep its own).</summary>
    public abstract double BallRadius(PhysicsParams parameters);

    /// <summary>
    /// Why the model cannot keep balls of <paramref name="radius"/> (m) on <paramref name="table"/>,
    /// or null when it can. A model whose radius is fixed accepts it.
    /// </summary>
    public virtual string? RadiusProblem(TableSpec table, double radius) => null;

    /// <summary>A new simulation of the scene at t = 0, before its shot.</summary>
    public abstract Simulation Create(Scene scene);

    /// <summary>The geometry the model's balls collide with on <paramref name="table"/>, as faces for the debug view (m).</summary>
    public abstract IReadOnlyList<CollisionFace> CollisionFaces(TableSpec table, PhysicsParams parameters);

    /// <summary>The model's name.</summary>
    public override string ToString() => Name;
}
