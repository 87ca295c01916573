using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions.BallBall;
using Billiards.Core.Physics.Collisions.BallCushion;
using static Billiards.Core.Tests.Physics.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>Invariants of the collision models: energy, momentum, restitution, symmetry, throw.</summary>
public class CollisionTests
{
    private static readonly PhysicsParams P = PhysicsParams.Default;

    private static (BallState A, BallState B) Pair(Vec3 va, Vec3 wa, Vec3 vb, Vec3 wb, double angleDeg = 0)
    {
        double phi = angleDeg * Math.PI / 180;
        var a = new BallState { Position = V(0, 0, R), Velocity = va, Spin = wa };
        var b = new BallState { Position = V(2 * R * Math.Cos(phi), 2 * R * Math.Sin(phi), R), Velocity = vb, Spin = wb };
        return (a, b);
    }

    [Fact]
    public void HeadOnStunSplitsSpeedByRestitution()
    {
        var (a, b) = Pair(V(2, 0), Vec3.Zero, Vec3.Zero, Vec3.Zero);
        FrictionalInelastic.Instance.Resolve(ref a, ref b, P);
        Assert.Equal((1 - 0.95) * 2 / 2, a.Velocity.X, 12); // 0.05
        Assert.Equal((1 + 0.95) * 2 / 2, b.Velocity.X, 12); // 1.95
        Assert.Equal(0.05, a.Velocity.X, 12);
        Assert.Equal(1.95, b.Velocity.X, 12);
        Assert.Equal(0, a.Velocity.Y, 12);
        Assert.Equal(0, b.Spin.Length, 12);
    }

