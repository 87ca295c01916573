using Billiards.Core.Physics.Standard;
using Billiards.Core.Physics.Thesis;

namespace Billiards.Benchmarks;

/// <summary>
/// Snapshots: capture plus restore of a 16-ball table mid-break (balls moving, predictions and
/// pair cache full), and the computer opponent's unit of search: restore the position, strike,
/// run to rest (the 8-ball break with the event integrator).
/// </summary>
public class SnapshotBenchmarks
{
    private Simulation _sim = null!;
    private ShotSpec _shot = null!;
    private SimulationSnapshot _moving = null!;
    private SimulationSnapshot _start = null!;

    /// <summary>exact or event (the standard model), or fixed (the thesis model).</summary>
    [Params("event", "exact", "fixed")]
    public string Integrator { get; set; } = "event";

    [GlobalSetup]
    public void Setup()
    {
        (_sim, _shot) = SceneShot.Of(Integrator == Integrators.Fixed
            ? BenchmarkScenes.Load("thesis-eight-ball-break.json", ThesisModel.ModelName, Integrator)
            : BenchmarkScenes.Load("eight-ball-break.json", StandardModel.ModelName, Integrator));
        _start = _sim.CreateSnapshot();
        _sim.Strike(_shot);
        _sim.AdvanceTo(0.4);
        _moving = _sim.CreateSnapshot();
    }

    /// <summary>Capture the 16-ball table mid-break into a snapshot, then restore it.</summary>
    [Benchmark]
    public double SnapshotAndRestore()
    {
        _sim.Capture(_moving);
        _sim.Restore(_moving);
        return _sim.Time;
    }

    /// <summary>Restore the position before the break, strike, run to rest.</summary>
    [Benchmark]
    public double RestoreStrikeRunToRest()
    {
        _sim.Restore(_start);
        _sim.Strike(_shot);
        _sim.AdvanceTo(600);
        return _sim.Time;
    }
}
