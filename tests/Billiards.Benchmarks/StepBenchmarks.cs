
namespace Billiards.Benchmarks;

/// <summary>
/// One fixed step of 1/250 s on a 9 ft table with 16 balls, of which MovingBalls roll, for each
/// model and integrator. Each invocation resets the table and takes 16 steps, so the reset (a
/// copy of 16 states) is shared by 16 steps and the balls never run down.
/// </summary>
public class StepBenchmarks
{
    private const int StepsPerInvoke = 16;
    private Simulation _moving = null!;
    private Simulation _idle = null!;

    /// <summary>How many of the 16 balls move.</summary>
    [Params(1, 4, 8, 16)]
    public int MovingBalls { get; set; }

    /// <summary>thesis, or the standard model's exact or euler integrator.</summary>
    [Params("thesis", "exact", "euler")]
    public string Model { get; set; } = "exact";

    [GlobalSetup]
    public void Setup()
    {
        // A name is the thesis model or one of the default model's integrators.
        var thesis = ModelRegistry.Find(Model);
        string model = thesis?.Name ?? ModelRegistry.Default.Name;
        string integrator = thesis?.Integrators[0].Name ?? Model;
        _moving = SimulationFactory.Create(BenchmarkScenes.Grid(16, MovingBalls, model, integrator));
        _idle = SimulationFactory.Create(BenchmarkScenes.Grid(16, 0, model, integrator));
    }

    /// <summary>One step with MovingBalls moving balls.</summary>
    [Benchmark(OperationsPerInvoke = StepsPerInvoke)]
    public void Step()
    {
        _moving.Reset();
        for (int i = 0; i < StepsPerInvoke; i++)
        {
            _moving.Step();
        }
    }

    /// <summary>One step with all 16 balls at rest: what a table that waits for the player costs.</summary>
    [Benchmark(OperationsPerInvoke = StepsPerInvoke)]
    public void IdleStep()
    {
        for (int i = 0; i < StepsPerInvoke; i++)
        {
            _idle.Step();
        }
    }
}
