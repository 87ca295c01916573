using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Physics.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>The elevated cue drives the cue ball into the slate, which returns it with e_t: steep, fast strokes jump.</summary>
public class JumpShotTests
{
    private const string Table = """{ "preset": "pool-9ft" }""";

    // The tip in the cue's frame: [0, 0] strikes through the ball's centre at 55 deg, no spin,
    // v = (1 + e_tip) V0 / (1 + m/M).
    private const string Jump = """{ "speed": 3, "aim_deg": 0, "tip": [0, 0], "elevation_deg": 55 }""";

    private static SimEvent[] Events(StandardSimulation sim) => sim.Events.AsSpan().ToArray();

    [Fact]
    public void TheSlateReturnsTheStrokeWithETAndItsFriction()
    {
        var sim = Create(Integrators.Event, 0.004, Table, Jump, "", Ball("cue", -0.8, 0));
        sim.AdvanceTo(1e-9);
        var p = PhysicsParams.Pool;
        double theta = 55 * Math.PI / 180;
        double v = (1 + p.ETip) * 3 / (1 + p.M / p.CueMass);
        var events = Events(sim);
        Assert.Equal([EventKind.CueStrike, EventKind.BallTable, EventKind.BallAirborne], events.Select(e => e.Kind));
        Assert.Equal(0, events[1].Time);
        AssertRelative(v * Math.Sin(theta), events[1].Speed, 1e-12, "speed into the slate");
        AssertRelative(0.5 * v * Math.Sin(theta) - G * sim.Time, sim.Balls[0].Velocity.Z, 1e-12, "rebound");
        // No spin from the strike, so the bed's friction stops the slip: v_x = 5/7 v cos theta, rolling spin.
        AssertRelative(5.0 / 7.0 * v * Math.Cos(theta), sim.Balls[0].Velocity.X, 1e-12, "speed along the bed");
        AssertRelative(sim.Balls[0].Velocity.X / R, sim.Balls[0].Spin.Y, 1e-12, "rolling spin");
    }

    [Fact]
    public void AJumpAtFiftyFiveDegreesAndThreeMetresPerSecondClearsABallUnderTheTopOfItsHop()
    {
        // First the hop alone, to find its top.
        var alone = Create(Integrators.Event, 0.004, Table, Jump, "", Ball("cue", -0.8, 0));
        alone.AdvanceTo(1e-9);
        double apex = alone.Balls[0].Velocity.Z / G;
        alone.AdvanceTo(apex);
        var top = alone.Balls[0].Position;
        Assert.True(top.Z - R > 2 * R, $"the hop rises only {top.Z - R:R} m");

        var runs = new List<StandardSimulation>();
        foreach (var integrator in new[] { Integrators.Event, Integrators.Exact })
        {
            // Until it has landed beyond the 1 and rolled on a while (later it may come back off the foot rail).
            var sim = Create(integrator, 0.004, Table, Jump, "", Ball("cue", -0.8, 0), Ball("1", top.X, top.Y));
            sim.AdvanceTo(2 * apex + 0.2);
            Assert.Contains(Events(sim), e => e.Kind == EventKind.BallAirborne);
            Assert.DoesNotContain(Events(sim), e => e.Kind == EventKind.BallBall);
            Assert.Equal(MotionState.Stationary, sim.Balls[1].State);
            Assert.True(sim.Balls[0].Position.X > top.X + 2 * R, "the cue ball did not get past the 1");
            runs.Add(sim);
        }
        // exact is the event solver on a grid: the same events, the same balls at the same time.
        AdvanceBoth(runs[0], runs[1], 2 * apex + 0.2);
        Assert.Equal(Events(runs[0]).Select(e => (e.Kind, e.A, e.B)), Events(runs[1]).Select(e => (e.Kind, e.A, e.B)));
        for (int k = 0; k < Events(runs[0]).Length; k++)
        {
            Assert.Equal(Events(runs[0])[k].Time, Events(runs[1])[k].Time, 1e-9);
        }
        for (int i = 0; i < 2; i++)
        {
            Assert.True((runs[0].Balls[i].Position - runs[1].Balls[i].Position).Length < 1e-9, $"ball {i} differs");
        }
        // The same stroke level goes through the 1.
        var level = Create(Integrators.Event, 0.004, Table, """{ "speed": 3, "aim_deg": 0, "tip": [0, 0], "elevation_deg": 0 }""", "",
            Ball("cue", -0.8, 0), Ball("1", top.X, top.Y));
        RunToRest(level);
        Assert.Contains(Events(level), e => e.Kind == EventKind.BallBall);
    }

    [Fact]
    public void TheShippedJumpSceneClearsItsBall()
    {
        var sim = Load("flight/jump.json", Integrators.Exact);
        sim.AdvanceTo(0.6);
        Assert.DoesNotContain(Events(sim), e => e.Kind == EventKind.BallBall);
        Assert.Contains(Events(sim), e => e.Kind == EventKind.BallAirborne);
    }

    [Theory]
    [InlineData(3, 5)]
    [InlineData(0.5, 30)]
    [InlineData(8, 2)]
    public void LowOrSlowStrokesStayOnTheBed(double speed, double elevation)
    {
        // e_t v sin theta under sqrt(2 g 0.005): the slate's return would not lift the ball 5 mm.
        var shot = new ShotSpec(speed, 0, 0, 0, elevation);
        double v = CueStrike.BallSpeed(speed, 0, 0, PhysicsParams.Pool);
        Assert.True(0.5 * v * Math.Sin(elevation * Math.PI / 180) < Math.Sqrt(2 * G * 0.005));
        var sim = Create(Integrators.Event, 0.004, Table, null, "", Ball("cue", -0.8, 0));
        sim.Strike(shot);
        RunToRest(sim);
        Assert.DoesNotContain(Events(sim), e => e.Kind == EventKind.BallAirborne);
    }

    // The event run ends exactly at the time; the exact run at the first step at or after it: both go on to the same grid time.
    private static void AdvanceBoth(StandardSimulation a, StandardSimulation b, double time)
    {
        b.AdvanceTo(time);
        a.AdvanceTo(b.Time);
    }

    [Fact]
    public void ALevelCueNeverTouchesTheSlate()
    {
        var sim = Create(Integrators.Event, 0.004, Table, """{ "speed": 8, "aim_deg": 0, "tip": [0.3, -0.4], "elevation_deg": 0 }""", "", Ball("cue", -0.8, 0));
        RunToRest(sim);
        Assert.DoesNotContain(Events(sim), e => e.Kind is EventKind.BallTable or EventKind.BallAirborne);
    }
}
