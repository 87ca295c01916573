using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Every integrator of the standard model resolves every contact through the scene's interaction
/// models (<see cref="InteractionModels"/>): the landing and the pocket drop included, and a
/// ball-ball contact in the air through the chosen ball-ball model, with no way around them.
/// </summary>
public class InteractionModelUseTests
{
    private sealed class CountingTable(IBallTableModel inner) : IBallTableModel
    {
        public int Calls { get; private set; }

        public string Name => "counting";

        public double Resolve(ref BallState ball, Vec3 normal, PhysicsParams p)
        {
            Calls++;
            return inner.Resolve(ref ball, normal, p);
        }
    }

    private sealed class CountingPocket(IBallPocketModel inner) : IBallPocketModel
    {
        public int Calls { get; private set; }

        public string Name => "counting";

        public double Drop(ref BallState ball, int pocket)
        {
            Calls++;
            return inner.Drop(ref ball, pocket);
        }
    }

    private sealed class CountingBallBall(IBallBallModel inner) : IBallBallModel
    {
        public int InTheAir { get; private set; }

        public string Name => "counting";

        public void Resolve(ref BallState a, ref BallState b, PhysicsParams p)
        {
            if (a.State == MotionState.Airborne || b.State == MotionState.Airborne)
            {
                InTheAir++;
            }
            inner.Resolve(ref a, ref b, p);
        }
    }

    /// <summary>
    /// A ball dropped 1 cm beside one at rest (an air contact), a ball dropped onto the bed and one
    /// thrown into a hole: each integrator, with each ball-ball model, calls the scene's models for
    /// the air contact, the landings and the drop.
    /// </summary>
    [Theory]
    [InlineData(Integrators.Exact, "frictional-inelastic")]
    [InlineData(Integrators.Event, "frictional-inelastic")]
    [InlineData(Integrators.Euler, "frictional-inelastic")]
    [InlineData(Integrators.Exact, "frictional-mathavan")]
    [InlineData(Integrators.Event, "frictional-mathavan")]
    [InlineData(Integrators.Euler, "frictional-mathavan")]
    public void EveryIntegratorTakesEveryContactThroughTheScenesModels(string integrator, string ballBall)
    {
        var table = TableSpec.FromPreset("pool-9ft");
        var hole = TableGeometry.Build(table, R).Pockets[4];
        var start = hole.Centre - new Vec3(0.3, 0.3, 0);
        var balls = new List<BallSetup>
        {
            new(new BallId(0), new Vec3(0.01, 0, 0.3), Vec3.Zero, Vec3.Zero),
            Ball(1, 0, 0),
            new(new BallId(2), new Vec3(-0.6, 0.2, 0.2), new Vec3(0.5, 0, 0), Vec3.Zero),
            new(new BallId(3), start with { Z = R }, new Vec3(1, 1, 0) * 0.6, Vec3.Zero),
        };
        var landing = new CountingTable(InteractionModels.Default.BallTable);
        var pocket = new CountingPocket(InteractionModels.Default.BallPocket);
        var pair = new CountingBallBall(ModelRegistry.FindBallBall(ballBall)!);
        var scene = Scene(integrator, integrator == Integrators.Euler ? 1e-4 : Dt250, balls, table);
        scene = scene with { Physics = scene.Physics with { Models = new InteractionModels(InteractionModels.Default.BallCushion, pair) { BallTable = landing, BallPocket = pocket } } };
        var sim = SimulationFactory.Create(scene);
        sim.AdvanceTo(30);
        Assert.True(pair.InTheAir > 0, "no air contact went through the ball-ball model");
        Assert.True(landing.Calls >= 2, $"the landing model was called {landing.Calls} times");
        Assert.True(pocket.Calls >= 1, "the pocket model was not called");
        Assert.Equal(MotionState.Pocketed, sim.Balls[3].State);
        AssertAtRestOnTheTable(sim, $"{integrator}, {ballBall}");
    }
}
