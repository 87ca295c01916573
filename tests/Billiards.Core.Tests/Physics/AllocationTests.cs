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
        var scene = SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(ModelRegistry.Standard.Name, integrator));
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
    [InlineData("snooker-break.json", "event")]
    [InlineData("snooker-break.json", "exact")]
    [InlineData("flight/jump.json", "exact")]
    [InlineData("flight/jump.json", "event")]
    [InlineData("flight/jump.json", "euler")]
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
    [InlineData("exact")]
    [InlineData("event")]
    public void ABreakWithTheCueBallHoppingIntoTheRackAllocatesNothing(string integrator)
    {
        var sim = Break("eight-ball-break.json", integrator);
        var shot = SceneLoader.Load(AssetFolder.Scene("eight-ball-break.json")).Shot! with { ElevationDeg = 6 };
        long bytes = BytesOf(() =>
        {
            sim.Reset();
            sim.Strike(shot);
            sim.AdvanceTo(600);
        });
        Assert.True(sim.IsAtRest);
        Assert.Contains(sim.Events.AsSpan().ToArray(), e => e.Kind == EventKind.BallAirborne);
        Assert.Equal(0, bytes);
    }

    [Theory]
    [InlineData("eight-ball-break.json", Integrators.Exact)]
    [InlineData("eight-ball-break.json", Integrators.Euler)]
    [InlineData("thesis-eight-ball-break.json", Integrators.Fixed)]
    public void AStepAllocatesNothingAfterWarmUp(string file, string integrator)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(null, integrator));
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
