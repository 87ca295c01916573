using System.Diagnostics;
using System.Globalization;
using System.Text;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Reports;

/// <summary>One measured configuration: a scene run by one model and integrator at one step.</summary>
/// <param name="Scene">Scene file name.</param>
/// <param name="Model">The model (<see cref="ModelRegistry"/>).</param>
/// <param name="Integrator">One of the model's integrators.</param>
/// <param name="Dt">Fixed step (s); the event solver's row carries the scene's dt but does not use it.</param>
/// <param name="MaxError">Largest final-position distance of any ball from the event solver's (m).</param>
/// <param name="MedianMicroseconds">Median wall time of one shot, strike to rest (µs).</param>
public sealed record AccuracyRow(string Scene, PhysicsModel Model, IIntegrator Integrator, double Dt, double MaxError, double MedianMicroseconds)
{
    /// <summary>The series this row belongs to in the plot: "exact", "euler", "event" or "thesis".</summary>
    public string Series => SeriesOf(Model, Integrator);

    /// <summary>A model's integrator is its series; a model with one integrator is a series of its own (the thesis model's error is model error).</summary>
    public static string SeriesOf(PhysicsModel model, IIntegrator integrator)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(integrator);
        return IsModelSeries(model) ? model.Name : integrator.Name;
    }

    /// <summary>Where the series stands in tables and plots: exact contacts, approximations, models of their own, the reference last.</summary>
    public int Rank => Integrator.IsReference ? 3 : IsModelSeries(Model) ? 2 : Integrator.Order > 0 ? 1 : 0;

    private static bool IsModelSeries(PhysicsModel model) => model.Integrators.Count == 1;
}

/// <summary>
/// The error-against-run-time report: every scene of the suite is run by each integrator at
/// each step, and its final positions are compared with the event-based reference solver's.
/// The thesis model appears as a row of model error (it is a different model, not an integrator
/// of the standard one).
/// </summary>
public static class AccuracyReport
{
    /// <summary>The steps measured (s): 1/30 .. 1/8000.</summary>
    public static IReadOnlyList<double> Steps { get; } = [1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 250, 1.0 / 500, 1.0 / 1000, 1.0 / 2000, 1.0 / 4000, 1.0 / 8000];

    /// <summary>Errors below this are drawn at it: a log axis has no zero.</summary>
    public const double PlotFloor = 1e-16;

    /// <summary>Measures every scene; reports progress one line per configuration.</summary>
    /// <param name="scenePaths">The suite.</param>
    /// <param name="progress">Where progress lines go (stderr).</param>
    /// <param name="minRepeats">Timed repetitions at least (after one warm-up run).</param>
    /// <param name="minTotalMilliseconds">Keep repeating until this much time was measured (or 50 repeats).</param>
    public static List<AccuracyRow> Measure(IReadOnlyList<string> scenePaths, TextWriter progress, int minRepeats = 5, double minTotalMilliseconds = 20)
    {
        var configs = Configurations();
        int total = scenePaths.Count * (configs.Count + 1), done = 0;
        var rows = new List<AccuracyRow>();
        foreach (string path in scenePaths)
        {
            string name = Path.GetFileNameWithoutExtension(path);
            var reference = SceneLoader.Load(path, new SceneOverrides(ModelRegistry.Standard.Name, ModelRegistry.Event.Name));
            var (truth, eventMicros) = TimeShot(reference, minRepeats, minTotalMilliseconds);
            rows.Add(new AccuracyRow(name, ModelRegistry.Standard, ModelRegistry.Event, reference.Physics.Dt, 0, eventMicros));
            Report(progress, ++done, total, name, ModelRegistry.Event.Name, null, 0, eventMicros);
            foreach (var (model, integrator, dt) in configs)
            {
                var scene = SceneLoader.Load(path, new SceneOverrides(model.Name, integrator.Name, dt));
                var (final, micros) = TimeShot(scene, minRepeats, minTotalMilliseconds);
                double error = MaxDistance(final, truth);
                rows.Add(new AccuracyRow(name, model, integrator, dt, error, micros));
                Report(progress, ++done, total, name, AccuracyRow.SeriesOf(model, integrator), dt, error, micros);
            }
        }
        return rows;
    }

