using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Physics;

/// <summary>
/// What every simulation of one table under one model and physics configuration shares and never
/// changes: the table's collision geometry, the parameters, the collision models. Simulations made
/// from one model keep only their own per-run state (balls, clock, predictions, events), so many of
/// them can run side by side, one per thread, and a <see cref="SimulationSnapshot"/> taken from one
/// restores into any other made from the same model.
/// </summary>
public abstract class TableModel
{
    /// <summary>Creates the common part of a model.</summary>
    /// <param name="table">The table.</param>
    /// <param name="physics">The model, integrator, step and parameters.</param>
    protected TableModel(TableSpec table, PhysicsConfig physics)
    {
        Table = table;
        Physics = physics;
    }

    /// <summary>The table.</summary>
    public TableSpec Table { get; }

    /// <summary>The model, integrator, step and parameters every simulation of this model uses.</summary>
    public PhysicsConfig Physics { get; }

    /// <summary>
    /// A new simulation of the scene's balls on this model's table, at t = 0 before its shot. The
    /// scene's table and physics must be this model's.
    /// </summary>
    /// <exception cref="ArgumentException">The scene's table or physics differ from the model's.</exception>
    public Simulation CreateSimulation(Scene scene)
    {
        if (scene.Table != Table || scene.Physics != Physics)
        {
            throw new ArgumentException("the scene's table or physics are not this table model's", nameof(scene));
        }
        return Create(scene);
    }

    /// <summary>The model's simulation of a scene already checked against the model.</summary>
    protected abstract Simulation Create(Scene scene);
}
