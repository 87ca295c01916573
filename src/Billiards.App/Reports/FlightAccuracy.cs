using System.Globalization;
using System.Text;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Reports;

/// <summary>One flight check: a measured quantity of a scene in one configuration against its analytic value.</summary>
/// <param name="Case">What is checked.</param>
/// <param name="Series">"event", or "exact" or "euler" with its step.</param>
/// <param name="Measured">The simulation's value.</param>
/// <param name="Analytic">The analytic value (NaN where the check is a bound, not a value).</param>
/// <param name="Error">|measured - analytic|, or the bound's excess (0 when it holds).</param>
/// <param name="Unit">The unit of the values.</param>
public sealed record FlightRow(string Case, string Series, double Measured, double Analytic, double Error, string Unit);

/// <summary>
/// The accuracy report's flight section: the shipped flight scenes (<c>assets/scenes/flight</c>)
/// against the analytic parabola and bounce times, a jump over a blocking ball, a ball leaving
/// the table, and the energy across every landing; by the event solver and by the exact and Euler
/// integrators at a coarse and a fine step. A section of its own, so the suite's rows are as before.
/// </summary>
public static class FlightAccuracy
{
    /// <summary>The configurations measured: the reference, then (integrator, step).</summary>
    public static IReadOnlyList<(string Integrator, double? Dt)> Configurations { get; } =
        [(Integrators.Event, null), (Integrators.Exact, 1.0 / 30), (Integrators.Exact, 1.0 / 1000), (Integrators.Euler, 1.0 / 1000)];

    /// <summary>The scenes the section reads, in the flight folder.</summary>
    public static IReadOnlyList<string> SceneNames { get; } = ["drop.json", "toss.json", "jump.json", "eight-ball-over-the-foot-rail.json"];

    /// <summary>Loads every scene in every configuration (throws on a bad one) before anything is measured.</summary>
    public static void Validate(string folder)
    {
        foreach (string name in SceneNames)
        {
            foreach (var (integrator, dt) in Configurations)
            {
                Load(folder, name, integrator, dt);
            }
        }
    }

    /// <summary>Measures every check in every configuration.</summary>
    public static List<FlightRow> Measure(string folder)
    {
        var rows = new List<FlightRow>();
        foreach (var (integrator, dt) in Configurations)
        {
            string series = dt is { } d ? $"{integrator} 1/{Math.Round(1 / d)}" : integrator;
            void Add(string what, double measured, double analytic, string unit) =>
                rows.Add(new FlightRow(what, series, measured, analytic, Math.Abs(measured - analytic), unit));

            // The drop from 0.3 m: first landing, its rebound, the second landing.
            var drop = Run(folder, "drop.json", integrator, dt, out var dropScene);
            var p = dropScene.Physics.Params;
            double r = dropScene.BallRadius, g = p.G;
            double t1 = Math.Sqrt(2 * (0.3 - r) / g), v1 = g * t1;
            var landings = Events(drop, EventKind.BallTable);
            Add("drop from 0.3 m: first landing sqrt(2 (0.3 - R) / g)", Time(landings, 0), t1, "s");
            Add("drop: rebound speed e_t times the landing speed", Speed(Events(drop, EventKind.BallAirborne), 0), p.ET * v1, "m/s");
            Add("drop: second landing t1 + 2 e_t v1 / g", Time(landings, 1), t1 + (2 * p.ET * v1 / g), "s");

            // The toss up at 2 m/s.
            var toss = Run(folder, "toss.json", integrator, dt, out _);
            Add("toss up at 2 m/s: landing 2 * 2 / g", Time(Events(toss, EventKind.BallTable), 0), 2 * 2 / g, "s");

            // The jump: the cue ball's first hop from the slate's return, and the 1 it must clear.
            var jump = Run(folder, "jump.json", integrator, dt, out var jumpScene);
            var strike = CueStrike.Strike(jumpScene.Shot!, jumpScene.Physics.Params);
            double up = p.ET * strike.IntoSlate;
            // The hop starts when the ball leaves the slate (t = 0 with exact contacts, Euler's first step).
            double launched = Time(Events(jump, EventKind.BallAirborne), 0);
            var cueLandings = Events(jump, EventKind.BallTable).Where(e => e.Time > launched).ToList();
            Add("jump: leaves the slate at the strike", launched, 0, "s");
            Add("jump at 55 deg, 3 m/s: first hop's landing 2 e_t v sin(theta) / g", Time(cueLandings, 0), 2 * up / g, "s");
            double hit = jump.Events.AsSpan().ToArray().Where(e => e.Kind == EventKind.BallBall).Select(e => e.Time).DefaultIfEmpty(double.PositiveInfinity).Min();
            double firstLanding = Time(cueLandings, 0);
            // Touching the 1 while the cue ball hops over it would be a contact before its landing.
            rows.Add(new FlightRow("jump: contacts with the 1 before the hop lands (0)", series, hit < firstLanding ? 1 : 0, 0, hit < firstLanding ? 1 : 0, "contacts"));

            // The 5 tossed over the foot rail: it leaves the table where it comes down to the rails'
            // top H beyond them (docs/flight.md), z0 + vz t - g t^2 / 2 = H + R, on the floor.
            var over = Run(folder, "eight-ball-over-the-foot-rail.json", integrator, dt, out var overScene);
            var five = overScene.Balls.First(b => b.Id.Value == 5);
            double vz = five.Velocity.Z, fall = overScene.Table.RailHeight + r - five.Position.Z;
            double down = (vz + Math.Sqrt(vz * vz - 2 * g * fall)) / g;
            Add("ball over the foot rail: ball-off-table coming down to the rails' top, (vz + sqrt(vz^2 - 2 g (H + R - z0))) / g", Time(Events(over, EventKind.BallOffTable), 0), down, "s");
            int fiveIndex = over.IndexOf(five.Id);
            Add("ball over the foot rail: off the table at x0 + vx t, beyond the rail", over.Balls[fiveIndex].Position.X, five.Position.X + five.Velocity.X * down, "m");

            // The energy (kinetic, rotational and the height's) across every landing of these shots;
            // not for euler, whose explicit step of gravity gains m g^2 dt^2 / 2 a step in the air by design.
            if (integrator == Integrators.Euler)
            {
                continue;
            }
            double rise = 0;
            foreach (string name in SceneNames)
            {
                rise = Math.Max(rise, LargestRiseAcrossLandings(Load(folder, name, integrator, dt)));
            }
            rows.Add(new FlightRow("energy across every landing never rises (largest rise)", series, rise, double.NaN, Math.Max(0, rise), "J"));
        }
        return rows;
    }

