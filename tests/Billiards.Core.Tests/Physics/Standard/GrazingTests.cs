using Billiards.Core.Physics;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Grazing hits at a cut angle of 90 deg +- 0.001 deg. The cue ball starts at (-0.3, 0) moving
/// along +x at 1 m/s with no spin, so its slip is along x and its path stays on y = 0 (it slides,
/// then rolls, straight). The object ball stands at (0, b). The centres come within |b|; with the
/// cut angle phi = asin(b / 2R), a hit at 89.999 deg needs b = 2R sin(89.999 deg) = 2R cos(0.001 deg)
/// = 2R (1 - 1.523e-10) (8.7e-12 m inside contact) and the matching miss b = 2R / cos(0.001 deg)
/// = 2R (1 + 1.523e-10) (8.7e-12 m outside). The gap polynomial |d(t)|^2 - 4R^2 has its minimum
/// at b^2 - 4R^2 = -+1.0e-12 m^2, against values of order 0.09 m^2 at the start whose round-off
/// is 1e-17: an exact solver tells them apart with five orders to spare. The cue ball reaches
/// x = 0 after about 0.5 s (sliding 0.146 s over 0.125 m, then rolling at 0.714 m/s).
/// </summary>
public class GrazingTests
{
    private static readonly double Angle = 0.001 * Math.PI / 180;

    private static Simulation Pass(string integrator, double dt, double offset) =>
        Create(integrator, dt, [Ball(0, -0.3, 0, vx: 1), Ball(1, 0, offset)]);

    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void ABarelyTouchingPassHitsTheObjectBall(string integrator, double dt)
    {
        double b = 2 * R * Math.Cos(Angle);
        Assert.True(b < 2 * R);
        var sim = Pass(integrator, dt, b);
        double maxObjectSpeed = 0;
        StepChecked(sim, 2, "grazing hit", afterStep: s => maxObjectSpeed = Math.Max(maxObjectSpeed, s.Balls[1].Velocity.Length));

        var hits = EventsOf(sim, EventKind.BallBall);
        Assert.Single(hits);
        // The normal at contact is nearly along y: its x part is sqrt(1 - (b/2R)^2) = sin(0.001 deg)
        // = 1.745e-5, so the approach speed is about 1.745e-5 times the cue ball's ~0.7 m/s.
        Assert.InRange(hits[0].Speed, 0.5 * Math.Sin(Angle) * 0.6, Math.Sin(Angle) * 1.0);
        var start = new Billiards.Core.Mathematics.Vec3(0, b, R);
        Assert.True((sim.Balls[1].Position - start).Length > 0, "the object ball did not move");
        // A graze hands on only what the normal carries: (1 + e)/2 = 0.975 of the approach speed
        // along n, plus a tangential friction impulse of at most mu_b e = 0.0475 of it, so
        // |v| <= sqrt(0.975^2 + 0.0475^2) = 0.976 of the approach speed right after the hit;
        // the cloth only slows it from there. So the object ball can never exceed the approach
        // speed (about 1.2e-5 m/s), whichever step we look at.
        Assert.True(maxObjectSpeed <= hits[0].Speed,
            $"the grazed ball moved at up to {maxObjectSpeed:E3} m/s after an approach of {hits[0].Speed:E3} m/s");
        AssertNoOverlap(sim, "grazing hit");
    }

    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void ABarelyMissingPassLeavesTheObjectBallAlone(string integrator, double dt)
    {
        double b = 2 * R / Math.Cos(Angle);
        Assert.True(b > 2 * R);
        var sim = Pass(integrator, dt, b);
        StepChecked(sim, 2, "grazing miss");

        Assert.Empty(EventsOf(sim, EventKind.BallBall));
        AssertVec(new Billiards.Core.Mathematics.Vec3(0, b, R), sim.Balls[1].Position, 0, "sim.Balls[1].Position");
        AssertVec(Billiards.Core.Mathematics.Vec3.Zero, sim.Balls[1].Velocity, 0, "sim.Balls[1].Velocity");
        Assert.Equal(0, sim.Balls[0].Position.Y); // the cue ball went by undeflected
        Assert.True(sim.Balls[0].Position.X > 0.1, $"the cue ball stopped short: {Fmt(sim.Balls[0].Position)}");
    }
}
