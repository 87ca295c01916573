using Billiards.Core.Physics;

namespace Billiards.Core.Scenes;

/// <summary>Creates the simulation a scene's physics block asks for, with its balls placed.</summary>
public static class SimulationFactory
{
    /// <summary>A new simulation of the scene at t = 0, before its shot.</summary>
    public static Simulation Create(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        return scene.Physics.Model.Create(scene);
    }
}
