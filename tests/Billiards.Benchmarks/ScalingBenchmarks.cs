
namespace Billiards.Benchmarks;

/// <summary>
/// One exact step with every ball moving, on a table that grows with the ball count so that the
/// density stays that of 16 balls on a 9 ft table: a broad phase keeps the cost near linear.
/// </summary>
public class ScalingBenchmarks
{
    private const int StepsPerInvoke = 4;
    private Simulation _sim = null!;

    /// <summary>Number of moving balls.</summary>
    [Params(64, 256, 1024)]
    public int Balls { get; set; }

    [GlobalSetup]
    public void Setup() => _sim = SimulationFactory.Create(BenchmarkScenes.Grid(Balls, Balls, ModelRegistry.Standard.Name, Integrators.Exact));

    /// <summary>One step of 1/250 s.</summary>
    [Benchmark(OperationsPerInvoke = StepsPerInvoke)]
    public void Step()
    {
        _sim.Reset();
        for (int i = 0; i < StepsPerInvoke; i++)
        {
            _sim.Step();
        }
    }
}
