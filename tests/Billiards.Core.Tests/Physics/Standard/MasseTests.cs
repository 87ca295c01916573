using Billiards.Core.Cue;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Extreme masse strokes: cue elevated 80-85 deg, large side offset, 5 m/s cue speed, from the
/// middle of the pocketless table. The ball leaves at v cos(theta) (a fraction of a m/s) with a
/// large tilted spin, so it slides on a curve for a long time. The run must end (rest by 120 s:
/// the ball cannot take more energy than the cue brought, 1/2 M V0^2 = 0.5 * 0.567 * 25 = 7.09 J;
/// rolling from the
/// largest plausible speed, 3 m/s, would take 3 / (mu_r g) = 31 s, spin-down of 1000 rad/s 92 s),
/// with finite state on the bed and energy never rising after the strike.
/// </summary>
public class MasseTests
{
    public static TheoryData<string, double, double, double, double> Strokes()
    {
        var data = new TheoryData<string, double, double, double, double>();
        foreach (var (integrator, dt) in new[] { ("exact", Dt30), ("exact", Dt250), ("exact", Dt8000), ("event", Dt250) })
        {
            data.Add(integrator, dt, 85, 0.5, 0);
            data.Add(integrator, dt, 80, -0.55, 0.2);
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Strokes))]
    public void ExtremeMasseTerminatesOnTheBedWithoutGainingEnergy(string integrator, double dt, double elevationDeg, double side, double height)
    {
        var sim = Create(integrator, dt, [Ball(0, 0, 0)]);
        sim.Strike(new ShotSpec(5, 30, side, height, elevationDeg));
        AssertFinite(sim, "masse strike");
        double e0 = KineticEnergy(sim.Balls);
        Assert.InRange(e0, 1e-3, 0.5 * 0.567 * 5 * 5);
        Assert.True(sim.Balls[0].Spin.Length > 50, $"no masse spin: {Fmt(sim.Balls[0].Spin)}");

        StepChecked(sim, 120, $"masse {elevationDeg} deg side {side} {integrator} dt {dt:R}");
        Assert.True(sim.IsAtRest, "the masse ball still moves at 120 s");
        Assert.Equal(0, KineticEnergy(sim.Balls));
    }
}
