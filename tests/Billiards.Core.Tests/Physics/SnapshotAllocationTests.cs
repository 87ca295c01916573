using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// Capture and restore allocate nothing (exact counts, GC.GetAllocatedBytesForCurrentThread), mid-shot
/// with balls moving and at rest, and neither does the computer opponent's unit of search: restore,
/// strike, run to rest.
/// </summary>
public class SnapshotAllocationTests
{
    public static TheoryData<string, string, string> Breaks => SimulationKit.Breaks;

    [Theory]
    [MemberData(nameof(Breaks))]
    public void CaptureAndRestoreAllocateNothing(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var sim = SimulationFactory.Create(scene);
        var atRest = sim.CreateSnapshot();
        sim.Strike(scene.Shot!);
        sim.AdvanceTo(0.4);
        var moving = sim.CreateSnapshot();
        long bytes = AllocationTests.BytesOf(() =>
        {
            sim.Restore(atRest);
            sim.Capture(atRest);
            sim.Restore(moving);
            sim.Capture(moving);
        });
        Assert.False(sim.IsAtRest);
        Assert.Equal(0, bytes);
    }

    [Theory]
    [MemberData(nameof(Breaks))]
    public void RestoreStrikeAndRunToRestAllocatesNothing(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var sim = SimulationFactory.Create(scene);
        var start = sim.CreateSnapshot();
        long bytes = AllocationTests.BytesOf(() =>
        {
            sim.Restore(start);
            sim.Strike(scene.Shot!);
            sim.AdvanceTo(600);
        });
        Assert.True(sim.IsAtRest);
        Assert.Equal(0, bytes);
    }
}
