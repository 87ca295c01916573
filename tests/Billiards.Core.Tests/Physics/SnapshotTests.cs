using Billiards.Core.Physics.Standard;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// Snapshot and restore: a simulation restored from a snapshot runs on bit for bit as the one it
/// was taken from, whether taken at rest or mid-shot with balls moving, and in any order.
/// </summary>
public class SnapshotTests
{
    // Where the run stops to take snapshots (s): before the strike, right after it, in the thick
    // of the break, while the last balls roll, at rest. The rerun repeats the same calls.
    private static readonly double[] Stops = [0.004, 0.1, 0.6, 2.5, 600];

    public static TheoryData<string, string, string> Breaks => SimulationKit.Breaks;

    private static Simulation Create(Scene scene)
    {
        var sim = SimulationFactory.Create(scene);
        sim.TrackOrientation = true; // so that orientations are compared too
        return sim;
    }

    [Theory]
    [MemberData(nameof(Breaks))]
    public void ARestoredSimulationRerunsEverySnapshotBitForBit(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var reference = Create(scene);
        var snapshots = new List<SimulationSnapshot> { reference.CreateSnapshot() };
        reference.Strike(scene.Shot!);
        foreach (double t in Stops)
        {
            reference.AdvanceTo(t);
            snapshots.Add(reference.CreateSnapshot());
        }
        Assert.True(reference.IsAtRest);
        Assert.True(reference.Events.Count > 20, "the break should be busy");

        // Restore into the same simulation, latest first, so that each restore undoes a later state.
        var sim = reference;
        var expected = Create(scene);
        expected.Strike(scene.Shot!);
        foreach (double t in Stops)
        {
            expected.AdvanceTo(t);
        }
        SimulationKit.AssertSameRun(expected, reference, "the reference run");
        for (int k = snapshots.Count - 1; k >= 0; k--)
        {
            sim.Restore(snapshots[k]);
            if (k == 0)
            {
                sim.Strike(scene.Shot!);
            }
            foreach (double t in Stops.Skip(k == 0 ? 0 : k))
            {
                sim.AdvanceTo(t);
            }
            SimulationKit.AssertSameRun(expected, sim, $"restored from snapshot {k}");
        }
    }

    [Theory]
    [MemberData(nameof(Breaks))]
    public void ASnapshotAfterAnyOfTheFirstStepsReruns(string file, string model, string integrator)
    {
        // The rack's balls touch, so the break's first steps (events, for the event integrator)
        // are full of repeat contacts within the TC model's contact duration: a snapshot taken
        // between them must carry the contact memory and every pending prediction.
        const int Steps = 60;
        var scene = SimulationKit.Load(file, model, integrator);
        var sim = Create(scene);
        sim.Strike(scene.Shot!);
        var snapshots = new SimulationSnapshot[Steps];
        for (int k = 0; k < Steps; k++)
        {
            snapshots[k] = sim.CreateSnapshot();
            sim.Step();
        }
        sim.AdvanceTo(600);
        var expected = Create(scene);
        expected.Strike(scene.Shot!);
        for (int k = 0; k < Steps; k++)
        {
            expected.Step();
        }
        expected.AdvanceTo(600);
        SimulationKit.AssertSameRun(expected, sim, "the reference run");

        for (int k = Steps - 1; k >= 0; k -= 3)
        {
            sim.Restore(snapshots[k]);
            for (int j = k; j < Steps; j++)
            {
                sim.Step();
            }
            sim.AdvanceTo(600);
            SimulationKit.AssertSameRun(expected, sim, $"restored before step {k}");
        }
    }

    [Theory]
    [MemberData(nameof(Breaks))]
    public void ARestoredStateEqualsTheCapturedOneAndTheSnapshotKeepsIt(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var sim = Create(scene);
        sim.Strike(scene.Shot!);
        sim.AdvanceTo(0.3);
        var snapshot = sim.CreateSnapshot();
        ulong atCapture = SimulationKit.Hash(sim, orientation: true);
        double time = sim.Time;
        int events = sim.Events.Count;

        // Run on and even start over: none of it may leak into the snapshot.
        sim.AdvanceTo(600);
        sim.Reset();
        sim.Strike(scene.Shot! with { AimDeg = scene.Shot!.AimDeg + 3 });
        sim.AdvanceTo(1);

        sim.Restore(snapshot);
        Assert.Equal(time, sim.Time);
        Assert.Equal(time, snapshot.Time);
        Assert.Equal(events, sim.Events.Count);
        Assert.Equal(atCapture, SimulationKit.Hash(sim, orientation: true));
        Assert.False(sim.IsAtRest);
    }

    [Theory]
    [MemberData(nameof(Breaks))]
    public void AnotherSimulationOfTheSameTableModelRestoresTheSnapshot(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var first = Create(scene);
        first.Strike(scene.Shot!);
        first.AdvanceTo(0.2);
        var snapshot = first.CreateSnapshot();
        first.AdvanceTo(600);

        var second = first.TableModel.CreateSimulation(scene);
        second.TrackOrientation = true;
        Assert.Same(first.TableModel, second.TableModel);
        second.Restore(snapshot);
        second.AdvanceTo(600);
        SimulationKit.AssertSameRun(first, second, "the second simulation");
    }

    [Fact]
    public void ASnapshotOfAnotherTableModelIsRefused()
    {
        var scene = SimulationKit.Load("eight-ball-break.json", StandardModel.ModelName, Integrators.Exact);
        var a = SimulationFactory.Create(scene);
        var b = SimulationFactory.Create(scene);
        var snapshot = a.CreateSnapshot();
        Assert.False(snapshot.Fits(b));
        Assert.Throws<ArgumentException>(() => b.Restore(snapshot));
        Assert.Throws<ArgumentException>(() => b.Capture(snapshot));
        var thesis = SimulationFactory.Create(SimulationKit.Load("thesis-eight-ball-break.json", ThesisModel.ModelName, Integrators.Fixed));
        Assert.Throws<ArgumentException>(() => thesis.Restore(snapshot));
    }

    [Fact]
    public void ATableModelRefusesASceneOfAnotherTable()
    {
        var eight = SimulationKit.Load("eight-ball-break.json", StandardModel.ModelName, Integrators.Exact);
        var euler = SimulationKit.Load("eight-ball-break.json", StandardModel.ModelName, Integrators.Euler);
        var model = SimulationFactory.Create(eight).TableModel;
        Assert.Throws<ArgumentException>(() => model.CreateSimulation(euler));
    }

    [Fact]
    public void TheThesisEffetIsPartOfTheSnapshot()
    {
        // Draw (e_y below centre) acts at the cue ball's first ball contact and decays there: a
        // snapshot before that contact must carry it, or the rerun's cue ball would not draw back.
        var scene = SimulationKit.Load("thesis-eight-ball-break.json", ThesisModel.ModelName, Integrators.Fixed);
        var shot = scene.Shot! with { TipHeight = -0.6, TipSide = 0.3 };
        var sim = Create(scene);
        sim.Strike(shot);
        sim.AdvanceTo(0.02);
        var snapshot = sim.CreateSnapshot();
        sim.AdvanceTo(600);
        var expected = SimulationKit.Hash(sim, orientation: true);

        var fresh = Create(scene);
        fresh.Strike(scene.Shot!); // no effet
        fresh.AdvanceTo(600);
        Assert.NotEqual(expected, SimulationKit.Hash(fresh, orientation: true));

        sim.Reset();
        sim.Restore(snapshot);
        sim.AdvanceTo(600);
        Assert.Equal(expected, SimulationKit.Hash(sim, orientation: true));
    }
}