    /// <summary>
    /// Checks every scene of the suite before anything is measured: as written, in every
    /// configuration the report runs, and that it has a shot to measure.
    /// </summary>
    /// <exception cref="SceneException">For the first scene that cannot be measured.</exception>
    public static void Validate(IReadOnlyList<string> scenePaths)
    {
        foreach (string path in scenePaths)
        {
            var scene = SceneLoader.Load(path);
            if (scene.Shot is null)
            {
                throw new SceneException(path, "$", "the accuracy report measures a shot, and the scene has no \"shot\"");
            }
            SceneLoader.Load(path, new SceneOverrides(ModelRegistry.Standard.Name, ModelRegistry.Event.Name));
            foreach (var (model, integrator, dt) in Configurations())
            {
                SceneLoader.Load(path, new SceneOverrides(model.Name, integrator.Name, dt));
            }
        }
    }

    // Every model's every integrator at every step, but the reference, which is run once per scene.
    private static List<(PhysicsModel Model, IIntegrator Integrator, double Dt)> Configurations()
    {
        var configs = new List<(PhysicsModel Model, IIntegrator Integrator, double Dt)>();
        foreach (double dt in Steps)
        {
            foreach (var model in ModelRegistry.All)
            {
                configs.AddRange(model.Integrators.Where(i => !i.IsReference).Select(i => (model, i, dt)));
            }
        }
        return configs;
    }

