using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Physics.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Physics.Standard.Events;

/// <summary>Contacts in the air: ball-ball in space, cushions at their height or passed over, pockets from the air, balls leaving the table.</summary>
public class AirCollisionTests
{
    private const string Table = """{ "preset": "pool-9ft" }""";

    private static string Ball3(string id, double x, double y, double z, double vx = 0, double vy = 0, double vz = 0) =>
        $$"""{ "id": "{{id}}", "position": [{{F(x)}}, {{F(y)}}, {{F(z)}}], "velocity": [{{F(vx)}}, {{F(vy)}}, {{F(vz)}}] }""";

    private static SimEvent[] Events(StandardSimulation sim) => sim.Events.AsSpan().ToArray();

    private static SimEvent First(StandardSimulation sim, EventKind kind) => Events(sim).First(e => e.Kind == kind);

    [Theory]
    [InlineData(Integrators.Event, 0.004)]
    [InlineData(Integrators.Exact, 0.004)]
    [InlineData(Integrators.Exact, 1.0 / 30)]
    public void ABallTossedOverTheFootRailLeavesTheTable(string integrator, double dt)
    {
        // From x = 1.0 at 2 m/s along +x and 2.5 m/s up: it crosses the noses' line x = L/2 after
        // (L/2 - 1) / 2 s, its bottom 0.25 m up, far above the rails, and comes down to the rails'
        // top H when 2.5 t - g t^2 / 2 = H, at x = 1 + 2 t, beyond the rails: on the floor.
        var spec = TableSpec.FromPreset("pool-9ft");
        var sim = Create(integrator, dt, Table, null, "", Ball3("cue", 1.0, 0, R, 2, 0, 2.5));
        RunToRest(sim);
        var off = First(sim, EventKind.BallOffTable);
        double t = (2.5 + Math.Sqrt(2.5 * 2.5 - 2 * G * spec.RailHeight)) / G;
        Assert.True(Math.Abs(off.Time - t) < 1e-12, $"left at {off.Time:R} s, expected {t:R} s");
        Assert.Equal(MotionState.OffTable, sim.Balls[0].State);
        Assert.Equal(1.0 + 2 * t, sim.Balls[0].Position.X, 12);
        Assert.True(sim.Balls[0].Position.X > spec.HalfLength + spec.RailWidth);
        Assert.DoesNotContain(Events(sim), e => e.Kind is EventKind.BallCushion or EventKind.BallPocket);
    }

    [Fact]
    public void ALowFlyingBallStrikesTheCushionAndComesBack()
    {
        // 5 mm off the bed, rising: at the cushion, before it lands, its bottom is 23 mm up, below the rails' top.
        var sim = Create(Integrators.Event, 0.004, Table, null, "", Ball3("cue", 1.0, 0, R + 0.005, 4, 0, 0.6));
        sim.AdvanceTo(0.5);
        var hit = First(sim, EventKind.BallCushion);
        var spec = TableSpec.FromPreset("pool-9ft");
        double t = (spec.HalfLength - R - 1.0) / 4;
        Assert.True(hit.Time < First(sim, EventKind.BallTable).Time, "it landed before the cushion");
        Assert.True(Math.Abs(hit.Time - t) < 1e-12, $"hit at {hit.Time:R} s, expected {t:R} s");
        Assert.DoesNotContain(Events(sim), e => e.Kind == EventKind.BallOffTable);
        Assert.True(sim.Balls[0].Velocity.X < 0, "the ball did not come back");
    }

    [Fact]
    public void ABallHighOverAPocketFliesOnAndALowOneDropsIn()
    {
        var spec = TableSpec.FromPreset("pool-9ft");
        var geometry = TableGeometry.Build(spec, R);
        var pocket = geometry.Pockets.ToArray().First(p => p.Centre.X > 0 && p.Centre.Y > 0 && p.Centre.X > spec.HalfLength - 0.1);
        // Along the diagonal towards the foot-left corner's hole, 0.2 m short of it.
        var dir = new Billiards.Core.Mathematics.Vec3(1, 1, 0).Normalized();
        var start = pocket.Centre - dir * 0.2;
        var low = Create(Integrators.Event, 0.004, Table, null, "", Ball3("cue", start.X, start.Y, R + 0.005, dir.X, dir.Y, 0.3));
        low.AdvanceTo(1);
        Assert.Equal(MotionState.Pocketed, low.Balls[0].State);
        var high = Create(Integrators.Event, 0.004, Table, null, "", Ball3("cue", start.X, start.Y, R + 0.2, dir.X, dir.Y, 1));
        high.AdvanceTo(1);
        Assert.Equal(MotionState.OffTable, high.Balls[0].State);
        Assert.DoesNotContain(Events(high), e => e.Kind == EventKind.BallPocket);
    }

