using System.Globalization;
using System.Text;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using SkiaSharp;

namespace Billiards.App.Reports;

/// <summary>How the ball spins as it reaches the cushion, in the cushion page.</summary>
/// <param name="Name">As the page names it.</param>
/// <param name="Follow">Topspin as a fraction of natural roll.</param>
/// <param name="Side">Side spin w_z in units of speed / R; positive is running english (it turns the ball along its run on the rail).</param>
public sealed record CushionSpin(string Name, double Follow, double Side);

/// <summary>One rebound: the incoming angle from the cushion's normal (deg), the rebound's angle from the normal (deg, on the side of the run) and its speed (m/s).</summary>
public readonly record struct Rebound(double IncomingDeg, double ReboundDeg, double Speed);

/// <summary>
/// The cushion page of the accuracy report: rebound angle and speed against the incoming angle
/// (0-80 deg from the normal) at 1 and 3 m/s, for a stun ball and for a rolling ball with running
/// and with reverse english, with every cushion model of the registry side by side, on the
/// default table (cushion nose at 0.64 of the ball's diameter) and parameters.
/// </summary>
public static class CushionReport
{
    /// <summary>The incoming speeds (m/s).</summary>
    public static IReadOnlyList<double> Speeds { get; } = [1, 3];

    /// <summary>The spins.</summary>
    public static IReadOnlyList<CushionSpin> Spins { get; } =
    [
        new("no spin", 0, 0),
        new("low slip", -0.28, 0),
        new("running english", 1, 1),
        new("reverse english", 1, -1),
    ];

    /// <summary>The incoming angles from the normal (deg): 0 to 80 by 2.</summary>
    public static IReadOnlyList<double> Angles { get; } = [.. Enumerable.Range(0, 41).Select(i => 2.0 * i)];

    /// <summary>The file names of the page and its plots.</summary>
    public static IReadOnlyList<string> FileNames { get; } = ["cushions.md", .. Speeds.Select(PlotName)];

    /// <summary>The plot of one speed.</summary>
    public static string PlotName(double speed) => string.Create(CultureInfo.InvariantCulture, $"cushions-{speed:0}ms.png");

