using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Physics.Collisions.CollisionKit;

namespace Billiards.Core.Tests.Physics.Collisions;

/// <summary>Allocation counts are exact, so they gate: no model allocates per collision, and a break with each cushion model allocates nothing.</summary>
public class ModelAllocationTests
{
    public static IEnumerable<object[]> Cushions() => CushionModels();

    public static IEnumerable<object[]> BallBalls() => BallBallModels();

    [Theory]
    [MemberData(nameof(Cushions))]
    public void ACushionImpactAllocatesNothing(string name)
    {
        var model = Cushion(name);
        var start = Incoming(2, 30, 1, 0.5);
        var ball = start;
        long bytes = AllocationTests.BytesOf(() =>
        {
            for (int i = 0; i < 100; i++)
            {
                ball = start;
                model.Resolve(ref ball, Normal, Height, P);
            }
        });
        Assert.Equal(0, bytes);
        Assert.True(ball.Velocity.X < 0);
    }

    [Theory]
    [MemberData(nameof(BallBalls))]
    public void ABallBallCollisionAllocatesNothing(string name)
    {
        var model = CollisionKit.BallBall(name);
        var a0 = Incoming(2, 0, 1, 0.5);
        var b0 = new BallState { Position = new Vec3(2 * R * 0.8, 2 * R * 0.6, R) };
        var (a, b) = (a0, b0);
        long bytes = AllocationTests.BytesOf(() =>
        {
            for (int i = 0; i < 100; i++)
            {
                (a, b) = (a0, b0);
                model.Resolve(ref a, ref b, P);
            }
        });
        Assert.Equal(0, bytes);
        Assert.True(b.Velocity.X > 0);
    }

    [Theory]
    [InlineData("models/eight-ball-break-han-2005.json")]
    [InlineData("models/eight-ball-break-mathavan-2010.json")]
    [InlineData("models/eight-ball-break-stronge-compliant.json")]
    [InlineData("models/cut-frictional-mathavan.json")]
    public void AWholeShotWithEachModelAllocatesNothingAfterWarmUp(string file)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file));
        var sim = SimulationFactory.Create(scene);
        long bytes = AllocationTests.BytesOf(() =>
        {
            sim.Reset();
            sim.Strike(scene.Shot!);
            sim.AdvanceTo(600);
        });
        Assert.True(sim.IsAtRest);
        Assert.Equal(0, bytes);
    }
}
