using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Physics.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>Balls in the air (physics-standard-model.md, "Flight"): parabolas, landings, bounces, against the analytic figures.</summary>
public class FlightTests
{
    private const double ET = 0.5;

    private static string Ball3(string id, double x, double y, double z, double vx = 0, double vy = 0, double vz = 0, double wx = 0, double wy = 0, double wz = 0) =>
        $$"""{ "id": "{{id}}", "position": [{{F(x)}}, {{F(y)}}, {{F(z)}}], "velocity": [{{F(vx)}}, {{F(vy)}}, {{F(vz)}}], "spin": [{{F(wx)}}, {{F(wy)}}, {{F(wz)}}] }""";

    private static SimEvent[] Of(StandardSimulation sim, EventKind kind) => sim.Events.AsSpan().ToArray().Where(e => e.Kind == kind).ToArray();

    [Theory]
    [InlineData(Integrators.Event, 0.004)]
    [InlineData(Integrators.Exact, 0.004)]
    [InlineData(Integrators.Exact, 1.0 / 30)]
    public void ADroppedBallLandsAtTheFreeFallTimeAndBouncesBackWithET(string integrator, double dt)
    {
        const double h = 0.3;
        var sim = Create(integrator, dt, BigTable, null, "", Ball3("cue", 0, 0, h));
        Assert.Equal(MotionState.Airborne, sim.Balls[0].State);
        RunToRest(sim);
        var landings = Of(sim, EventKind.BallTable);
        var lifts = Of(sim, EventKind.BallAirborne);
        double fall = Math.Sqrt(2 * (h - R) / G);
        double impact = Math.Sqrt(2 * G * (h - R));
        Assert.True(Math.Abs(landings[0].Time - fall) < 1e-6, $"first landing at {landings[0].Time:R} s, expected {fall:R} s");
        AssertRelative(impact, landings[0].Speed, 1e-9, "impact speed");
        Assert.Equal(landings[0].Time, lifts[0].Time);
        AssertRelative(ET * impact, lifts[0].Speed, 1e-12, "rebound speed");
        // Each bounce: up at e_t times the impact, back after 2 v / g, until a rebound would not lift it 5 mm.
        double t = fall, v = impact;
        int bounces = 0;
        while (ET * v >= Math.Sqrt(2 * G * 0.005))
        {
            v *= ET;
            t += 2 * v / G;
            bounces++;
            Assert.True(Math.Abs(landings[bounces].Time - t) < 1e-6, $"landing {bounces} at {landings[bounces].Time:R} s, expected {t:R} s");
            AssertRelative(v, landings[bounces].Speed, 1e-9, $"impact speed of landing {bounces}");
        }
        Assert.Equal(bounces + 1, landings.Length);
        Assert.Equal(bounces, lifts.Length);
        Assert.Equal(MotionState.Stationary, sim.Balls[0].State);
        Assert.Equal(R, sim.Balls[0].Position.Z);
    }

    [Theory]
    [InlineData(Integrators.Event, 0.004)]
    [InlineData(Integrators.Exact, 0.004)]
    [InlineData(Integrators.Exact, 0.05)]
    public void ABallTossedUpLandsAfterTwiceItsSpeedOverG(string integrator, double dt)
    {
        var sim = Create(integrator, dt, BigTable, null, "", Ball3("cue", 0, 0, R, 0, 0, 2));
        Assert.Equal(MotionState.Airborne, sim.Balls[0].State);
        sim.AdvanceTo(0.5);
        var landing = Of(sim, EventKind.BallTable)[0];
        Assert.True(Math.Abs(landing.Time - 2 * 2 / G) < 1e-6, $"landed at {landing.Time:R} s, expected {2 * 2 / G:R} s");
        AssertRelative(2, landing.Speed, 1e-9, "impact speed");
    }

    [Fact]
    public void InTheAirTheCentreFollowsTheParabolaAndTheSpinStays()
    {
        // Long enough in the air to sample it on a coarse grid.
        var sim = Create(Integrators.Exact, 0.01, BigTable, null, "", Ball3("cue", -1, 0.2, 0.5, 1.5, -0.7, 1, 20, -30, 40));
        foreach (double t in new[] { 0.05, 0.13, 0.29, 0.41 })
        {
            sim.AdvanceTo(t);
            double tt = sim.Time;
            var b = sim.Balls[0];
            Assert.Equal(MotionState.Airborne, b.State);
            Assert.Equal(-1 + 1.5 * tt, b.Position.X, 12);
            Assert.Equal(0.2 - 0.7 * tt, b.Position.Y, 12);
            Assert.Equal(0.5 + tt - 0.5 * G * tt * tt, b.Position.Z, 12);
            Assert.Equal(1 - G * tt, b.Velocity.Z, 12);
            Assert.Equal(V(20, -30, 40), b.Spin);
        }
    }