    [Theory]
    [InlineData(Integrators.Event, 0.004)]
    [InlineData(Integrators.Exact, 1.0 / 30)]
    public void ABallFallingOnABallAtRestMeetsItAtTheExactTimeAndDrivesItIntoTheBed(string integrator, double dt)
    {
        // Dropped from 0.3 m, 1 cm to the side of the 1: they touch when the vertical gap is
        // sqrt(4 R^2 - 0.01^2), after t = sqrt(2 (0.3 - R - gap) / g).
        const double dx = 0.01;
        var sim = Create(integrator, dt, Table, null, "", Ball3("cue", dx, 0, 0.3), Ball("1", 0, 0));
        double gap = Math.Sqrt(4 * R * R - dx * dx);
        double t = Math.Sqrt(2 * (0.3 - R - gap) / G);
        sim.AdvanceTo(t + 0.05);
        var hit = First(sim, EventKind.BallBall);
        Assert.True(Math.Abs(hit.Time - t) < 1e-9, $"met at {hit.Time:R} s, expected {t:R} s");
        AssertRelative(G * t * gap / (2 * R), hit.Speed, 1e-9, "normal approach speed");
        // The 1 was driven down (the bed returns it at once) and away to -x; the cue ball to +x.
        Assert.Contains(Events(sim), e => e.Kind == EventKind.BallTable && e.A.Value == 1 && e.Time == hit.Time);
        Assert.True(sim.Balls[1].Velocity.X < 0 && sim.Balls[0].Velocity.X > 0);
    }

    [Fact]
    public void TwoBallsInTheAirMeetAndSeparateAtEBTimesTheirApproach()
    {
        var sim = Create(Integrators.Event, 0.004, """{ "preset": "pocketless", "length": 10, "width": 5 }""", null, "",
            Ball3("cue", -0.25, 0, 0.5, 1, 0, 0), Ball3("1", 0.25, 0, 0.5, -1, 0, 0));
        sim.AdvanceTo(0.25);
        var hit = First(sim, EventKind.BallBall);
        double t = (0.5 - 2 * R) / 2;
        Assert.True(Math.Abs(hit.Time - t) < 1e-12, $"met at {hit.Time:R} s, expected {t:R} s");
        Assert.Equal(MotionState.Airborne, sim.Balls[0].State);
        AssertRelative(0.95 * 2, sim.Balls[1].Velocity.X - sim.Balls[0].Velocity.X, 1e-12, "separation speed");
        Assert.Equal(sim.Balls[0].Velocity.Z, sim.Balls[1].Velocity.Z);
    }

    [Theory]
    [InlineData(0.002)]
    [InlineData(1.0 / 30)]
    public void ExactEqualsEventThroughAirContacts(double dt)
    {
        string[] balls = [Ball3("cue", 0.012, 0.004, 0.3, 0.3, 0, 0), Ball("1", 0, 0), Ball3("2", 0.8, 0.1, R, 2, 0.3, 2.5), Ball3("3", -0.5, 0, 0.2, 1, 0, 0.5), Ball3("4", 0.5, 0.01, 0.2, -1, 0, 0.5)];
        var exact = Create(Integrators.Exact, dt, Table, null, "", balls);
        var reference = Create(Integrators.Event, dt, Table, null, "", balls);
        RunToRest(reference);
        RunToRest(exact);
        Assert.Equal(reference.Events.Count, exact.Events.Count);
        for (int i = 0; i < balls.Length; i++)
        {
            double d = (exact.Balls[i].Position - reference.Balls[i].Position).Length;
            Assert.True(d <= 1e-6, $"ball {exact.Ids[i]} differs by {d:E2} m");
            Assert.Equal(reference.Balls[i].State, exact.Balls[i].State);
        }
        Assert.Contains(Events(reference), e => e.Kind == EventKind.BallOffTable);
        Assert.True(Events(reference).Count(e => e.Kind == EventKind.BallBall) >= 2);
    }

    [Fact]
    public void ASceneRailHeightIsReadAndChecked()
    {
        var scene = SceneLoader.Parse("""{ "format": "billiards-scene/1", "table": { "preset": "pool-9ft", "rail_height": 0.05 }, "balls": [] }""", "t.json");
        Assert.Equal(0.05, scene.Table.RailHeight);
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse("""{ "format": "billiards-scene/1", "table": { "preset": "pool-9ft", "rail_height": 0.02 }, "balls": [] }""", "t.json"));
        Assert.Contains("$.table.rail_height", e.Message);
    }
}
