using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Benchmarks;

/// <summary>
/// A whole shot of a scene, the unit of the whole-shot benchmarks: the scene's simulation and its
/// shot, rerun from the scene's start to rest by each <see cref="RunToRest"/>.
/// </summary>
/// <param name="Simulation">The scene's simulation.</param>
/// <param name="Shot">The shot struck.</param>
public sealed record SceneShot(Simulation Simulation, ShotSpec Shot)
{
    /// <summary>The scene's simulation with its shot, or with what <paramref name="change"/> makes of the shot.</summary>
    public static SceneShot Of(Scene scene, Func<ShotSpec, ShotSpec>? change = null)
    {
        ArgumentNullException.ThrowIfNull(scene);
        var shot = scene.Shot ?? throw new ArgumentException($"the scene \"{scene.Name}\" has no shot", nameof(scene));
        return new SceneShot(SimulationFactory.Create(scene), change is null ? shot : change(shot));
    }

    /// <summary>A shipped scene (assets/scenes/<paramref name="file"/>) with the standard model and <paramref name="integrator"/>.</summary>
    public static SceneShot Load(string file, string integrator, Func<ShotSpec, ShotSpec>? change = null) =>
        Of(BenchmarkScenes.Load(file, ModelRegistry.Standard.Name, integrator), change);

    /// <summary>Back to the scene's start, strike, run to rest; returns the time at rest (s).</summary>
    public double RunToRest()
    {
        Simulation.Reset();
        Simulation.Strike(Shot);
        Simulation.AdvanceTo(600);
        return Simulation.Time;
    }
}

/// <summary>Seeded scenes for the benchmarks; the whole-shot ones come from assets/scenes.</summary>
public static class BenchmarkScenes
{
    /// <summary>A shipped scene with the given model and integrator.</summary>
    public static Scene Load(string file, string model, string integrator) =>
        SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(model, integrator));

    /// <summary>
    /// <paramref name="total"/> balls on a grid over a table of the 9 ft table's density (16 balls on
    /// 2.54 x 1.27 m), the first <paramref name="moving"/> of them rolling at 1.5 m/s in seeded directions.
    /// </summary>
    public static Scene Grid(int total, int moving, string model, string integrator, int seed = 1)
    {
        double area = 2.54 * 1.27 / 16 * total;
        double length = Math.Sqrt(2 * area), width = length / 2;
        var table = TableSpec.FromPreset(total <= 16 ? "pool-9ft" : "pocketless") with { Length = length, Width = width };
        double radius = ModelRegistry.Get(model).BallRadius(PhysicsParams.Default);
        int columns = (int)Math.Ceiling(Math.Sqrt(total * 2.0));
        int rows = (int)Math.Ceiling(total / (double)columns);
        double dx = length / (columns + 1), dy = width / (rows + 1);
        var random = new Random(seed);
        var balls = new List<BallSetup>(total);
        for (int i = 0; i < total; i++)
        {
            var position = new Vec3(-length / 2 + dx * (i % columns + 1), -width / 2 + dy * (i / columns + 1), radius);
            var velocity = Vec3.Zero;
            var spin = Vec3.Zero;
            if (i < moving)
            {
                double angle = random.NextDouble() * 2 * Math.PI;
                velocity = new Vec3(1.5 * Math.Cos(angle), 1.5 * Math.Sin(angle), 0);
                spin = Vec3.Cross(Vec3.UnitZ, velocity) / radius; // rolling: w = z x v / R
            }
            balls.Add(new BallSetup(new BallId(i), position, velocity, spin));
        }
        var physicsModel = ModelRegistry.Get(model);
        var physics = PhysicsConfig.Default with { Model = physicsModel, Integrator = ModelRegistry.FindIntegrator(physicsModel, integrator)! };
        return new Scene("benchmark", $"{total} balls, {moving} moving", table, physics, null, balls, null, null);
    }
}
