namespace Billiards.Benchmarks;

/// <summary>
/// A whole break simulated from the strike to rest: the seeded 8-ball and 9-ball break scenes of
/// assets/scenes (cue at 8 m/s) with the standard model's exact integrator at the default step,
/// and with the event-based solver.
/// </summary>
public class BreakBenchmarks
{
    private SceneShot _eight = null!;
    private SceneShot _nine = null!;

    /// <summary>exact (fixed steps of 1/250 s) or event.</summary>
    [Params("exact", "event")]
    public string Integrator { get; set; } = "exact";

    [GlobalSetup]
    public void Setup()
    {
        _eight = SceneShot.Load("eight-ball-break.json", Integrator);
        _nine = SceneShot.Load("nine-ball-break.json", Integrator);
    }

    /// <summary>8-ball break to rest.</summary>
    [Benchmark]
    public double EightBallBreak() => _eight.RunToRest();

    /// <summary>9-ball break to rest.</summary>
    [Benchmark]
    public double NineBallBreak() => _nine.RunToRest();
}
