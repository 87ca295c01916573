using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Shared pieces of the stiff and extreme stability suite: scenes built in code, the three step
/// sizes, and the invariants every case checks (finite state, on the bed, no overlap, energy).
/// </summary>
internal static class StabilityKit
{
    public const double M = PhysicsParams.DefaultMass;
    public const double R = PhysicsParams.DefaultRadius;
    public const double G = 9.81;
    public const double MuS = 0.2;
    public const double MuR = 0.01;

    /// <summary>I = 2/5 m R^2 (kg m^2).</summary>
    public const double Inertia = 0.4 * M * R * R;

    /// <summary>How far a centre may stand past the cushion line and still count as on the bed (m).</summary>
    public const double BedTolerance = 1e-9;

    /// <summary>Largest overlap of two balls the suite accepts (m): 0.1 mm.</summary>
    public const double OverlapTolerance = 1e-4;

    public const double Dt30 = 1.0 / 30;
    public const double Dt250 = 1.0 / 250;
    public const double Dt8000 = 1.0 / 8000;

    /// <summary>The exact integrator at the three step sizes, and the event solver once (its steps are events, dt only labels it).</summary>
    public static TheoryData<string, double> ExactAndEvent => new()
    {
        { Integrators.Exact, Dt30 },
        { Integrators.Exact, Dt250 },
        { Integrators.Exact, Dt8000 },
        { Integrators.Event, Dt250 },
    };

    /// <summary>As <see cref="ExactAndEvent"/>, plus the naive Euler baseline at the three step sizes.</summary>
    public static TheoryData<string, double> AllIntegrators => new()
    {
        { Integrators.Exact, Dt30 },
        { Integrators.Exact, Dt250 },
        { Integrators.Exact, Dt8000 },
        { Integrators.Event, Dt250 },
        { Integrators.Euler, Dt30 },
        { Integrators.Euler, Dt250 },
        { Integrators.Euler, Dt8000 },
    };

    public static readonly TableSpec Pocketless = TableSpec.FromPreset("pocketless");

    /// <summary>A ball at (x, y) on the bed with a velocity and spin.</summary>
    public static BallSetup Ball(int id, double x, double y, double vx = 0, double vy = 0, Vec3 spin = default) =>
        new(new BallId(id), new Vec3(x, y, R), new Vec3(vx, vy, 0), spin);

    /// <summary>A scene of explicit balls on <paramref name="table"/> (pocketless by default), no rack, no rules.</summary>
    public static Scene Scene(string integrator, double dt, IEnumerable<BallSetup> balls, TableSpec? table = null, PhysicsParams? parameters = null) =>
        new("stability.json", "stability", table ?? Pocketless,
            PhysicsConfig.Default with { Integrator = ModelRegistry.FindIntegrator(ModelRegistry.Standard, integrator)!, Dt = dt, Params = parameters ?? PhysicsParams.Default },
            null, [.. balls.OrderBy(b => b.Id.Value)], null, null);

    public static Simulation Create(string integrator, double dt, IEnumerable<BallSetup> balls, TableSpec? table = null, PhysicsParams? parameters = null) =>
        SimulationFactory.Create(Scene(integrator, dt, balls, table, parameters));

    /// <summary>The ball radius the simulation runs with (m).</summary>
    public static double RadiusOf(Simulation sim) => sim is StandardSimulation s ? s.Parameters.R : R;

    /// <summary>
    /// The 15 object balls in a triangle with spacing exactly 2R (frozen: every neighbour touches),
    /// the apex (ball 1) on the foot spot, opening towards +x. Rows are sqrt(3) R apart, so
    /// neighbours in adjacent rows are sqrt(3 R^2 + R^2) = 2R apart.
    /// </summary>
    public static List<BallSetup> FrozenRack(TableSpec table)
    {
        var balls = new List<BallSetup>();
        double apex = table.HalfLength / 2;
        int id = 1;
        for (int row = 0; row < 5; row++)
        {
            for (int j = 0; j <= row; j++)
            {
                balls.Add(Ball(id++, apex + row * Math.Sqrt(3) * R, (2 * j - row) * R));
            }
        }
        return balls;
    }

    /// <summary>
    /// The cue speed V0 that gives the ball <paramref name="ballSpeed"/> with a centre hit and a
    /// level cue: TP A-30 with a = b = 0, theta = 0 gives v = 2 V0 / (1 + m/M) and no spin, so
    /// V0 = v (1 + m/M) / 2, with m/M = 0.170097 / 0.567 = 0.29999.
    /// </summary>
    public static double CueSpeedFor(double ballSpeed) => ballSpeed * (1 + M / PhysicsParams.Default.CueMass) / 2;

