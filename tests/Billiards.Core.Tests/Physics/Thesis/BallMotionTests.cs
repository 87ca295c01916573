using System.Numerics;
using Billiards.Core.Physics.Thesis;
using static Billiards.Core.Tests.Physics.Thesis.ThesisKit;

namespace Billiards.Core.Tests.Physics.Thesis;

/// <summary>Step 1 (p += v dt), Formel 5 (damping) and Formel 6-10 with Listing 1 (orientation).</summary>
public class BallMotionTests
{
    [Fact]
    public void OneStepMovesByTheOldVelocityThenDampsItBy09965()
    {
        var ball = At(1, 0, 0, vx: 100);
        var engine = Engine("thesis", ball);
        engine.CalculatePhysics();
        // Step 1 before step 6: x = 100 cm/s * 1/250 s = 0.4 cm; then v = 100 * 0.9965 = 99.65 cm/s.
        AssertVector(new Vector3(0.4f, Y, 0), ball.Position, 1e-5f);
        AssertVector(new Vector3(99.65f, 0, 0), ball.Velocity, 1e-4f);
    }

    [Theory]
    [InlineData(250)]   // the seed's step
    [InlineData(50)]
    [InlineData(1000)]
    public void DampingPerSecondIsTheSeedsWhateverTheStep(int stepsPerSecond)
    {
        var ball = At(1, 0, 0, vx: 100);
        var engine = Engine("thesis", 1.0 / stepsPerSecond, ball);
        for (int i = 0; i < stepsPerSecond; i++)
        {
            engine.CalculatePhysics();
        }
        // After one second: 100 * 0.9965^250 = 41.61 cm/s, whatever dt (damping 0.9965^(250 dt) per step).
        double expected = 100 * Math.Pow(0.9965, 250);
        Assert.Equal(expected, ball.Velocity.X, 0.01);
        Assert.Equal(1.0, engine.Time, 1e-9);
    }

    [Fact]
    public void AQuarterRollAlongXTurnsTheTopForward()
    {
        // d = (pi r / 2, 0, 0): angle = |d| / r = pi/2 (Formel 6), axis = y x x = -z (Formel 7),
        // q = (cos pi/4, sin pi/4 * (0, 0, -1)) (Formel 9); from identity the product is q.
        float r = PhysicsEngine.BallRadius;
        var q = PhysicsEngine.Roll(Quaternion.Identity, new Vector3(MathF.PI * r / 2, 0, 0));
        float h = MathF.Sqrt(0.5f);
        Assert.Equal(h, q.W, 1e-5f);
        Assert.Equal(0, q.X, 1e-5f);
        Assert.Equal(0, q.Y, 1e-5f);
        Assert.Equal(-h, q.Z, 1e-5f);
        // Rolling forward, the top point (0, 1, 0) goes to the front (1, 0, 0).
        AssertVector(Vector3.UnitX, Vector3.Transform(Vector3.UnitY, q), 1e-5f);
    }

    [Fact]
    public void TwoRollsComposeNewestFirstAsInFormel10()
    {
        float r = PhysicsEngine.BallRadius;
        var first = PhysicsEngine.Roll(Quaternion.Identity, new Vector3(MathF.PI * r / 2, 0, 0));
        var both = PhysicsEngine.Roll(first, new Vector3(0, 0, MathF.PI * r / 2));
        // First a quarter turn about -z: (1,0,0) -> (0,-1,0), the contact point. Then a quarter turn
        // about y x z = +x: (0,-1,0) -> (0,0,-1), behind the ball rolling along +z. Applying them
        // in the other order would give (0,-1,0).
        AssertVector(new Vector3(0, 0, -1), Vector3.Transform(Vector3.UnitX, both), 1e-5f);
        // q2 * q1 with q1 = (h, 0, 0, -h), q2 = (h, h, 0, 0) [w, x, y, z], h = sqrt 1/2 (Formel 10):
        // w = h*h - (h,0,0).(0,0,-h) = 1/2; v = h (0,0,-h) + h (h,0,0) + (h,0,0) x (0,0,-h) = (1/2, 1/2, -1/2).
        Assert.Equal(0.5f, both.W, 1e-5f);
        AssertVector(new Vector3(0.5f, 0.5f, -0.5f), new Vector3(both.X, both.Y, both.Z), 1e-5f);
    }

    [Fact]
    public void AMoveUnderAMillionthOfACentimetreLeavesTheOrientation()
    {
        var q = Quaternion.Normalize(new Quaternion(1, 2, 3, 4));
        Assert.Equal(q, PhysicsEngine.Roll(q, new Vector3(1e-7f, 0, 0)));
    }

    [Fact]
    public void OrientationIsOnlyIntegratedWhenTrackedAndNeverChangesTheMotion()
    {
        var tracked = At(1, 0, 0, vx: 100, vz: 30);
        var untracked = At(1, 0, 0, vx: 100, vz: 30);
        var a = Engine("thesis", tracked);
        var b = Engine("thesis", untracked);
        a.TrackOrientation = true;
        for (int i = 0; i < 100; i++)
        {
            a.CalculatePhysics();
            b.CalculatePhysics();
        }
        Assert.Equal(Quaternion.Identity, untracked.Orientation);
        Assert.NotEqual(Quaternion.Identity, tracked.Orientation);
        Assert.Equal(untracked.Position, tracked.Position);
        Assert.Equal(untracked.Velocity, tracked.Velocity);
    }

    [Fact]
    public void ARandomOrientationIsAUnitQuaternionAndRepeatsWithItsSeed()
    {
        var a = new Ball(1, Vector3.Zero);
        var b = new Ball(1, Vector3.Zero);
        a.RandomizeOrientation(new Random(5));
        b.RandomizeOrientation(new Random(5));
        Assert.Equal(1, a.Orientation.Length(), 1e-6f);
        Assert.Equal(a.Orientation, b.Orientation);
    }
}
