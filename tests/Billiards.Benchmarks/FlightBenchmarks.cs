using BenchmarkDotNet.Attributes;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Benchmarks;

/// <summary>
/// Balls in the air: the jump shot of assets/scenes/flight/jump.json (55 deg, 3 m/s, the cue ball
/// over the 1 and on to rest), and the 8-ball break struck with the cue raised 6 deg, hard enough
/// for the slate to return the cue ball into the rack in the air (flight in a full rack).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class FlightBenchmarks
{
    private Simulation _jump = null!;
    private Simulation _break = null!;
    private ShotSpec _jumpShot = null!;
    private ShotSpec _breakShot = null!;

    /// <summary>exact (fixed steps of 1/250 s) or event.</summary>
    [Params("exact", "event")]
    public string Integrator { get; set; } = "exact";

    [GlobalSetup]
    public void Setup()
    {
        var jump = BenchmarkScenes.Load("flight/jump.json", ModelRegistry.Standard.Name, Integrator);
        var eight = BenchmarkScenes.Load("eight-ball-break.json", ModelRegistry.Standard.Name, Integrator);
        (_jump, _jumpShot) = (SimulationFactory.Create(jump), jump.Shot!);
        (_break, _breakShot) = (SimulationFactory.Create(eight), eight.Shot! with { ElevationDeg = 6 });
    }

    /// <summary>The jump shot to rest.</summary>
    [Benchmark]
    public double JumpShot() => Run(_jump, _jumpShot);

    /// <summary>The 8-ball break with the cue raised 6 deg (the cue ball hops into the rack) to rest.</summary>
    [Benchmark]
    public double EightBallBreakHopping() => Run(_break, _breakShot);

    private static double Run(Simulation sim, ShotSpec shot)
    {
        sim.Reset();
        sim.Strike(shot);
        sim.AdvanceTo(600);
        return sim.Time;
    }
}