    /// <summary>Total kinetic energy, translational and rotational: sum of 1/2 m v^2 + 1/2 I w^2 (J).</summary>
    public static double KineticEnergy(ReadOnlySpan<BallState> balls)
    {
        double e = 0;
        foreach (ref readonly var b in balls)
        {
            e += 0.5 * M * b.Velocity.LengthSquared + 0.5 * Inertia * b.Spin.LengthSquared;
        }
        return e;
    }

    /// <summary>
    /// Kinetic energy plus the potential energy m g (z - R) of the balls in the air (J): what may
    /// never rise once a ball can fly (a falling ball turns height into speed).
    /// </summary>
    public static double MechanicalEnergy(Simulation sim)
    {
        double e = KineticEnergy(sim.Balls);
        double r = RadiusOf(sim);
        foreach (ref readonly var b in sim.Balls)
        {
            if (b.State == MotionState.Airborne)
            {
                e += M * G * (b.Position.Z - r);
            }
        }
        return e;
    }

    /// <summary>Total linear momentum in the bed plane (kg m/s).</summary>
    public static Vec3 Momentum(ReadOnlySpan<BallState> balls)
    {
        var p = Vec3.Zero;
        foreach (ref readonly var b in balls)
        {
            p += b.Velocity.XY * M;
        }
        return p;
    }

