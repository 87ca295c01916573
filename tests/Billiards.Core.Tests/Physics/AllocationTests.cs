using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// Allocation counts are exact, so they gate: after warm-up, a step and a whole break allocate
/// nothing (GC.GetAllocatedBytesForCurrentThread).
/// </summary>
public class AllocationTests
{
    private static Simulation Break(string file, string integrator)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(Models.Standard, integrator));
        return SimulationFactory.Create(scene);
    }

    internal static long BytesOf(Action action)
    {
        action(); // warm-up: buffers reach their size, the JIT has compiled everything
        action();
        long before = GC.GetAllocatedBytesForCurrentThread();
        action();
        return GC.GetAllocatedBytesForCurrentThread() - before;
    }

    [Theory]
    [InlineData("eight-ball-break.json", "exact")]
    [InlineData("eight-ball-break.json", "event")]
    [InlineData("eight-ball-break.json", "euler")]
    [InlineData("nine-ball-break.json", "exact")]
    public void AWholeBreakAllocatesNothingAfterWarmUp(string file, string integrator)
    {
        var sim = Break(file, integrator);
        var scene = SceneLoader.Load(AssetFolder.Scene(file));
        long bytes = BytesOf(() =>
        {
            sim.Reset();
            sim.Strike(scene.Shot!);
            sim.AdvanceTo(600);
        });
        Assert.True(sim.IsAtRest);
        Assert.Equal(0, bytes);
    }

    [Theory]
    [InlineData(Models.Standard, Integrators.Exact)]
    [InlineData(Models.Standard, Integrators.Euler)]
    [InlineData(Models.Thesis, Integrators.Fixed)]
    public void AStepAllocatesNothingAfterWarmUp(string model, string integrator)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(model == Models.Thesis ? "thesis-eight-ball-break.json" : "eight-ball-break.json"), new SceneOverrides(model, integrator));
        var sim = SimulationFactory.Create(scene);
        sim.Strike(scene.Shot!);
        long bytes = BytesOf(() =>
        {
            for (int i = 0; i < 50; i++)
            {
                sim.Step();
            }
        });
        Assert.Equal(0, bytes);
    }
}