    private static void Report(TextWriter progress, int done, int total, string scene, string series, double? dt, double error, double micros) =>
        progress.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"[{done,4}/{total}] {scene,-20} {series,-7} {(dt is { } d ? $"dt=1/{Math.Round(1 / d)}" : ""),-11} error {error,10:0.00e+00} m  {micros,10:0.0} us"));

    /// <summary>Runs a shot from strike to rest once to warm up, then repeatedly; returns the final positions and the median time (µs).</summary>
    public static (Billiards.Core.Mathematics.Vec3[] Final, double MedianMicroseconds) TimeShot(Scene scene, int minRepeats, double minTotalMilliseconds)
    {
        var final = RunOnce(scene, out _);
        var times = new List<double>();
        double spent = 0;
        while (times.Count < minRepeats || (spent < minTotalMilliseconds && times.Count < 50))
        {
            RunOnce(scene, out double micros);
            times.Add(micros);
            spent += micros / 1000;
        }
        return (final, Median(times));
    }

    private static Billiards.Core.Mathematics.Vec3[] RunOnce(Scene scene, out double micros)
    {
        var sim = SimulationFactory.Create(scene);
        long start = Stopwatch.GetTimestamp();
        if (scene.Shot is { } shot)
        {
            sim.Strike(shot);
        }
        sim.AdvanceTo(600);
        micros = Stopwatch.GetElapsedTime(start).TotalMicroseconds;
        var balls = sim.Balls;
        var positions = new Billiards.Core.Mathematics.Vec3[balls.Length];
        for (int i = 0; i < balls.Length; i++)
        {
            positions[i] = balls[i].Position;
        }
        return positions;
    }

    /// <summary>The largest distance between corresponding positions (m).</summary>
    public static double MaxDistance(IReadOnlyList<Billiards.Core.Mathematics.Vec3> a, IReadOnlyList<Billiards.Core.Mathematics.Vec3> b)
    {
        double max = 0;
        for (int i = 0; i < a.Count; i++)
        {
            max = Math.Max(max, (a[i] - b[i]).LengthXY);
        }
        return max;
    }

    /// <summary>The median of a list; NaN for an empty one.</summary>
    public static double Median(IReadOnlyList<double> values)
    {
        if (values.Count == 0)
        {
            return double.NaN;
        }
        var sorted = values.Order().ToArray();
        int n = sorted.Length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    /// <summary>
    /// The observed order of convergence: the least-squares slope of log(error) against log(dt).
    /// Points with an error at or below <see cref="PlotFloor"/> carry no information and are left out.
    /// </summary>
    public static double ObservedOrder(IEnumerable<(double Dt, double Error)> points)
    {
        var p = points.Where(x => x.Error > PlotFloor).Select(x => (X: Math.Log(x.Dt), Y: Math.Log(x.Error))).ToList();
        if (p.Count < 2)
        {
            return double.NaN;
        }
        double mx = p.Average(q => q.X), my = p.Average(q => q.Y);
        double sxy = p.Sum(q => (q.X - mx) * (q.Y - my)), sxx = p.Sum(q => (q.X - mx) * (q.X - mx));
        return sxy / sxx;
    }

    /// <summary>One point of a series: the worst and the median error over the suite, and the mean per-shot time, at one step.</summary>
    public sealed record SeriesPoint(double Dt, double MaxError, double MedianError, double MeanMicroseconds);

    /// <summary>Aggregates rows into the plot's series, ordered by step from coarse to fine.</summary>
    public static Dictionary<string, List<SeriesPoint>> Series(IEnumerable<AccuracyRow> rows) =>
        rows.GroupBy(r => r.Series).ToDictionary(
            g => g.Key,
            g => g.GroupBy(r => r.Integrator.IsReference ? 0 : r.Dt)
                  .Select(s => new SeriesPoint(s.Key, s.Max(r => r.MaxError), Median([.. s.Select(r => r.MaxError)]), s.Average(r => r.MedianMicroseconds)))
                  .OrderByDescending(s => s.Dt).ToList());

    /// <summary>The rows as CSV.</summary>
    public static string ToCsv(IEnumerable<AccuracyRow> rows)
    {
        var sb = new StringBuilder("scene,model,integrator,dt_s,steps_per_s,max_error_m,median_us\n");
        foreach (var r in rows)
        {
            sb.Append(CultureInfo.InvariantCulture, $"{r.Scene},{r.Model.Name},{r.Integrator.Name},{r.Dt:R},{Math.Round(1 / r.Dt)},{r.MaxError:R},{r.MedianMicroseconds:0.###}\n");
        }
        return sb.ToString();
    }

    /// <summary>The Markdown summary: the table per series and step, euler's observed order, event's cost.</summary>
    public static string ToMarkdown(IReadOnlyList<AccuracyRow> rows, int sceneCount)
    {
        var series = Series(rows);
        var sb = new StringBuilder();
        var inv = CultureInfo.InvariantCulture;
        sb.Append(inv, $"# Accuracy report: error against run time\n\n");
        sb.Append(inv, $"{sceneCount} scenes of `assets/scenes/accuracy`, each run from the strike to rest. Error: the largest final-position distance of any ball from the event-based reference solver (m), per scene; the table gives the worst and the median scene, the plot the median (a typical shot: the worst is a near-chaotic combination). Time: the median wall time of one shot after warm-up (µs), averaged over the suite. Made by `billiards report accuracy`.\n\n");
        sb.Append("The cushion models side by side (rebound angle and speed against the incoming angle): [cushions.md](cushions.md). The engine against measured data (physics-standard-model.md, \"Against the real table\"): [reality.md](reality.md).\n\n");
        sb.Append("| series | dt (s) | worst error (m) | median error (m) | mean time per shot (µs) |\n|---|---|---|---|---|\n");
        var reference = Pick(rows, r => r.Integrator.IsReference);
        foreach (var name in Ordered(rows))
        {
            foreach (var p in series[name])
            {
                string dt = name == reference ? "events" : $"1/{Math.Round(1 / p.Dt)}";
                sb.Append(inv, $"| {name} | {dt} | {p.MaxError:0.00e+00} | {p.MedianError:0.00e+00} | {p.MeanMicroseconds:0.0} |\n");
            }
        }
        if (Pick(rows, r => r.Integrator.Order > 0) is { } approximate)
        {
            var euler = series[approximate];
            double all = ObservedOrder(euler.Select(p => (p.Dt, p.MaxError)));
            var perScene = rows.Where(r => r.Series == approximate).GroupBy(r => r.Scene)
                .Select(g => (Scene: g.Key, All: ObservedOrder(g.Select(r => (r.Dt, r.MaxError))),
                              Fine: ObservedOrder(g.Where(r => r.Dt <= 1.0 / 250 + 1e-15).Select(r => (r.Dt, r.MaxError)))))
                .OrderBy(x => x.Scene, StringComparer.Ordinal).ToList();
            double medianAll = Median(perScene.Select(x => x.All).Where(double.IsFinite).ToList());
            double medianFine = Median(perScene.Select(x => x.Fine).Where(double.IsFinite).ToList());
            sb.Append(inv, $"\n**Observed order of `{approximate}`:** {medianAll:0.00} (median over the scenes of the least-squares slope of log error against log dt; {medianFine:0.00} over dt <= 1/250); 1 is first order. Fitted to the suite's worst error instead: {all:0.00}.\n\n");
            sb.Append(inv, $"| scene | order of `{approximate}`, every dt | order, dt <= 1/250 |\n|---|---|---|\n");
            foreach (var (scene, o, fine) in perScene)
            {
                sb.Append(inv, $"| {scene} | {o:0.00} | {fine:0.00} |\n");
            }
        }
        string? exactName = Pick(rows, r => r.Rank == 0 && r.Integrator.ExactContacts);
        if (exactName is not null && reference is not null)
        {
            var exact = series[exactName];
            sb.Append(inv, $"\n**`{exactName}` against `{reference}`:** the largest difference at any step is {exact.Max(p => p.MaxError):0.00e+00} m.\n");
            var ev = series[reference];
            var at250 = exact.MinBy(p => Math.Abs(p.Dt - 1.0 / 250))!;
            sb.Append(inv, $"\n**Cost of `{reference}`:** {ev[0].MeanMicroseconds:0.0} µs per shot, {ev[0].MeanMicroseconds / at250.MeanMicroseconds:0.00} times `{exactName}` at dt = 1/250 ({at250.MeanMicroseconds:0.0} µs).\n");
        }
        foreach (var model in Ordered(rows).Where(n => rows.First(r => r.Series == n).Rank == 2))
        {
            var points = series[model];
            sb.Append(inv, $"\n**`{model}`** is a model of its own, not an integrator of the standard one: its error ({points.Min(p => p.MaxError):0.00} to {points.Max(p => p.MaxError):0.00} m) is model error and does not vanish as dt shrinks.\n");
        }
        return sb.ToString();
    }

    // The series in the order of the table and the plot (by rank, then name).
    private static List<string> Ordered(IEnumerable<AccuracyRow> rows) =>
        [.. rows.GroupBy(r => r.Series).OrderBy(g => g.First().Rank).ThenBy(g => g.Key, StringComparer.Ordinal).Select(g => g.Key)];

    // The first series whose rows fit, or null.
    private static string? Pick(IEnumerable<AccuracyRow> rows, Func<AccuracyRow, bool> fits) => rows.FirstOrDefault(fits)?.Series;

    /// <summary>A log-log work-precision diagram (error against run time), one line per series, as SVG.</summary>
    public static string ToSvg(IReadOnlyList<AccuracyRow> rows)
    {
        var series = Series(rows);
        const double W = 820, H = 520, L = 90, R = 170, T = 40, B = 60;
        var pts = series.Values.SelectMany(s => s).ToList();
        double x0 = Math.Floor(Math.Log10(pts.Min(p => p.MeanMicroseconds))), x1 = Math.Ceiling(Math.Log10(pts.Max(p => p.MeanMicroseconds)));
        double y0 = Math.Floor(Math.Log10(pts.Min(p => Math.Max(p.MedianError, PlotFloor)))), y1 = Math.Ceiling(Math.Log10(pts.Max(p => Math.Max(p.MedianError, PlotFloor))));
        if (x1 <= x0) x1 = x0 + 1;
        if (y1 <= y0) y1 = y0 + 1;
        double X(double us) => L + (Math.Log10(us) - x0) / (x1 - x0) * (W - L - R);
        double Y(double err) => H - B - (Math.Log10(Math.Max(err, PlotFloor)) - y0) / (y1 - y0) * (H - T - B);
        var inv = CultureInfo.InvariantCulture;
        var sb = new StringBuilder();
        sb.Append(inv, $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{W}\" height=\"{H}\" viewBox=\"0 0 {W} {H}\" font-family=\"sans-serif\" font-size=\"12\">\n");
        sb.Append(inv, $"<rect width=\"{W}\" height=\"{H}\" fill=\"white\"/>\n");
        sb.Append(inv, $"<text x=\"{W / 2}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">Work-precision: median final-position error against run time per shot</text>\n");
        for (double e = x0; e <= x1; e++)
        {
            sb.Append(inv, $"<line x1=\"{X(Math.Pow(10, e)):0.#}\" y1=\"{T}\" x2=\"{X(Math.Pow(10, e)):0.#}\" y2=\"{H - B}\" stroke=\"#ddd\"/><text x=\"{X(Math.Pow(10, e)):0.#}\" y=\"{H - B + 18}\" text-anchor=\"middle\">1e{e}</text>\n");
        }
        for (double e = y0; e <= y1; e++)
        {
            sb.Append(inv, $"<line x1=\"{L}\" y1=\"{Y(Math.Pow(10, e)):0.#}\" x2=\"{W - R}\" y2=\"{Y(Math.Pow(10, e)):0.#}\" stroke=\"#ddd\"/><text x=\"{L - 6}\" y=\"{Y(Math.Pow(10, e)) + 4:0.#}\" text-anchor=\"end\">1e{e}</text>\n");
        }
        sb.Append(inv, $"<rect x=\"{L}\" y=\"{T}\" width=\"{W - L - R}\" height=\"{H - T - B}\" fill=\"none\" stroke=\"black\"/>\n");
        sb.Append(inv, $"<text x=\"{(L + W - R) / 2}\" y=\"{H - 18}\" text-anchor=\"middle\">mean run time per shot (µs, log)</text>\n");
        sb.Append(inv, $"<text transform=\"translate(22 {(T + H - B) / 2}) rotate(-90)\" text-anchor=\"middle\">median final-position error vs event (m, log)</text>\n");
        string[] colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"];
        int k = 0;
        var reference = Pick(rows, r => r.Integrator.IsReference);
        foreach (var name in Ordered(rows))
        {
            string c = colours[k % colours.Length];
            var s = series[name];
            string poly = string.Join(" ", s.Select(p => string.Create(inv, $"{X(p.MeanMicroseconds):0.#},{Y(p.MedianError):0.#}")));
            sb.Append(inv, $"<polyline points=\"{poly}\" fill=\"none\" stroke=\"{c}\" stroke-width=\"2\"/>\n");
            foreach (var p in s)
            {
                string label = name == reference ? name : $"1/{Math.Round(1 / p.Dt)}";
                sb.Append(inv, $"<circle cx=\"{X(p.MeanMicroseconds):0.#}\" cy=\"{Y(p.MedianError):0.#}\" r=\"4.5\" fill=\"{c}\"><title>{name} {label}: median {p.MedianError:0.00e+00} m, worst {p.MaxError:0.00e+00} m, {p.MeanMicroseconds:0.0} µs</title></circle>\n");
            }
            double ly = T + 20 + 22 * k;
            sb.Append(inv, $"<line x1=\"{W - R + 15}\" y1=\"{ly}\" x2=\"{W - R + 40}\" y2=\"{ly}\" stroke=\"{c}\" stroke-width=\"2\"/><text x=\"{W - R + 46}\" y=\"{ly + 4}\">{name}</text>\n");
            k++;
        }
        sb.Append(inv, $"<text x=\"{W - R + 15}\" y=\"{T + 20 + 22 * k + 10}\" font-size=\"10\">errors below 1e-16</text><text x=\"{W - R + 15}\" y=\"{T + 20 + 22 * k + 23}\" font-size=\"10\">are drawn at 1e-16</text>\n");
        sb.Append("</svg>\n");
        return sb.ToString();
    }
}
