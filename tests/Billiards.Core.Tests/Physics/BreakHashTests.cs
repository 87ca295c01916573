using Billiards.Core.Physics.Standard;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// The expected-hash test of Box2D: the final state of the 8-ball break (every ball's position,
/// velocity, spin, state and pocket, bit for bit, and the event count) hashed and pinned, for
/// both models and every integrator. It is a guard, not a reference: the pinned values are what
/// the engine computed when they were set, and any change of physics, of the order of floating
/// point operations or of the compiler's code for them shows here first. A change that alters
/// them on purpose updates them and says why in its commit message; the other tests tell whether
/// the physics is still right.
/// </summary>
public class BreakHashTests
{
    [Theory]
    [InlineData("thesis-eight-ball-break.json", ThesisModel.ModelName, Integrators.Fixed, 0xD0E3B603DB3D0310UL)]
    [InlineData("eight-ball-break.json", StandardModel.ModelName, Integrators.Exact, 0x24564B002D920BACUL)]
    [InlineData("eight-ball-break.json", StandardModel.ModelName, Integrators.Event, 0x459F1247C5E1ACBEUL)]
    [InlineData("eight-ball-break.json", StandardModel.ModelName, Integrators.Euler, 0x7CE4BD134A04453CUL)]
    public void TheBreakEndsInThePinnedState(string file, string model, string integrator, ulong expected)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var sim = SimulationFactory.Create(scene);
        sim.Strike(scene.Shot!);
        sim.AdvanceTo(600);
        Assert.True(sim.IsAtRest);
        Assert.Equal($"0x{expected:X16}", $"0x{SimulationKit.Hash(sim):X16}");
    }
}
