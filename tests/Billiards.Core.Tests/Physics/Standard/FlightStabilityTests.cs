using Billiards.Core.Cue;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Balls thrown about: 16 balls on the pocketless 9 ft table (the bed check holds balls inside the
/// cushion lines, which a pocket's mouth is not), each seeded at a random height (up to 0.3 m) with
/// random velocities (up to 4 m/s along the bed, -2 to 3 m/s up) and spins. They fly over and
/// into each other, bounce, strike and pass over cushions and leave the table. Every
/// run must end, with finite state, no overlap, every ball on the bed or off the table, and the energy (kinetic plus the height's) never rising.
/// </summary>
public class FlightStabilityTests
{
    public static TheoryData<string, double, int> Runs()
    {
        var data = new TheoryData<string, double, int>();
        foreach (int seed in new[] { 1, 2, 3 })
        {
            data.Add("exact", Dt30, seed);
            data.Add("exact", Dt250, seed);
            // Not euler: its explicit step of gravity gains m g^2 dt^2 / 2 per step in the air, by design first order.
            data.Add("event", Dt250, seed);
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Runs))]
    public void ThrownBallsEndOnTheBedOrOffTheTable(string integrator, double dt, int seed)
    {
        var table = Pocketless;
        var random = new SeededRandom(seed);
        var balls = new List<BallSetup>();
        for (int i = 0; i < 16; i++)
        {
            // A 4 x 4 grid 0.4 m apart, jittered by up to 5 cm: never overlapping.
            double x = -0.6 + 0.4 * (i % 4) + (random.NextDouble() - 0.5) * 0.1;
            double y = -0.45 + 0.3 * (i / 4) + (random.NextDouble() - 0.5) * 0.1;
            double z = R + random.NextDouble() * 0.3;
            var v = new Vec3((random.NextDouble() - 0.5) * 8, (random.NextDouble() - 0.5) * 8, random.NextDouble() * 5 - 2);
            var w = new Vec3((random.NextDouble() - 0.5) * 200, (random.NextDouble() - 0.5) * 200, (random.NextDouble() - 0.5) * 100);
            balls.Add(new BallSetup(new BallId(i), new Vec3(x, y, z), v, w));
        }
        var sim = Create(integrator, dt, balls, table);
        StepChecked(sim, 120, $"thrown balls, seed {seed}, {integrator} dt {dt:R}");
        Assert.True(sim.IsAtRest, "the thrown balls still move at 120 s");
        foreach (var b in sim.Balls)
        {
            Assert.True(b.State is MotionState.Stationary or MotionState.OffTable, $"a ball ended {b.State}");
        }
        AssertAtRestOnTheTable(sim, $"thrown balls, seed {seed}, {integrator} dt {dt:R}");
        var events = sim.Events.AsSpan().ToArray();
        Assert.Contains(events, e => e.Kind == EventKind.BallTable);
        Assert.Contains(events, e => e.Kind == EventKind.BallBall);
        Assert.Contains(events, e => e.Kind == EventKind.BallOffTable);
    }

    public static TheoryData<string, double> Strokes => new()
    {
        { "exact", Dt30 },
        { "exact", Dt250 },
        { "event", Dt250 },
    };

    [Theory]
    [MemberData(nameof(Strokes))]
    public void AJumpOverABlockingBallAndABallTossedOffTheTableEndSound(string integrator, double dt)
    {
        // The must-show jump (55 deg through the centre at 3 m/s, the 1 under the top of its hop)
        // on the 9 ft table with pockets, while the 5 is tossed over the foot rail: each step
        // finite, on the bed or in the air clear of the table, the energy never rising; the 1
        // untouched until the cue ball is down, the 5 off the table where it came down to the
        // rails' top, beyond them: vz t - g t^2 / 2 = H, 2 m/s t further on.
        var table = TableSpec.FromPreset("pool-9ft");
        var balls = new List<BallSetup>
        {
            Ball(0, -0.8, 0),
            Ball(1, -0.4356, 0),
            new(new BallId(5), new Vec3(1.1, 0.3, R), new Vec3(2.0, 0, 2.5), Vec3.Zero),
        };
        var sim = Create(integrator, dt, balls, table);
        sim.Strike(new ShotSpec(3.0, 0, 0, Math.Sin(55 * Math.PI / 180), 55), new BallId(0));
        StepChecked(sim, 60, $"jump and toss, {integrator} dt {dt:R}");
        var events = sim.Events.AsSpan().ToArray();
        double landed = events.Where(e => e.Kind == EventKind.BallTable && e.A == new BallId(0) && e.Time > 0).Min(e => e.Time);
        Assert.DoesNotContain(events, e => e.Kind == EventKind.BallBall && e.Time < landed);
        var off = Assert.Single(events, e => e.Kind == EventKind.BallOffTable);
        Assert.Equal(new BallId(5), off.A);
        double down = (2.5 + Math.Sqrt(2.5 * 2.5 - 2 * G * table.RailHeight)) / G;
        Assert.Equal(down, off.Time, 1e-9);
        Assert.Equal(MotionState.OffTable, sim.Balls[Index(sim, 5)].State);
        Assert.Equal(1.1 + 2.0 * down, sim.Balls[Index(sim, 5)].Position.X, 1e-9);
        Assert.True(1.1 + 2.0 * down > table.HalfLength + table.RailWidth, "the 5 should come down beyond the foot rail");
        Assert.True(sim.IsAtRest, "still moving at 60 s");
    }

    public static TheoryData<string, double> ElevatedRuns => new()
    {
        { "exact", Dt30 },
        { "exact", Dt250 },
        { "event", Dt250 },
        { "euler", Dt250 },
    };

    /// <summary>
    /// Issue 40's elevated strokes, 60 seeded ones per integrator: a racked 8- or 9-ball table on
    /// every preset in turn, the cue ball anywhere on the bed, 0.1-12 m/s, a tip within half the
    /// radius, the cue elevated 0-80 deg. Every step finite, every ball on the bed or in the air
    /// clear of the table (the energy never rising, but for euler's first-order gravity), and at
    /// rest every ball on the bed, in a pocket or off the table: none outside it, none inside a cushion.
    /// </summary>
    [Theory]
    [MemberData(nameof(ElevatedRuns))]
    public void ElevatedStrokesOnEveryPresetEndOnTheTable(string integrator, double dt)
    {
        var random = new SeededRandom(40);
        int offTable = 0;
        for (int stroke = 0; stroke < 60; stroke++)
        {
            var table = TableSpec.FromPreset(TableSpec.PresetNames[stroke % TableSpec.PresetNames.Count]);
            var rack = new RackSpec(random.NextDouble() < 0.5 ? RackGame.EightBall : RackGame.NineBall, (int)(random.NextDouble() * 1e6));
            var balls = Initializer.Rack(rack, table, R).Select(b => new BallSetup(b.Id, b.Position, Vec3.Zero, Vec3.Zero)).ToList();
            Vec3 cue;
            do
            {
                cue = new Vec3((2 * random.NextDouble() - 1) * (table.HalfLength - R), (2 * random.NextDouble() - 1) * (table.HalfWidth - R), R);
            }
            while (balls.Any(b => (b.Position - cue).LengthXY < 2 * R));
            balls.Insert(0, new BallSetup(PoolBalls.Cue, cue, Vec3.Zero, Vec3.Zero));
            double tip = 0.5 * Math.Sqrt(random.NextDouble()), angle = 2 * Math.PI * random.NextDouble();
            var shot = new ShotSpec(0.1 + 11.9 * random.NextDouble(), 360 * random.NextDouble() - 180, tip * Math.Cos(angle), tip * Math.Sin(angle), 80 * random.NextDouble());
            var sim = Create(integrator, dt, balls, table);
            sim.Strike(shot, PoolBalls.Cue);
            string where = $"stroke {stroke} on {table.Preset}, {integrator} dt {dt:R}";
            if (integrator == "euler")
            {
                while (!sim.IsAtRest && sim.Time < 120)
                {
                    sim.Step();
                    AssertFinite(sim, where);
                    // First-order gravity: within one step's g dt^2 of the landing height.
                    AssertOnBed(sim, where, airTolerance: 9.81 * dt * dt);
                }
            }
            else
            {
                StepChecked(sim, 120, where, checkOverlap: true, energyTolerance: 1e-9);
            }
            Assert.True(sim.IsAtRest, $"{where}: still moving at 120 s");
            AssertAtRestOnTheTable(sim, where);
            offTable += sim.Balls.ToArray().Count(b => b.State == MotionState.OffTable);
        }
        Assert.True(offTable > 0, "no stroke left the table: the mix should make some leave");
    }
}