    /// <summary>The rebound of a ball reaching the foot cushion at <paramref name="speed"/> (m/s), <paramref name="incomingDeg"/> off its normal, with the spin.</summary>
    public static Rebound Resolve(IBallCushionModel model, double speed, double incomingDeg, CushionSpin spin, PhysicsParams p, double height)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(spin);
        ArgumentNullException.ThrowIfNull(p);
        double a = incomingDeg * Math.PI / 180;
        var v = new Vec3(speed * Math.Cos(a), speed * Math.Sin(a), 0);
        // Running english turns the contact with the run along the rail (w_z < 0 for a run towards +y).
        var w = Vec3.Cross(Vec3.UnitZ, v) / p.R * spin.Follow + new Vec3(0, 0, -spin.Side * speed / p.R);
        var ball = new BallState { Position = new Vec3(0, 0, p.R), Velocity = v, Spin = w };
        model.Resolve(ref ball, new Vec3(-1, 0, 0), height, p);
        double angle = Math.Atan2(ball.Velocity.Y, -ball.Velocity.X) * 180 / Math.PI;
        return new Rebound(incomingDeg, angle, ball.Velocity.LengthXY);
    }

    /// <summary>Every curve: per model, speed and spin, the rebounds over <see cref="Angles"/>.</summary>
    public static Dictionary<(string Model, double Speed, string Spin), Rebound[]> Curves(PhysicsParams p, double height) =>
        (from model in ModelRegistry.BallCushionModels
         from speed in Speeds
         from spin in Spins
         select (model, speed, spin)).ToDictionary(
            c => (c.model.Name, c.speed, c.spin.Name),
            c => Angles.Select(angle => Resolve(c.model, c.speed, angle, c.spin, p, height)).ToArray());

    /// <summary>The page: what is drawn, the plots and a table of a few angles.</summary>
    public static string ToMarkdown(Dictionary<(string Model, double Speed, string Spin), Rebound[]> curves, PhysicsParams p, double height)
    {
        ArgumentNullException.ThrowIfNull(curves);
        ArgumentNullException.ThrowIfNull(p);
        var inv = CultureInfo.InvariantCulture;
        var sb = new StringBuilder("# Cushion models side by side\n\n");
        sb.Append(inv, $"A ball meets a straight cushion at 1 and 3 m/s, 0 to 80 degrees off the cushion's normal (0 = head-on), as a stun ball (no spin) and as a rolling ball with running or reverse english (side spin of speed / R; running english turns the ball along its run on the rail). Each cushion model of the registry (`physics.models.ball_cushion`) resolves the impact with the default parameters (e_c = {p.EC}, f_c = {p.FC}, mu_s = {p.MuS}, omega_ratio = {p.OmegaRatio}) and the cushion nose at {height * 1000:0.###} mm (0.64 of the ball's diameter). The rebound angle is measured from the normal, on the side of the ball's run (negative: the ball comes back across the normal). Mathavan, Jackson and Parkin state their model for normal speeds up to 2.5 m/s: at 3 m/s its steep rebounds lie beyond that. Made by `billiards report cushions` (and by `report accuracy`).\n\n");
        foreach (double speed in Speeds)
        {
            sb.Append(inv, $"![Rebound angle and speed at {speed:0} m/s]({PlotName(speed)})\n\n");
        }
        sb.Append(StrongeAgainstHan(curves));
        sb.Append("| speed | spin | incoming (deg) |");
        foreach (var m in ModelRegistry.BallCushionNames)
        {
            sb.Append(inv, $" {m}: angle, speed |");
        }
        sb.Append("\n|---|---|---|");
        sb.Append(string.Concat(ModelRegistry.BallCushionNames.Select(_ => "---|")));
        sb.Append('\n');
        foreach (double speed in Speeds)
        {
            foreach (var spin in Spins)
            {
                foreach (int i in new[] { 0, 15, 30, 40 })
                {
                    sb.Append(inv, $"| {speed:0} m/s | {spin.Name} | {Angles[i]:0} |");
                    foreach (var m in ModelRegistry.BallCushionNames)
                    {
                        var r = curves[(m, speed, spin.Name)][i];
                        sb.Append(inv, $" {r.ReboundDeg:0.0}, {r.Speed:0.000} |");
                    }
                    sb.Append('\n');
                }
            }
        }
        return sb.ToString();
    }

    /// <summary>
    /// Where stronge-compliant and han-2005 differ: the largest differences in rebound angle and
    /// speed per speed and spin, with where along the incoming angles they lie.
    /// </summary>
    public static string StrongeAgainstHan(Dictionary<(string Model, double Speed, string Spin), Rebound[]> curves)
    {
        ArgumentNullException.ThrowIfNull(curves);
        var inv = CultureInfo.InvariantCulture;
        var sb = new StringBuilder("## Where stronge-compliant differs from han-2005\n\n");
        sb.Append("Both take Coulomb friction at the cushion with the same e_c and f_c; a ball whose contact slips throughout (gross slip: a rolling ball, running or reverse english) takes the same branch in both, and they agree. They part where the contact's slip is small enough to stop during the impact: the stun ball (no spin: the contact above the centre slips only at v sin theta_a) and the low-slip ball (a draw of sin theta_a = 0.28 of natural roll, which leaves the contact's vertical slip at zero). Han's model then sticks rigidly; Stronge's compliant contact stores tangential energy and gives part of it back (omega_ratio), so the rebound angle and speed differ.\n\n");
        sb.Append("| speed | spin | largest angle difference (deg, at incoming) | largest speed difference (m/s, at incoming) |\n|---|---|---|---|\n");
        foreach (double speed in Speeds)
        {
            foreach (var spin in Spins)
            {
                var han = curves[("han-2005", speed, spin.Name)];
                var stronge = curves[("stronge-compliant", speed, spin.Name)];
                int ia = 0, iv = 0;
                for (int i = 0; i < han.Length; i++)
                {
                    ia = Math.Abs(han[i].ReboundDeg - stronge[i].ReboundDeg) > Math.Abs(han[ia].ReboundDeg - stronge[ia].ReboundDeg) ? i : ia;
                    iv = Math.Abs(han[i].Speed - stronge[i].Speed) > Math.Abs(han[iv].Speed - stronge[iv].Speed) ? i : iv;
                }
                sb.Append(inv, $"| {speed:0} m/s | {spin.Name} | {Math.Abs(han[ia].ReboundDeg - stronge[ia].ReboundDeg):0.00} (at {Angles[ia]:0}) | {Math.Abs(han[iv].Speed - stronge[iv].Speed):0.000} (at {Angles[iv]:0}) |\n");
            }
        }
        sb.Append('\n');
        return sb.ToString();
    }

    private static readonly SKColor[] Colours = [new(0x1f, 0x77, 0xb4), new(0xd6, 0x27, 0x28), new(0x2c, 0xa0, 0x2c), new(0x94, 0x67, 0xbd)];

    /// <summary>
    /// The plot of one speed as PNG: a row of rebound angles and a row of rebound speeds against
    /// the incoming angle, a column per spin, a line per model.
    /// </summary>
    public static byte[] ToPng(Dictionary<(string Model, double Speed, string Spin), Rebound[]> curves, double speed)
    {
        ArgumentNullException.ThrowIfNull(curves);
        const int PanelW = 360, PanelH = 250, Left = 70, Top = 60, GapX = 40, GapY = 60, Bottom = 60, LegendH = 30;
        int width = Left + Spins.Count * (PanelW + GapX), height = Top + 2 * (PanelH + GapY) + Bottom + LegendH;
        using var bitmap = new SKBitmap(width, height);
        using (var canvas = new SKCanvas(bitmap))
        {
            canvas.Clear(SKColors.White);
            using var font = new SKFont(SKTypeface.Default, 14);
            using var small = new SKFont(SKTypeface.Default, 12);
            using var text = new SKPaint { Color = SKColors.Black, IsAntialias = true };
            using var grid = new SKPaint { Color = new SKColor(0xdd, 0xdd, 0xdd), StrokeWidth = 1 };
            using var frame = new SKPaint { Color = SKColors.Black, Style = SKPaintStyle.Stroke, StrokeWidth = 1 };
            var inv = CultureInfo.InvariantCulture;
            canvas.DrawText(string.Create(inv, $"Cushion rebounds at {speed:0} m/s: angle and speed against the incoming angle"), width / 2f, 28, SKTextAlign.Center, new SKFont(SKTypeface.Default, 18), text);
            var all = curves.Where(c => c.Key.Speed == speed).SelectMany(c => c.Value).ToList();
            // Angles on a 15-degree grid from the lowest rebound (reverse english can bring the ball
            // back across the normal) to 90; speeds on a grid of a tenth of the incoming speed.
            double angleMin = Math.Min(0, Math.Floor(all.Min(r => r.ReboundDeg) / 15) * 15);
            double tenth = speed / 10;
            double speedMin = Math.Floor(all.Min(r => r.Speed) / tenth) * tenth, speedMax = Math.Ceiling(all.Max(r => r.Speed) / tenth) * tenth;
            for (int row = 0; row < 2; row++)
            {
                for (int col = 0; col < Spins.Count; col++)
                {
                    float x0 = Left + col * (PanelW + GapX), y0 = Top + row * (PanelH + GapY);
                    double yMin = row == 0 ? angleMin : speedMin, yMax = row == 0 ? 90 : speedMax, yStep = row == 0 ? 15 : tenth;
                    float X(double deg) => x0 + (float)(deg / 80 * PanelW);
                    float Y(double value) => y0 + PanelH - (float)((value - yMin) / (yMax - yMin) * PanelH);
                    for (double g = 0; g <= 80 + 1e-9; g += 10)
                    {
                        canvas.DrawLine(X(g), y0, X(g), y0 + PanelH, grid);
                        canvas.DrawText(string.Create(inv, $"{g:0}"), X(g), y0 + PanelH + 16, SKTextAlign.Center, small, text);
                    }
                    for (double g = yMin; g <= yMax + 1e-9; g += yStep)
                    {
                        canvas.DrawLine(x0, Y(g), x0 + PanelW, Y(g), grid);
                        canvas.DrawText(row == 0 ? string.Create(inv, $"{g:0}") : string.Create(inv, $"{g:0.0#}"), x0 - 6, Y(g) + 4, SKTextAlign.Right, small, text);
                    }
                    canvas.DrawRect(x0, y0, PanelW, PanelH, frame);
                    string title = row == 0 ? $"{Spins[col].Name}: rebound angle (deg)" : $"{Spins[col].Name}: rebound speed (m/s)";
                    canvas.DrawText(title, x0 + PanelW / 2f, y0 - 8, SKTextAlign.Center, font, text);
                    canvas.DrawText("incoming angle from the normal (deg)", x0 + PanelW / 2f, y0 + PanelH + 34, SKTextAlign.Center, small, text);
                    int k = 0;
                    foreach (var model in ModelRegistry.BallCushionNames)
                    {
                        // Where models agree their lines coincide: each is drawn thinner than the one before.
                        using var line = new SKPaint { Color = Colours[k % Colours.Length], StrokeWidth = 5f - 1.5f * k, Style = SKPaintStyle.Stroke, IsAntialias = true };
                        using var path = new SKPath();
                        var points = curves[(model, speed, Spins[col].Name)];
                        for (int i = 0; i < points.Length; i++)
                        {
                            var p = new SKPoint(X(points[i].IncomingDeg), Y(row == 0 ? points[i].ReboundDeg : points[i].Speed));
                            if (i == 0)
                            {
                                path.MoveTo(p);
                            }
                            else
                            {
                                path.LineTo(p);
                            }
                        }
                        canvas.Save();
                        canvas.ClipRect(new SKRect(x0, y0, x0 + PanelW, y0 + PanelH));
                        canvas.DrawPath(path, line);
                        canvas.Restore();
                        k++;
                    }
                }
            }
            float ly = height - LegendH;
            float lx = Left;
            int m = 0;
            foreach (var model in ModelRegistry.BallCushionNames)
            {
                using var line = new SKPaint { Color = Colours[m % Colours.Length], StrokeWidth = 5f - 1.5f * m };
                canvas.DrawLine(lx, ly, lx + 30, ly, line);
                canvas.DrawText(model, lx + 38, ly + 5, SKTextAlign.Left, font, text);
                lx += 220;
                m++;
            }
        }
        using var image = SKImage.FromBitmap(bitmap);
        using var data = image.Encode(SKEncodedImageFormat.Png, 100);
        return data.ToArray();
    }

    /// <summary>Every file of the page, by name (<see cref="FileNames"/>).</summary>
    public static IReadOnlyList<(string Name, byte[] Bytes)> Files()
    {
        var p = PhysicsParams.Default;
        double height = Core.Table.TableSpec.FromPreset("pool-9ft").CushionHeight;
        var curves = Curves(p, height);
        return [(FileNames[0], Encoding.UTF8.GetBytes(ToMarkdown(curves, p, height))), .. Speeds.Select(s => (PlotName(s), ToPng(curves, s)))];
    }
}
