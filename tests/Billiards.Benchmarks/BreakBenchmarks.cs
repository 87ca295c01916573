using BenchmarkDotNet.Attributes;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Benchmarks;

/// <summary>
/// A whole break simulated from the strike to rest: the seeded 8-ball and 9-ball break scenes of
/// assets/scenes (cue at 8 m/s) with the standard model's exact integrator at the default step,
/// and with the event-based solver.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class BreakBenchmarks
{
    private Simulation _eight = null!;
    private Simulation _nine = null!;
    private ShotSpec _eightShot = null!;
    private ShotSpec _nineShot = null!;

    /// <summary>exact (fixed steps of 1/250 s) or event.</summary>
    [Params("exact", "event")]
    public string Integrator { get; set; } = "exact";

    [GlobalSetup]
    public void Setup()
    {
        var eight = BenchmarkScenes.Load("eight-ball-break.json", ModelRegistry.Standard.Name, Integrator);
        var nine = BenchmarkScenes.Load("nine-ball-break.json", ModelRegistry.Standard.Name, Integrator);
        (_eight, _eightShot) = (SimulationFactory.Create(eight), eight.Shot!);
        (_nine, _nineShot) = (SimulationFactory.Create(nine), nine.Shot!);
    }

    /// <summary>8-ball break to rest.</summary>
    [Benchmark]
    public double EightBallBreak() => BenchmarkScenes.RunToRest(_eight, _eightShot);

    /// <summary>9-ball break to rest.</summary>
    [Benchmark]
    public double NineBallBreak() => BenchmarkScenes.RunToRest(_nine, _nineShot);
}
