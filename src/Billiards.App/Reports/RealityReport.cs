using System.Globalization;
using System.Text;
using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
using SkiaSharp;

namespace Billiards.App.Reports;

/// <summary>One measured case against the engine: what was measured, its band, the engine's value and the verdict.</summary>
/// <param name="Series">The series' id (assets/reality/measurements.json).</param>
/// <param name="Case">The case, as the page names it.</param>
/// <param name="X">Its abscissa (speed, angle, offset; NaN for a single value).</param>
/// <param name="Measured">The measured value.</param>
/// <param name="Low">The band's low end.</param>
/// <param name="High">The band's high end.</param>
/// <param name="Engine">The engine's value with the default models and the table's parameters.</param>
/// <param name="Beyond">Why the case lies beyond a rigid-ball model (or the model named), or null.</param>
public sealed record RealityCase(string Series, string Case, double X, double Measured, double Low, double High, double Engine, string? Beyond)
{
    /// <summary>The engine's value lies in the band.</summary>
    public bool Within => Engine >= Low && Engine <= High;

    /// <summary>pass, fail, or beyond (a case the page marks as beyond the model, whatever the engine gives).</summary>
    public string Verdict => Beyond is not null ? "beyond" : Within ? "pass" : "fail";
}

/// <summary>
/// The reality page of the accuracy report (<c>report reality</c>, and <c>report accuracy</c>):
/// every measured series of physics-standard-model.md's "Against the real table", from
/// assets/reality/measurements.json, with the engine's curve over it, plotted, with the pass band
/// and the verdict. The engine is the default interaction models with the preset's parameters of
/// the table the series was measured on (<see cref="PhysicsParams.Pool"/>, <see cref="PhysicsParams.Snooker"/>).
/// </summary>
public static class RealityReport
{
    /// <summary>The series plotted, one PNG each.</summary>
    public static IReadOnlyList<string> Plotted { get; } = ["cushion-rebound", "head-on", "throw-speed", "throw-angle", "cut-shots", "squirt"];

    /// <summary>The file names of the page.</summary>
    public static IReadOnlyList<string> FileNames { get; } = ["reality.md", "reality.csv", .. Plotted.Select(p => $"reality-{p}.png")];

    /// <summary>The data file.</summary>
    public static string DataPath => AssetFolder.File(Path.Combine("reality", "measurements.json"));

    private static readonly PhysicsParams Pool = PhysicsParams.Pool;
    private static readonly PhysicsParams Snooker = BallSet.Snooker.DefaultParams;
    private static double SnookerCushion => TableSpec.FromPreset(SnookerTable.Preset).CushionHeight;

    /// <summary>The rebound speed of a rolling ball without sidespin from a perpendicular cushion (m/s).</summary>
    public static double Rebound(double speed, PhysicsParams p, double height)
    {
        ArgumentNullException.ThrowIfNull(p);
        var ball = new BallState { Position = new Vec3(0, 0, p.R), Velocity = new Vec3(speed, 0, 0), Spin = new Vec3(0, speed / p.R, 0) };
        InteractionModels.Default.BallCushion.Resolve(ref ball, new Vec3(-1, 0, 0), height, p);
        return ball.Velocity.LengthXY;
    }

    /// <summary>
    /// Two balls after an impact at <paramref name="cutDeg"/>: the cue ball at <paramref name="speed"/>
    /// along +x, rolling or stunned, the object ball at rest; the default ball-ball model.
    /// </summary>
    public static (BallState Cue, BallState Object) Impact(double speed, double cutDeg, bool rolling, PhysicsParams p)
    {
        ArgumentNullException.ThrowIfNull(p);
        double c = cutDeg * Math.PI / 180;
        var cue = new BallState { Position = new Vec3(0, 0, p.R), Velocity = new Vec3(speed, 0, 0), Spin = rolling ? new Vec3(0, speed / p.R, 0) : Vec3.Zero };
        var ob = new BallState { Position = new Vec3(2 * p.R * Math.Cos(c), -2 * p.R * Math.Sin(c), p.R) };
        InteractionModels.Default.BallBall.Resolve(ref cue, ref ob, p);
        return (cue, ob);
    }

    /// <summary>A ball's velocity once it rolls (the slip law v - 2/7 u, physics-standard-model.md).</summary>
    public static Vec3 PostSlip(in BallState b, double r)
    {
        var u = b.Velocity.XY + (Vec3.Cross(Vec3.UnitZ, b.Spin) * r).XY;
        return b.Velocity.XY - (u * (2.0 / 7.0));
    }

