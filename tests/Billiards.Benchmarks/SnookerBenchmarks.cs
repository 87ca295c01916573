namespace Billiards.Benchmarks;

/// <summary>
/// Snooker's break-off (assets/scenes/snooker-break.json: 22 balls on the 12 ft table, the cue
/// ball from the D into the side of the pack at 7 m/s) from the strike to rest with the event
/// integrator, beside the 8-ball break (16 balls, 8 m/s) as the baseline: the ratio column is
/// the snooker break's time over the 8-ball break's (the target: at most 2, with 0 B allocated).
/// </summary>
public class SnookerBenchmarks
{
    private SceneShot _eight = null!;
    private SceneShot _snooker = null!;

    [GlobalSetup]
    public void Setup()
    {
        _eight = SceneShot.Load("eight-ball-break.json", Integrators.Event);
        _snooker = SceneShot.Load("snooker-break.json", Integrators.Event);
    }

    /// <summary>8-ball break to rest, event integrator: the baseline.</summary>
    [Benchmark(Baseline = true)]
    public double EightBallBreak() => _eight.RunToRest();

    /// <summary>Snooker break-off to rest, event integrator.</summary>
    [Benchmark]
    public double SnookerBreakOff() => _snooker.RunToRest();
}
