using BenchmarkDotNet.Attributes;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Benchmarks;

/// <summary>
/// Snooker's break-off (assets/scenes/snooker-break.json: 22 balls on the 12 ft table, the cue
/// ball from the D into the side of the pack at 7 m/s) from the strike to rest with the event
/// integrator, beside the 8-ball break (16 balls, 8 m/s) as the baseline: the ratio column is
/// the snooker break's time over the 8-ball break's (the target: at most 2, with 0 B allocated).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class SnookerBenchmarks
{
    private Simulation _eight = null!;
    private Simulation _snooker = null!;
    private ShotSpec _eightShot = null!;
    private ShotSpec _snookerShot = null!;

    [GlobalSetup]
    public void Setup()
    {
        var eight = BenchmarkScenes.Load("eight-ball-break.json", ModelRegistry.Standard.Name, Integrators.Event);
        var snooker = BenchmarkScenes.Load("snooker-break.json", ModelRegistry.Standard.Name, Integrators.Event);
        (_eight, _eightShot) = (SimulationFactory.Create(eight), eight.Shot!);
        (_snooker, _snookerShot) = (SimulationFactory.Create(snooker), snooker.Shot!);
    }

    /// <summary>8-ball break to rest, event integrator: the baseline.</summary>
    [Benchmark(Baseline = true)]
    public double EightBallBreak() => BenchmarkScenes.RunToRest(_eight, _eightShot);

    /// <summary>Snooker break-off to rest, event integrator.</summary>
    [Benchmark]
    public double SnookerBreakOff() => BenchmarkScenes.RunToRest(_snooker, _snookerShot);
}