    /// <summary>Every position, velocity and spin is finite.</summary>
    public static void AssertFinite(Simulation sim, string where)
    {
        var balls = sim.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            Assert.True(balls[i].Position.IsFinite && balls[i].Velocity.IsFinite && balls[i].Spin.IsFinite,
                $"{where}: ball {sim.Ids[i]} is not finite at t = {sim.Time:R}: p {Fmt(balls[i].Position)}, v {Fmt(balls[i].Velocity)}, w {Fmt(balls[i].Spin)}");
        }
    }

    /// <summary>
    /// Every ball not in a pocket or off the table has its centre inside the cushion lines less R
    /// (to <see cref="BedTolerance"/>) or in a pocket's mouth clear of the jaws, and z = R, or, when it flies, z at least R and, wherever a
    /// ball on the bed would not fit under it (over a cushion, a rail, a hole or the floor), its
    /// bottom above the rails' top: nothing of the table is inside a ball in the air, to
    /// <paramref name="airTolerance"/> (euler's explicit step of gravity may carry a ball up to
    /// g dt^2 below its landing height before the step finds the landing).
    /// </summary>
    public static void AssertOnBed(Simulation sim, string where, double airTolerance = BedTolerance)
    {
        var balls = sim.Balls;
        double r = RadiusOf(sim);
        double xMax = sim.Table.HalfLength - r + BedTolerance;
        double yMax = sim.Table.HalfWidth - r + BedTolerance;
        var geometry = TableGeometry.Build(sim.Table, r);
        double railTop = sim.Table.RailHeight + r;
        for (int i = 0; i < balls.Length; i++)
        {
            if (balls[i].IsOutOfPlay)
            {
                continue;
            }
            var p = balls[i].Position;
            if (balls[i].State == MotionState.Airborne)
            {
                bool overBed = geometry.SurfaceUnder(p).Kind == SurfaceKind.Bed;
                Assert.True(p.Z >= (overBed ? r : railTop) - airTolerance,
                    $"{where}: ball {sim.Ids[i]} in the air at t = {sim.Time:R} is inside the table at {Fmt(p)} (over {geometry.SurfaceUnder(p).Kind}, rails' top {railTop:R})");
                continue;
            }
            // Inside the noses' lines less R, or in a pocket's mouth, and in no cushion or jaw.
            bool onBed = (Math.Abs(p.X) <= xMax && Math.Abs(p.Y) <= yMax)
                || (TableBounds.Contains(sim.Table, p, r) && geometry.CushionDepth(p) <= StateChecker.CushionTolerance);
            Assert.True(onBed && Math.Abs(p.Z - r) <= BedTolerance,
                $"{where}: ball {sim.Ids[i]} left the bed at t = {sim.Time:R}: {Fmt(p)} (limits |x| <= {xMax:R}, |y| <= {yMax:R}, or a pocket's mouth; {geometry.CushionDepth(p):E3} m into a cushion)");
        }
    }

    /// <summary>
    /// The table-bound guarantee at rest (<see cref="StateChecker.PlaceOf"/>): every ball is on the
    /// bed, in a pocket or off the table, none outside the table nor inside a cushion.
    /// </summary>
    public static void AssertAtRestOnTheTable(Simulation sim, string where)
    {
        for (int i = 0; i < sim.Balls.Length; i++)
        {
            var place = StateChecker.PlaceOf(sim, i);
            Assert.True(place is BallPlace.Bed or BallPlace.Pocket or BallPlace.OffTable,
                $"{where}: ball {sim.Ids[i]} ended {place} at {Fmt(sim.Balls[i].Position)}, {sim.Balls[i].State}");
        }
    }

    /// <summary>No two balls in play (in space) overlap by more than <see cref="OverlapTolerance"/>.</summary>
    public static void AssertNoOverlap(Simulation sim, string where)
    {
        var balls = sim.Balls;
        double r = RadiusOf(sim);
        for (int i = 0; i < balls.Length; i++)
        {
            for (int j = i + 1; j < balls.Length; j++)
            {
                if (balls[i].IsOutOfPlay || balls[j].IsOutOfPlay)
                {
                    continue;
                }
                // In space: a ball in the air may pass over another.
                double d = (balls[i].Position - balls[j].Position).Length;
                Assert.True(d >= 2 * r - OverlapTolerance,
                    $"{where}: balls {sim.Ids[i]} and {sim.Ids[j]} overlap by {2 * r - d:E3} m at t = {sim.Time:R}");
            }
        }
    }

    /// <summary>
    /// Advances (see <see cref="Advance"/>) until rest or <paramref name="limit"/>, checking after every step: finite, on the bed,
    /// and kinetic energy never above the previous sample by more than round-off
    /// (<paramref name="energyTolerance"/> of the energy at the start). Returns the largest rise seen.
    /// </summary>
    public static double StepChecked(Simulation sim, double limit, string where, bool checkOverlap = false, double energyTolerance = 1e-12, Action<Simulation>? afterStep = null)
    {
        double previous = MechanicalEnergy(sim);
        double slack = energyTolerance * Math.Max(previous, 1e-300);
        double worstRise = 0;
        while (sim.Time < limit - 1e-12 && !sim.IsAtRest)
        {
            Advance(sim);
            double e = MechanicalEnergy(sim);
            AssertFinite(sim, where);
            AssertOnBed(sim, where);
            if (checkOverlap)
            {
                AssertNoOverlap(sim, where);
            }
            afterStep?.Invoke(sim);
            worstRise = Math.Max(worstRise, e - previous);
            Assert.True(e <= previous + slack,
                $"{where}: kinetic energy rose from {previous:R} J to {e:R} J (by {e - previous:E3} J) in the step ending t = {sim.Time:R}");
            previous = e;
        }
        return worstRise;
    }

    /// <summary>
    /// One sample step: a fixed step for the stepping integrators; for the event solver, whose
    /// own steps jump from event to event, an advance of its nominal dt (events inside are
    /// resolved exactly, and it stops early at rest).
    /// </summary>
    public static void Advance(Simulation sim)
    {
        if (sim.Integrator.IsReference)
        {
            sim.AdvanceTo(sim.Time + sim.Dt);
        }
        else
        {
            sim.Step();
        }
    }

    /// <summary>
    /// A vector as text. Vec3's own ToString never returns (its record printer prints the XY
    /// property, itself a Vec3, forever), so no message here may interpolate a Vec3 directly.
    /// </summary>
    public static string Fmt(Vec3 v) => $"({v.X:R}, {v.Y:R}, {v.Z:R})";

    /// <summary>Asserts two vectors equal component by component within <paramref name="tolerance"/> (0: bit for bit up to the sign of zero).</summary>
    public static void AssertVec(Vec3 expected, Vec3 actual, double tolerance, string what)
    {
        bool ok = Math.Abs(expected.X - actual.X) <= tolerance && Math.Abs(expected.Y - actual.Y) <= tolerance
            && Math.Abs(expected.Z - actual.Z) <= tolerance;
        Assert.True(ok, $"{what}: expected {Fmt(expected)}, got {Fmt(actual)} (tolerance {tolerance:E2})");
    }

    /// <summary>Index of a ball in the simulation, asserting that it exists.</summary>
    public static int Index(Simulation sim, int id)
    {
        int i = sim.IndexOf(new BallId(id));
        Assert.True(i >= 0, $"ball {id} not found");
        return i;
    }

    /// <summary>The events of one kind, in log order.</summary>
    public static List<SimEvent> EventsOf(Simulation sim, EventKind kind) =>
        [.. sim.Events.AsSpan().ToArray().Where(e => e.Kind == kind)];
}