    /// <summary>The stun throw (deg) at a cut, for a cue ball speed (m/s).</summary>
    public static double Throw(double cueSpeed, double cutDeg, PhysicsParams p)
    {
        var (_, ob) = Impact(cueSpeed, cutDeg, rolling: false, p);
        double direction = Math.Atan2(ob.Velocity.Y, ob.Velocity.X) * 180 / Math.PI;
        return direction + cutDeg; // the line of centres is at -cut; throw turns the ball towards the cue ball's side
    }

    /// <summary>The rigid-ball gearing limit on stun throw (deg): atan(tan(cut) / (3.5 (1 + e_b))).</summary>
    public static double GearingLimit(double cutDeg, double eb) => Math.Atan(Math.Tan(cutDeg * Math.PI / 180) / (3.5 * (1 + eb))) * 180 / Math.PI;

    /// <summary>Every case of every series, with pool's and snooker's parameters (the defaults unless given).</summary>
    public static List<RealityCase> Measure(JsonDocument data, PhysicsParams? pool = null, PhysicsParams? snooker = null)
    {
        ArgumentNullException.ThrowIfNull(data);
        pool ??= Pool;
        snooker ??= Snooker;
        var cases = new List<RealityCase>();
        foreach (var s in data.RootElement.GetProperty("series").EnumerateArray())
        {
            string id = s.GetProperty("id").GetString()!;
            switch (id)
            {
                case "rolling-deceleration" or "sliding-deceleration":
                {
                    var range = s.GetProperty("range");
                    double lo = range[0].GetDouble(), hi = range[1].GetDouble();
                    double engine = (id[0] == 'r' ? snooker.MuR : snooker.MuS) * snooker.G;
                    cases.Add(new(id, "snooker cloth", double.NaN, (lo + hi) / 2, lo, hi, engine, null));
                    break;
                }
                case "cushion-rebound":
                {
                    var fit = s.GetProperty("fit");
                    double Fit(double x) => (fit[0].GetDouble() * x * x) + (fit[1].GetDouble() * x) + fit[2].GetDouble();
                    var pts = Points(s);
                    double sigma = Std(pts.Select(q => q[1] - Fit(q[0])));
                    double u = s.GetProperty("y_uncertainty").GetDouble();
                    foreach (var q in pts)
                    {
                        double band = u + (2 * sigma);
                        cases.Add(new(id, F($"{q[0]:0.00} m/s"), q[0], q[1], q[1] - band, q[1] + band, Rebound(q[0], snooker, SnookerCushion), null));
                    }
                    break;
                }
                case "head-on":
                {
                    var pts = Points(s);
                    double sigma = Std(pts.Select(q => q[1] / q[0]));
                    double u = s.GetProperty("y_uncertainty").GetDouble();
                    foreach (var q in pts)
                    {
                        double band = u + (2 * sigma * q[0]);
                        var (_, ob) = Impact(q[0], 0, rolling: true, snooker);
                        cases.Add(new(id, F($"{q[0]:0.000} m/s"), q[0], q[1], q[1] - band, q[1] + band, ob.Velocity.LengthXY, null));
                    }
                    break;
                }
                case "throw-speed-30" or "throw-speed-45":
                {
                    double cut = s.GetProperty("cut_deg").GetDouble(), band = s.GetProperty("band_deg").GetDouble();
                    double limit = GearingLimit(cut, pool.EB);
                    foreach (var q in Points(s))
                    {
                        double cueSpeed = 2 * q[0] / ((1 + pool.EB) * Math.Cos(cut * Math.PI / 180));
                        cases.Add(new(id, F($"{cut:0} deg, OB {q[0]:0.00} m/s"), q[0], q[1], q[1] - band, q[1] + band, Throw(cueSpeed, cut, pool),
                            q[1] > limit ? F($"beyond the rigid-ball gearing limit atan(tan {cut:0} / (3.5 (1 + e_b))) = {limit:0.00} deg (the balls would have to turn faster than gears)") : null));
                    }
                    break;
                }
                case "throw-angle":
                {
                    double band = s.GetProperty("band_deg").GetDouble();
                    foreach (var q in Points(s))
                    {
                        double deg = Math.Atan(q[2] / 36) * 180 / Math.PI, limit = GearingLimit(q[1], pool.EB);
                        cases.Add(new(id, F($"{q[1]:0} deg, CB {q[0]:0.000} m/s"), q[1], deg, deg - band, deg + band, Throw(q[0], q[1], pool),
                            deg > limit ? F($"beyond the rigid-ball gearing limit {limit:0.00} deg") : null));
                    }
                    break;
                }
                case "cut-shots":
                {
                    double rel = s.GetProperty("relative_band").GetDouble(), abs = s.GetProperty("absolute_band").GetDouble();
                    var beyond = s.GetProperty("beyond").EnumerateArray().ToDictionary(b => (b.GetProperty("point").GetInt32(), b.GetProperty("column").GetInt32()), b => b.GetProperty("reason").GetString());
                    var pts = Points(s);
                    for (int k = 0; k < pts.Count; k++)
                    {
                        var q = pts[k];
                        var (cue, ob) = Impact(q[0], q[1], rolling: true, snooker);
                        var vc = PostSlip(cue, snooker.R);
                        var vo = PostSlip(ob, snooker.R);
                        double angle = Math.Abs(Math.Atan2(vc.Y, vc.X) * 180 / Math.PI);
                        string name = F($"shot {k + 1} ({q[0]:0.000} m/s, {q[1]:0.00} deg)");
                        double[] engine = [vc.Length, vo.Length, angle];
                        string[] what = ["cue ball speed", "object ball speed", "cue ball angle"];
                        for (int c = 0; c < 3; c++)
                        {
                            double m = q[2 + c], band = (rel * m) + (c < 2 ? abs : 0);
                            cases.Add(new(id, $"{name}: {what[c]}", k + 1, m, m - band, m + band, engine[c], beyond.GetValueOrDefault((k, 2 + c))));
                        }
                    }
                    break;
                }
                case "spin-down":
                    foreach (var q in s.GetProperty("points").EnumerateArray())
                    {
                        string table = q.GetProperty("table").GetString()!;
                        double v = q.GetProperty("value").GetDouble(), band = q.GetProperty("band").GetDouble();
                        cases.Add(new(id, $"{table} cloth (rad/s^2)", double.NaN, v, v - band, v + band, (table == "pool" ? pool : snooker).SpinDeceleration, null));
                    }
                    break;
                case "squirt":
                {
                    double u = s.GetProperty("y_uncertainty").GetDouble();
                    var beyond = s.GetProperty("beyond").EnumerateArray().ToDictionary(b => b.GetProperty("point").GetInt32(), b => b.GetProperty("reason").GetString());
                    var pts = Points(s);
                    for (int k = 0; k < pts.Count; k++)
                    {
                        var q = pts[k];
                        double a = q[0] * 0.0254 / pool.R;
                        double engine = CueStrike.SquirtAngle(a, pool.M / pool.CueEndMass) * 180 / Math.PI;
                        cases.Add(new(id, F($"offset {q[0]:0.00} in ({a:0.00} R)"), q[0], q[1], q[2] - u, q[3] + u, engine, beyond.GetValueOrDefault(k)));
                    }
                    break;
                }
            }
        }
        return cases;
    }