    public static TheoryData<double, double, double, double> BallBallCases()
    {
        var data = new TheoryData<double, double, double, double>();
        foreach (double angle in new[] { 0.0, 10, 30, 45, 60, 80 })
        {
            foreach (double spin in new[] { -60.0, 0, 35, 120 })
            {
                data.Add(angle, 1.5, spin, 20);
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(BallBallCases))]
    public void BallBallConservesMomentumRestitutionAndNeverGainsEnergy(double cutDeg, double speed, double topspin, double side)
    {
        foreach (var p in new[] { P, P with { MuBModel = BallBallFriction.Alciatore } })
        {
            var (a, b) = Pair(V(speed, 0), V(0, topspin, side), V(0.2, -0.1), V(5, 0, -3), cutDeg);
            var n = (b.Position - a.Position).Normalized();
            double approach = Vec3.Dot(a.Velocity - b.Velocity, n);
            var momentum = a.Velocity + b.Velocity;
            double energy = Energy(a) + Energy(b);
            FrictionalInelastic.Instance.Resolve(ref a, ref b, p);
            double separation = Vec3.Dot(b.Velocity - a.Velocity, n);
            Assert.Equal(p.EB * approach, separation, 12);
            var after = a.Velocity + b.Velocity;
            Assert.Equal(momentum.X, after.X, 12);
            Assert.Equal(momentum.Y, after.Y, 12);
            Assert.True(Energy(a) + Energy(b) <= energy * (1 + 1e-12), "energy increased");
        }
    }

    [Fact]
    public void NoThrowWithoutSlip()
    {
        // Outside spin that exactly cancels the cut's slip: the contact points move together.
        double phi = 30 * Math.PI / 180;
        double v = 1;
        // Slip of a's contact relative to b's along t = z x n: the tangential velocity v_t plus
        // R w_z (from R (w_z z) x n = R w_z t). Choose w_z = -v_t / R to cancel it.
        var n = V(Math.Cos(phi), Math.Sin(phi));
        var t = V(-n.Y, n.X);
        double vt = Vec3.Dot(V(v, 0), t);
        var (a, b) = Pair(V(v, 0), V(0, 0, -vt / R), Vec3.Zero, Vec3.Zero, 30);
        FrictionalInelastic.Instance.Resolve(ref a, ref b, P);
        Assert.Equal(0, Vec3.Dot(b.Velocity, t), 12);
    }

    [Fact]
    public void CutInducedThrowMatchesAlciatoreTpA14()
    {
        // TP A-14, stun shot at cut angle phi: the object ball leaves at throw angle
        // atan(min(mu(v_rel), tan(phi)/7)) off the line of centres, with v_rel = v sin(phi) the
        // contact points' slip speed and mu Alciatore's fit a + b exp(-c v_rel).
        double phi = 30 * Math.PI / 180;
        double v = 1.5;
        double vRel = v * Math.Sin(phi);
        double mu = 9.951e-3 + 0.108 * Math.Exp(-1.088 * vRel);
        double expected = Math.Atan(Math.Min(mu, Math.Tan(phi) / 7));

        var p = P with { MuBModel = BallBallFriction.Alciatore };
        var (a, b) = Pair(V(v, 0), Vec3.Zero, Vec3.Zero, Vec3.Zero, 30);
        FrictionalInelastic.Instance.Resolve(ref a, ref b, p);
        double throwAngle = phi - Math.Atan2(b.Velocity.Y, b.Velocity.X);
        Assert.True(throwAngle > 0, "throw is away from the cut side");
        AssertRelative(expected, throwAngle, 0.10, "throw angle");
    }

    [Theory]
    [InlineData(15.0, 40.0, -25.0)]
    [InlineData(50.0, -80.0, 10.0)]
    public void BallBallIsMirrorSymmetric(double cutDeg, double wy, double wz)
    {
        // Mirror y -> -y: velocities (x, -y), spins (pseudovectors) (-x, y, -z).
        var (a, b) = Pair(V(1.2, 0.1), V(3, wy, wz), V(-0.1, 0.05), V(-1, 2, 4), cutDeg);
        var (ma, mb) = Pair(V(1.2, -0.1), V(-3, wy, -wz), V(-0.1, -0.05), V(1, 2, -4), -cutDeg);
        FrictionalInelastic.Instance.Resolve(ref a, ref b, P);
        FrictionalInelastic.Instance.Resolve(ref ma, ref mb, P);
        AssertMirror(a, ma);
        AssertMirror(b, mb);
    }

    private static void AssertMirror(in BallState s, in BallState m)
    {
        Assert.Equal(s.Velocity.X, m.Velocity.X, 12);
        Assert.Equal(s.Velocity.Y, -m.Velocity.Y, 12);
        Assert.Equal(s.Spin.X, -m.Spin.X, 12);
        Assert.Equal(s.Spin.Y, m.Spin.Y, 12);
        Assert.Equal(s.Spin.Z, -m.Spin.Z, 12);
    }

    public static TheoryData<double, double> CushionCases()
    {
        var data = new TheoryData<double, double>();
        foreach (double incidence in new[] { 1.0, 5, 15, 30, 45, 60, 75, 85, 89 })
        {
            foreach (double speed in new[] { 0.1, 0.5, 2, 6, 12 })
            {
                data.Add(incidence, speed);
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(CushionCases))]
    public void CushionNeverGainsEnergyAndReflects(double incidenceDeg, double speed)
    {
        // Incidence measured from the rail: 1 deg is a graze, 89 nearly head-on.
        double a = incidenceDeg * Math.PI / 180;
        var normal = V(-1, 0); // the foot cushion (+x), its normal points back to the table
        foreach (var (spinKind, spin) in new[] { ("none", Vec3.Zero), ("rolling", V(-speed * Math.Sin(a) / R, speed * Math.Cos(a) / R)), ("side", V(0, 0, 40)), ("side-left", V(3, -20, -40)) })
        {
            // The velocity's x (into the cushion) is speed sin(a), a measured from the rail line.
            var b = new BallState { Velocity = V(speed * Math.Sin(a), speed * Math.Cos(a)), Spin = spin };
            double before = Energy(b);
            Han2005.Instance.Resolve(ref b, normal, TableSpecHeight, P);
            Assert.True(Energy(b) <= before * (1 + 1e-12), $"energy increased ({spinKind})");
            Assert.True(b.Velocity.X < 0, $"the ball must leave the cushion ({spinKind})");
            Assert.Equal(0, b.Velocity.Z);
        }
    }

    private const double TableSpecHeight = 0.64 * 2 * R;

    [Theory]
    [InlineData(30.0, 2.0, 0.0, 0.0, 0.0)]
    [InlineData(60.0, 1.0, 20.0, 30.0, 15.0)]
    [InlineData(10.0, 5.0, -10.0, 60.0, -35.0)]
    public void CushionIsMirrorSymmetric(double incidenceDeg, double speed, double wx, double wy, double wz)
    {
        double a = incidenceDeg * Math.PI / 180;
        var normal = V(-1, 0);
        var s = new BallState { Velocity = V(speed * Math.Sin(a), speed * Math.Cos(a)), Spin = V(wx, wy, wz) };
        var m = new BallState { Velocity = V(speed * Math.Sin(a), -speed * Math.Cos(a)), Spin = V(-wx, wy, -wz) };
        Han2005.Instance.Resolve(ref s, normal, TableSpecHeight, P);
        Han2005.Instance.Resolve(ref m, normal, TableSpecHeight, P);
        AssertMirror(s, m);
    }

    [Fact]
    public void CushionHeadOnKeepsTheLineAndRestitutionBounds()
    {
        // Head-on without spin: no sideways motion, and the rebound speed lies between e_c cos^2
        // and the full normal speed (Han's normal impulse acts along the tilted contact normal).
        var b = new BallState { Velocity = V(2, 0) };
        Han2005.Instance.Resolve(ref b, V(-1, 0), TableSpecHeight, P);
        Assert.Equal(0, b.Velocity.Y, 12);
        Assert.InRange(-b.Velocity.X, 0.5, 2.0);
        // Sin of the contact angle from h: theta_a = asin(h / R - 1) = 16.26 deg.
        Assert.Equal(16.26, Math.Asin(TableSpecHeight / R - 1) * 180 / Math.PI, 2);
    }

    [Fact]
    public void RightEnglishThrowsTheReboundToTheRight()
    {
        // Ball moving +x into the foot cushion with w_z > 0 (right english: the tip hit the right
        // side, turning the ball anticlockwise seen from above). The contact point then slides
        // towards +y, so friction pushes the ball to -y: the shooter's right (he looks along +x).
        var b = new BallState { Velocity = V(2, 0), Spin = V(0, 0, 30) };
        Han2005.Instance.Resolve(ref b, V(-1, 0), TableSpecHeight, P);
        Assert.True(b.Velocity.Y < 0, $"vy = {b.Velocity.Y}");
    }
}