    [Theory]
    [InlineData(0.002)]
    [InlineData(0.004)]
    [InlineData(1.0 / 30)]
    public void ExactEqualsEventInTheAir(double dt)
    {
        // A ball thrown with spin: it flies, bounces with friction (the slip changes its path and
        // spin at each landing) and ends rolling; exact and event must agree all the way.
        string[] balls = [Ball3("cue", -2, 0.3, 0.4, 1.2, 0.4, 1.5, 30, 10, 5), Ball3("1", 2, -1, 0.2, -0.6, 0.2, 0, -10, 0, 0)];
        var exact = Create(Integrators.Exact, dt, BigTable, null, "", balls);
        var reference = Create(Integrators.Event, dt, BigTable, null, "", balls);
        double worst = 0;
        for (double t = 0.01; t < 3; t += 0.0137)
        {
            exact.AdvanceTo(t);
            reference.AdvanceTo(exact.Time);
            for (int i = 0; i < 2; i++)
            {
                worst = Math.Max(worst, (exact.Balls[i].Position - reference.Balls[i].Position).Length);
            }
        }
        Assert.True(worst <= 1e-9, $"exact and event differ by {worst:E2} m");
        Assert.Equal(Of(reference, EventKind.BallTable).Length, Of(exact, EventKind.BallTable).Length);
        Assert.True(Of(exact, EventKind.BallTable).Length >= 4, "the balls should land and bounce");
    }

    [Theory]
    [InlineData(0, 0, 0)]
    [InlineData(2, 0, 0)]
    [InlineData(2, 0, -150)]
    [InlineData(0.5, 0.5, 300)]
    public void ALandingNeverAddsEnergy(double vx, double vy, double wy)
    {
        var sim = Create(Integrators.Event, 0.004, BigTable, null, "", Ball3("cue", 0, 0, 0.25, vx, vy, 0.5, 0, wy, 10));
        double before = Energy(sim.Balls[0]) + 0.170097 * G * (sim.Balls[0].Position.Z - R);
        int seen = 0;
        while (!sim.IsAtRest && sim.Time < 60)
        {
            sim.Step();
            if (sim.Events.Count > seen && sim.Events[sim.Events.Count - 1].Kind is EventKind.BallTable or EventKind.BallAirborne)
            {
                var b = sim.Balls[0];
                double now = Energy(b) + 0.170097 * G * (b.Position.Z - R);
                Assert.True(now <= before * (1 + 1e-12), $"energy rose across a landing: {before:R} -> {now:R} J");
                before = now;
            }
            seen = sim.Events.Count;
        }
        Assert.True(seen > 0);
    }

    [Fact]
    public void ALandingWithBackspinSlidesAgainstItsSlip()
    {
        // Dropped straight down with backspin: the bed's friction drives it backwards (-x), and
        // takes spin off, never more than the no-slip limit (the slip does not reverse).
        double wy = -100;
        var sim = Create(Integrators.Event, 0.004, BigTable, null, "", Ball3("cue", 0, 0, 0.2, 0, 0, 0, 0, wy, 0));
        sim.AdvanceTo(Math.Sqrt(2 * (0.2 - R) / G) + 1e-4);
        var b = sim.Balls[0];
        double impact = Math.Sqrt(2 * G * (0.2 - R));
        double slip = R * -wy; // u_x = v_x - R w_y
        double j = Math.Min(0.2 * (1 + ET) * impact, slip / 3.5);
        Assert.Equal(-j, b.Velocity.X, 12);
        Assert.Equal(wy + 2.5 / R * j, b.Spin.Y, 9);
        Assert.True(b.Velocity.X - R * b.Spin.Y >= -1e-12, "the landing reversed the slip");
    }

    [Fact]
    public void AScenePlacesABallInTheAirAndRefusesOneInTheBed()
    {
        var sim = Create(Integrators.Event, 0.004, BigTable, null, "", Ball3("cue", 0, 0, 0.1, 0, 0, 1));
        Assert.Equal(0.1, sim.Balls[0].Position.Z);
        Assert.Equal(1, sim.Balls[0].Velocity.Z);
        var e = Assert.Throws<SceneException>(() => Create(Integrators.Event, 0.004, BigTable, null, "", Ball3("cue", 0, 0, 0.01)));
        Assert.Contains("$.balls[0].position[2]", e.Message);
        var thesis = Assert.Throws<SceneException>(() => SceneLoader.Parse(
            """{ "format": "billiards-scene/1", "physics": { "model": "thesis" }, "balls": [ { "id": "cue", "position": [0, 0, 0.1] } ] }""", "t.json"));
        Assert.Contains("standard model", thesis.Message);
    }
}
