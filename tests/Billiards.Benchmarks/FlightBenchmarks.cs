namespace Billiards.Benchmarks;

/// <summary>
/// Balls in the air: the jump shot of assets/scenes/flight/jump.json (55 deg, 3 m/s, the cue ball
/// over the 1 and on to rest), and the 8-ball break struck with the cue raised 6 deg, hard enough
/// for the slate to return the cue ball into the rack in the air (flight in a full rack).
/// </summary>
public class FlightBenchmarks
{
    private SceneShot _jump = null!;
    private SceneShot _break = null!;

    /// <summary>exact (fixed steps of 1/250 s) or event.</summary>
    [Params("exact", "event")]
    public string Integrator { get; set; } = "exact";

    [GlobalSetup]
    public void Setup()
    {
        _jump = SceneShot.Load("flight/jump.json", Integrator);
        _break = SceneShot.Load("eight-ball-break.json", Integrator, shot => shot with { ElevationDeg = 6 });
    }

    /// <summary>The jump shot to rest.</summary>
    [Benchmark]
    public double JumpShot() => _jump.RunToRest();

    /// <summary>The 8-ball break with the cue raised 6 deg (the cue ball hops into the rack) to rest.</summary>
    [Benchmark]
    public double EightBallBreakHopping() => _break.RunToRest();
}