    private static List<double[]> Points(JsonElement s) =>
        [.. s.GetProperty("points").EnumerateArray().Select(p => p.EnumerateArray().Select(x => x.GetDouble()).ToArray())];

    private static double Std(IEnumerable<double> values)
    {
        var v = values.ToList();
        double mean = v.Average();
        return Math.Sqrt(v.Sum(x => (x - mean) * (x - mean)) / Math.Max(1, v.Count - 1));
    }

    private static string F(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);

    /// <summary>The summary table as CSV.</summary>
    public static string ToCsv(IEnumerable<RealityCase> cases)
    {
        var sb = new StringBuilder("series,case,measured,low,high,engine,verdict,beyond\n");
        foreach (var c in cases)
        {
            sb.Append(F($"{c.Series},\"{c.Case}\",{c.Measured:0.####},{c.Low:0.####},{c.High:0.####},{c.Engine:0.####},{c.Verdict},\"{c.Beyond?.Replace("\"", "'", StringComparison.Ordinal)}\"\n"));
        }
        return sb.ToString();
    }

    /// <summary>The page: per series, its sources, plot and cases, and the verdicts.</summary>
    public static string ToMarkdown(JsonDocument data, IReadOnlyList<RealityCase> cases)
    {
        ArgumentNullException.ThrowIfNull(data);
        ArgumentNullException.ThrowIfNull(cases);
        var sources = data.RootElement.GetProperty("sources");
        var sb = new StringBuilder("# Against the real table\n\n");
        sb.Append(F($"Each measured series of physics-standard-model.md's \"Against the real table\" (data: assets/reality/measurements.json, with each point's source, figure or table and, where read off a plot, the reading's uncertainty), against the engine with the default interaction models (`{InteractionModels.Default.BallCushion.Name}`, `{InteractionModels.Default.BallBall.Name}`) and the parameters of the table it was measured on: pool's cloth and balls (`PhysicsParams.Pool`) or snooker's (`PhysicsParams.Snooker`). A case passes when the engine lies in its band; a case marked beyond lies outside what the model can do, for the reason given, and the defaults are not tuned to it. Made by `billiards report reality` (and `report accuracy`).\n\n"));
        int pass = cases.Count(c => c.Verdict == "pass"), fail = cases.Count(c => c.Verdict == "fail"), beyond = cases.Count(c => c.Verdict == "beyond");
        sb.Append(F($"**{pass} pass, {fail} fail, {beyond} beyond the model** of {cases.Count} cases."));
        var before = Measure(data, PhysicsParams.Default, PhysicsParams.Default with { R = Snooker.R, M = Snooker.M, MuSp = 4.0 / 9 * Snooker.R, CueEndMass = Snooker.M / 30 });
        sb.Append(F($" With the defaults before (pooltool's parameters on both tables: e_c 0.85, mu_b 0.05, pool's cloth on snooker) {before.Count(c => c.Verdict == "pass")} pass and {before.Count(c => c.Verdict == "fail")} fail.\n\n"));
        sb.Append("| series | cases | pass | fail | beyond |\n|---|---|---|---|---|\n");
        foreach (var g in cases.GroupBy(c => c.Series))
        {
            sb.Append(F($"| {g.Key} | {g.Count()} | {g.Count(c => c.Verdict == "pass")} | {g.Count(c => c.Verdict == "fail")} | {g.Count(c => c.Verdict == "beyond")} |\n"));
        }
        foreach (var s in data.RootElement.GetProperty("series").EnumerateArray())
        {
            string id = s.GetProperty("id").GetString()!;
            sb.Append(F($"\n## {id}\n\n"));
            string src = s.GetProperty("source").GetString()!;
            sb.Append(F($"Source: {sources.GetProperty(src).GetString()}; {s.GetProperty("where").GetString()}. {(s.GetProperty("read_off_plot").GetBoolean() ? "Read off the plot" + (s.TryGetProperty("y_uncertainty", out var yu) ? F($" (reading uncertainty {yu.GetDouble()} in y") + (s.TryGetProperty("x_uncertainty", out var xu) ? F($", {xu.GetDouble()} in x") : "") + ")" : "") + "." : "Quoted as printed.")}"));
            if (s.TryGetProperty("band_reason", out var br))
            {
                sb.Append(F($" Band: {br.GetString()}."));
            }
            sb.Append("\n\n");
            string? plot = Plotted.FirstOrDefault(p => id.StartsWith(p, StringComparison.Ordinal));
            if (plot is not null && (id != "throw-speed-45"))
            {
                sb.Append(F($"![{id}](reality-{plot}.png)\n\n"));
            }
            sb.Append("| case | measured | band | engine | verdict |\n|---|---|---|---|---|\n");
            foreach (var c in cases.Where(c => c.Series == id))
            {
                sb.Append(F($"| {c.Case} | {c.Measured:0.###} | {c.Low:0.###} to {c.High:0.###} | {c.Engine:0.###} | {c.Verdict}{(c.Beyond is null ? "" : ": " + c.Beyond)} |\n"));
            }
        }
        return sb.ToString();
    }

    private static readonly SKColor Measured = new(0x1f, 0x77, 0xb4), EngineColour = new(0xd6, 0x27, 0x28), BandColour = new(0x1f, 0x77, 0xb4, 0x30), BeyondColour = new(0x88, 0x88, 0x88);

    /// <summary>One plot: measured points with their bands as error bars, the engine's curve (or its values) over them.</summary>
    public static byte[] Plot(string title, string xLabel, string yLabel, IReadOnlyList<RealityCase> points, IReadOnlyList<Func<double, double>> curves, (double Min, double Max)? xRange = null)
    {
        ArgumentNullException.ThrowIfNull(points);
        ArgumentNullException.ThrowIfNull(curves);
        const int W = 760, H = 520, L = 80, T = 50, R = 30, B = 70;
        double x0 = xRange?.Min ?? points.Min(p => p.X), x1 = xRange?.Max ?? points.Max(p => p.X);
        var ys = points.SelectMany(p => new[] { p.Low, p.High, p.Engine }).ToList();
        foreach (var curve in curves)
        {
            ys.AddRange(Enumerable.Range(0, 101).Select(i => curve(x0 + ((x1 - x0) * i / 100))));
        }
        double yStep = NiceStep(ys.Max() - ys.Min()), xStep = NiceStep(x1 - x0);
        double y0 = Math.Floor(ys.Min() / yStep) * yStep, y1 = Math.Ceiling(ys.Max() / yStep) * yStep;
        float X(double x) => L + (float)((x - x0) / (x1 - x0) * (W - L - R));
        float Y(double y) => H - B - (float)((y - y0) / (y1 - y0) * (H - T - B));
        using var bitmap = new SKBitmap(W, H);
        using (var canvas = new SKCanvas(bitmap))
        {
            canvas.Clear(SKColors.White);
            using var font = new SKFont(SKTypeface.Default, 13);
            using var big = new SKFont(SKTypeface.Default, 16);
            using var text = new SKPaint { Color = SKColors.Black, IsAntialias = true };
            using var grid = new SKPaint { Color = new SKColor(0xdd, 0xdd, 0xdd), StrokeWidth = 1 };
            using var frame = new SKPaint { Color = SKColors.Black, Style = SKPaintStyle.Stroke, StrokeWidth = 1 };
            canvas.DrawText(title, W / 2f, 28, SKTextAlign.Center, big, text);
            for (double gx = Math.Ceiling(x0 / xStep) * xStep; gx <= x1 + 1e-9; gx += xStep)
            {
                canvas.DrawLine(X(gx), T, X(gx), H - B, grid);
                canvas.DrawText(F($"{gx:0.##}"), X(gx), H - B + 18, SKTextAlign.Center, font, text);
            }
            for (double gy = y0; gy <= y1 + 1e-9; gy += yStep)
            {
                canvas.DrawLine(L, Y(gy), W - R, Y(gy), grid);
                canvas.DrawText(F($"{gy:0.###}"), L - 6, Y(gy) + 4, SKTextAlign.Right, font, text);
            }
            canvas.DrawRect(L, T, W - L - R, H - T - B, frame);
            canvas.DrawText(xLabel, (L + W - R) / 2f, H - B + 40, SKTextAlign.Center, font, text);
            canvas.Save();
            canvas.RotateDegrees(-90, 18, (T + H - B) / 2f);
            canvas.DrawText(yLabel, 18, (T + H - B) / 2f, SKTextAlign.Center, font, text);
            canvas.Restore();
            using var bar = new SKPaint { Color = Measured, StrokeWidth = 2, IsAntialias = true };
            using var grey = new SKPaint { Color = BeyondColour, StrokeWidth = 2, IsAntialias = true };
            using var band = new SKPaint { Color = BandColour, Style = SKPaintStyle.Fill };
            using var engine = new SKPaint { Color = EngineColour, StrokeWidth = 2.5f, Style = SKPaintStyle.Stroke, IsAntialias = true };
            using var engineDot = new SKPaint { Color = EngineColour, Style = SKPaintStyle.Fill, IsAntialias = true };
            foreach (var p in points)
            {
                var paint = p.Beyond is null ? bar : grey;
                canvas.DrawRect(X(p.X) - 5, Y(p.High), 10, Y(p.Low) - Y(p.High), band);
                canvas.DrawLine(X(p.X), Y(p.Low), X(p.X), Y(p.High), paint);
                canvas.DrawLine(X(p.X) - 5, Y(p.Low), X(p.X) + 5, Y(p.Low), paint);
                canvas.DrawLine(X(p.X) - 5, Y(p.High), X(p.X) + 5, Y(p.High), paint);
                canvas.DrawCircle(X(p.X), Y(p.Measured), 4, paint);
                if (curves.Count == 0)
                {
                    canvas.DrawRect(X(p.X) - 4, Y(p.Engine) - 4, 8, 8, engineDot);
                }
            }
            foreach (var curve in curves)
            {
                using var path = new SKPath();
                for (int i = 0; i <= 200; i++)
                {
                    double x = x0 + ((x1 - x0) * i / 200);
                    var pt = new SKPoint(X(x), Y(curve(x)));
                    if (i == 0)
                    {
                        path.MoveTo(pt);
                    }
                    else
                    {
                        path.LineTo(pt);
                    }
                }
                canvas.Save();
                canvas.ClipRect(new SKRect(L, T, W - R, H - B));
                canvas.DrawPath(path, engine);
                canvas.Restore();
            }
            canvas.DrawCircle(L + 20, T + 18, 4, bar);
            canvas.DrawText("measured, with its band", L + 30, T + 22, SKTextAlign.Left, font, text);
            canvas.DrawCircle(L + 20, T + 36, 4, grey);
            canvas.DrawText("beyond the model (see the page)", L + 30, T + 40, SKTextAlign.Left, font, text);
            canvas.DrawLine(L + 12, T + 54, L + 28, T + 54, engine);
            canvas.DrawText("engine (default models)", L + 30, T + 58, SKTextAlign.Left, font, text);
        }
        using var image = SKImage.FromBitmap(bitmap);
        using var encoded = image.Encode(SKEncodedImageFormat.Png, 100);
        return encoded.ToArray();
    }

    // A grid step of 1, 2 or 5 times a power of ten, about a fifth of the span.
    private static double NiceStep(double span)
    {
        double raw = Math.Max(span, 1e-9) / 5, power = Math.Pow(10, Math.Floor(Math.Log10(raw))), f = raw / power;
        return power * (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10);
    }

    /// <summary>Every file of the page, by name (<see cref="FileNames"/>), and its cases.</summary>
    public static (IReadOnlyList<(string Name, byte[] Bytes)> Files, List<RealityCase> Cases) Files()
    {
        using var data = JsonDocument.Parse(File.ReadAllBytes(DataPath));
        var cases = Measure(data);
        List<RealityCase> Of(string prefix) => [.. cases.Where(c => c.Series.StartsWith(prefix, StringComparison.Ordinal))];
        double e = Pool.EB;
        Func<double, double> ThrowAt(double cut) => u => Throw(2 * u / ((1 + e) * Math.Cos(cut * Math.PI / 180)), cut, Pool);
        var files = new List<(string, byte[])>
        {
            (FileNames[0], Encoding.UTF8.GetBytes(ToMarkdown(data, cases))),
            (FileNames[1], Encoding.UTF8.GetBytes(ToCsv(cases))),
            (FileNames[2], Plot("Rolling ball into a perpendicular cushion (snooker, Mathavan 2009 Fig. 9)", "incident speed (m/s)", "rebound speed (m/s)", Of("cushion-rebound"), [x => Rebound(x, Snooker, SnookerCushion)], (0.2, 3.6))),
            (FileNames[3], Plot("Head-on, rolling cue ball (snooker, Mathavan 2014 Fig. 4)", "cue ball speed (m/s)", "object ball speed (m/s)", Of("head-on"), [x => Impact(x, 0, true, Snooker).Object.Velocity.LengthXY], (0.8, 2.4))),
            (FileNames[4], Plot("Stun throw against the object ball's speed (30 and 45 deg cuts)", "object ball speed (m/s)", "throw (deg)", [.. Of("throw-speed")], [ThrowAt(30), ThrowAt(45)], (0.2, 3.4))),
            (FileNames[5], Plot("Stun throw against the cut (TP B.3, Colenso; engine at 1.111, 2.222, 3.333 m/s)", "cut angle (deg)", "throw (deg)", Of("throw-angle"), [c => Throw(1.111, c, Pool), c => Throw(2.222, c, Pool), c => Throw(3.333, c, Pool)], (5, 60))),
            (FileNames[6], Plot("Cut shots: post-slip speeds and cue ball angle, by shot (engine: squares)", "shot", "speed (m/s) or angle / 40 deg", [.. Of("cut-shots").Select(c => c.Case.EndsWith("angle", StringComparison.Ordinal) ? c with { Measured = c.Measured / 40, Low = c.Low / 40, High = c.High / 40, Engine = c.Engine / 40 } : c)], [], (0.5, 5.5))),
            (FileNames[7], Plot("Squirt against the tip offset (Squirt part II, Players cue)", "tip offset (in)", "squirt (deg)", Of("squirt"), [x => CueStrike.SquirtAngle(x * 0.0254 / Pool.R, Pool.M / Pool.CueEndMass) * 180 / Math.PI], (0.1, 0.6))),
        };
        return (files, cases);
    }
}