    /// <summary>The section in Markdown.</summary>
    public static string ToMarkdown(IReadOnlyList<FlightRow> rows)
    {
        var inv = CultureInfo.InvariantCulture;
        var sb = new StringBuilder();
        sb.Append("\n## Flight\n\n");
        sb.Append("The scenes of `assets/scenes/flight` against the analytic parabola and bounce times (g, R and e_t of the scene), the jump's blocking ball, the ball leaving the table and the energy across every landing (at each `ball-table` event of the four shots, the total just after less just before; a rise above round-off would be a defect). Event solver, then `exact` and `euler` at a coarse and a fine step; a section of its own, the suite's rows above are unchanged by it.\n\n");
        sb.Append("| check | series | measured | analytic | error | unit |\n|---|---|---|---|---|---|\n");
        foreach (var row in rows.OrderBy(x => x.Case, StringComparer.Ordinal).ThenBy(x => Rank(x.Series)))
        {
            string analytic = double.IsNaN(row.Analytic) ? "<= 0" : row.Analytic.ToString("0.000000000", inv);
            sb.Append(inv, $"| {row.Case} | {row.Series} | {row.Measured:0.000000000} | {analytic} | {row.Error:0.00e+00} | {row.Unit} |\n");
        }
        return sb.ToString();
    }

    private static int Rank(string series) => Configurations.Select((c, i) => (Name: c.Dt is { } d ? $"{c.Integrator} 1/{Math.Round(1 / d)}" : c.Integrator, i)).First(c => c.Name == series).i;

    private static Scene Load(string folder, string name, string integrator, double? dt) =>
        SceneLoader.Load(Path.Combine(folder, name), new SceneOverrides(ModelRegistry.Standard.Name, integrator, dt));

    private static Simulation Run(string folder, string name, string integrator, double? dt, out Scene scene)
    {
        scene = Load(folder, name, integrator, dt);
        var sim = SimulationFactory.Create(scene);
        if (scene.Shot is { } shot)
        {
            sim.Strike(shot, scene.CueBall);
        }
        sim.AdvanceTo(60);
        return sim;
    }

    private static List<SimEvent> Events(Simulation sim, EventKind kind) => [.. sim.Events.AsSpan().ToArray().Where(e => e.Kind == kind)];

    private static double Time(List<SimEvent> events, int k) => k < events.Count ? events[k].Time : double.NaN;

    private static double Speed(List<SimEvent> events, int k) => k < events.Count ? events[k].Speed : double.NaN;

    // Steps the shot to each landing in turn and compares the energy a nanosecond either side.
    private static double LargestRiseAcrossLandings(Scene scene)
    {
        var first = SimulationFactory.Create(scene);
        if (scene.Shot is { } shot)
        {
            first.Strike(shot, scene.CueBall);
        }
        first.AdvanceTo(60);
        var times = first.Events.AsSpan().ToArray().Where(e => e.Kind == EventKind.BallTable && e.Time > 0).Select(e => e.Time).Distinct().ToList();
        double rise = 0;
        foreach (double t in times)
        {
            var sim = SimulationFactory.Create(scene);
            if (scene.Shot is { } s)
            {
                sim.Strike(s, scene.CueBall);
            }
            const double Eps = 1e-9;
            sim.AdvanceTo(t - Eps);
            double before = Energy(sim, scene);
            sim.AdvanceTo(t + Eps);
            rise = Math.Max(rise, Energy(sim, scene) - before);
        }
        return rise;
    }

    private static double Energy(Simulation sim, Scene scene)
    {
        var p = scene.Physics.Params;
        double r = scene.BallRadius, inertia = 0.4 * p.M * r * r, e = 0;
        foreach (var b in sim.Balls)
        {
            if (b.IsOutOfPlay)
            {
                continue;
            }
            e += (0.5 * p.M * b.Velocity.LengthSquared) + (0.5 * inertia * b.Spin.LengthSquared) + (p.M * p.G * (b.Position.Z - r));
        }
        return e;
    }
}
