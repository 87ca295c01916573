using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// Many simulations of one shared table model, one per thread, each restoring from one shared
/// snapshot: every thread's result equals the same shot run alone, bit for bit. The table model
/// and the snapshot are only read, so nothing is shared that a run changes.
/// </summary>
public class ParallelSimulationTests
{
    private const int Threads = 4;
    private const int ShotsPerThread = 3;

    public static TheoryData<string, string, string> Breaks => SimulationKit.Breaks;

    [Theory]
    [MemberData(nameof(Breaks))]
    public void SimulationsOfOneTableModelOnParallelThreadsEqualSerialRuns(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var first = SimulationFactory.Create(scene);
        var tableModel = first.TableModel;
        var start = first.CreateSnapshot();
        // Each shot a slightly different aim and speed, so that a mix-up between threads shows.
        var shots = Enumerable.Range(0, Threads * ShotsPerThread)
            .Select(k => scene.Shot! with { AimDeg = scene.Shot!.AimDeg + 0.5 * k, Speed = scene.Shot.Speed * (1 - 0.02 * k) })
            .ToArray();

        var serial = new ulong[shots.Length];
        for (int k = 0; k < shots.Length; k++)
        {
            var sim = tableModel.CreateSimulation(scene);
            sim.Strike(shots[k]);
            sim.AdvanceTo(600);
            serial[k] = SimulationKit.Hash(sim);
        }
        Assert.True(serial.Distinct().Count() == shots.Length, "the shots should end differently");

        var parallel = new ulong[shots.Length];
        var threads = Enumerable.Range(0, Threads).Select(t => new Thread(() =>
        {
            var sim = tableModel.CreateSimulation(scene);
            for (int s = 0; s < ShotsPerThread; s++)
            {
                int k = t * ShotsPerThread + s;
                sim.Restore(start);
                sim.Strike(shots[k]);
                sim.AdvanceTo(600);
                parallel[k] = SimulationKit.Hash(sim);
            }
        })).ToArray();
        foreach (var thread in threads)
        {
            thread.Start();
        }
        foreach (var thread in threads)
        {
            thread.Join();
        }
        Assert.Equal(serial, parallel);
    }
}
