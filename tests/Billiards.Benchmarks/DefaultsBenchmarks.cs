namespace Billiards.Benchmarks;

/// <summary>
/// The 8-ball break to rest with the defaults against the real table (pool's cloth and balls, the
/// measured cushion restitution and throw law, the leather tip: the shipped scene, cue at 9.249 m/s)
/// and with the defaults before them (pooltool's parameters, an elastic tip: cue at 8 m/s, the same
/// ball speed), side by side in one run; the exact integrator at the default step, and the event solver.
/// </summary>
public class DefaultsBenchmarks
{
    private SceneShot _break = null!;

    /// <summary>"measured" (the defaults now) or "pooltool" (the defaults before).</summary>
    [Params("measured", "pooltool")]
    public string Defaults { get; set; } = "measured";

    /// <summary>exact (fixed steps of 1/250 s) or event.</summary>
    [Params("exact", "event")]
    public string Integrator { get; set; } = "exact";

    [GlobalSetup]
    public void Setup()
    {
        var scene = BenchmarkScenes.Load("eight-ball-break.json", ModelRegistry.Standard.Name, Integrator);
        if (Defaults == "pooltool")
        {
            scene = scene with { Physics = scene.Physics with { Params = PhysicsParams.Default }, Shot = scene.Shot! with { Speed = 8.0 } };
        }
        _break = SceneShot.Of(scene);
    }

    /// <summary>8-ball break to rest.</summary>
    [Benchmark]
    public double EightBallBreak() => _break.RunToRest();
}
