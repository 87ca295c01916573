using System.Globalization;
using System.Text;
using Billiards.Core.Ai;
using Billiards.Core.Scenes;
using SkiaSharp;

namespace Billiards.App.Reports;

/// <summary>
/// <c>report ai SUMMARY.json ... --out DIR</c>: the computer player under execution noise, from the
/// merged summaries of noisy self-play runs (one a noise level, the planner that plays for the
/// noise as player 0 against the noise-blind planner as player 1, <c>--planners noise,blind</c>):
/// a Markdown page with 95 % intervals (<c>ai.md</c>) and the break-and-run rate against the noise
/// (<c>ai-break-and-run.png</c>).
/// </summary>
public static class AiReport
{
    /// <summary>The files the report writes into its folder.</summary>
    public static IReadOnlyList<string> FileNames { get; } = ["ai.md", "ai-break-and-run.png"];

    /// <summary>The normal quantile of a two-sided 95 % interval.</summary>
    public const double Z = 1.959963984540054;

    /// <summary>The Wilson score interval (95 %) of <paramref name="k"/> successes in <paramref name="n"/> trials; (0, 1) without a trial.</summary>
    public static (double Low, double High) Wilson(int k, int n)
    {
        if (n <= 0)
        {
            return (0, 1);
        }
        double p = (double)k / n, z2 = Z * Z;
        double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
        double half = Z / (1 + z2 / n) * Math.Sqrt(p * (1 - p) / n + z2 / (4.0 * n * n));
        return (Math.Max(0, centre - half), Math.Min(1, centre + half));
    }

    /// <summary>
    /// A 95 % interval of balls per visit, <paramref name="balls"/> / <paramref name="visits"/>, with
    /// the balls taken as a Poisson count (the summary keeps no per-visit spread): its standard
    /// error sqrt(balls) / visits.
    /// </summary>
    public static (double Low, double High) PerVisit(int balls, int visits)
    {
        if (visits <= 0)
        {
            return (0, 0);
        }
        double mean = (double)balls / visits, half = Z * Math.Sqrt(balls) / visits;
        return (Math.Max(0, mean - half), mean + half);
    }

    /// <summary>Reads the summaries (<paramref name="files"/>), checks that each is a noisy run of the noise planner against the blind one, and orders them by noise.</summary>
    /// <exception cref="SceneException">A file that is not such a summary, or two of the same noise.</exception>
    public static IReadOnlyList<AiRun> Read(IReadOnlyList<string> files) => Read(files, []);

    /// <summary>
    /// Reads the summaries (<paramref name="files"/>) as <see cref="Read(IReadOnlyList{string})"/>
    /// does, with the racks the noise planner did not break in them (<paramref name="breakFiles"/>):
    /// the shards of a run of the same seed, games and noise with the noise planner on both sides
    /// (<c>--planners noise,noise</c>) over the odd games, whose breaks player 1 made in the run
    /// against the blind planner (shards K/N of one even N, every odd K once: <c>--shard 1/2</c>, or
    /// <c>1/4</c> and <c>3/4</c> side by side). The break-and-run rate then counts every rack of
    /// the run's games that the noise planner broke.
    /// </summary>
    /// <exception cref="SceneException">A file that is not such a summary, or shards that are not the odd games of a run given.</exception>
    public static IReadOnlyList<AiRun> Read(IReadOnlyList<string> files, IReadOnlyList<string> breakFiles)
    {
        ArgumentNullException.ThrowIfNull(files);
        ArgumentNullException.ThrowIfNull(breakFiles);
        var runs = new List<SelfPlaySummary>();
        foreach (string file in files)
        {
            var s = Load(file);
            if (s.Planners != new Core.Rules.PerPlayer<SearchError>(SearchError.Noise, SearchError.Exact))
            {
                throw new SceneException(file, "$.planners", "expected noise,blind (the planner for the noise as player 0 against the blind one)");
            }
            if (!s.Shard.IsWhole)
            {
                throw new SceneException(file, "$.shard", "one shard of a run (merge the shards first: selfplay --merge)");
            }
            if (runs.FirstOrDefault(r => r.Noise == s.Noise) is not null)
            {
                throw new SceneException(file, "$.noise", $"{s.Noise} is given twice");
            }
            runs.Add(s);
        }
        var others = runs.ToDictionary(r => r.Noise!, _ => new List<(string File, SelfPlaySummary Summary)>());
        foreach (string file in breakFiles)
        {
            var s = Load(file);
            if (s.Planners != new Core.Rules.PerPlayer<SearchError>(SearchError.Noise, SearchError.Noise))
            {
                throw new SceneException(file, "$.planners", "expected noise,noise (the racks of the odd games broken by the planner for the noise)");
            }
            var run = runs.FirstOrDefault(r => r.Noise == s.Noise)
                ?? throw new SceneException(file, "$.noise", $"no run against the blind planner at {s.Noise} is given");
            if (s.Rules != run.Rules || s.Seed != run.Seed || s.RunGames != run.RunGames || s.Levels != run.Levels)
            {
                throw new SceneException(file, "$.seed", $"not the games of the run at {s.Noise} (expected {run.Rules.Name}, seed {run.Seed}, {run.RunGames} games, levels {run.Levels.First},{run.Levels.Second})");
            }
            others[run.Noise!].Add((file, s));
        }
        foreach (var (noise, shards) in others)
        {
            if (shards.Count > 0 && OddGamesProblem(shards.Select(x => x.Summary.Shard).ToList()) is { } problem)
            {
                throw new SceneException(shards[0].File, "$.shard", $"{problem} at {noise} (expected every odd shard K/N of one even N once: the odd games)");
            }
        }
        return [.. runs.OrderBy(r => r.Noise!.Scale).Select(r => new AiRun(r, [.. others[r.Noise!].Select(x => x.Summary)]))];
    }

    private static SelfPlaySummary Load(string file)
    {
        string text;
        try
        {
            text = File.ReadAllText(file);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new SceneException(file, "$", $"cannot read the file ({e.Message})");
        }
        var s = SelfPlaySummary.Parse(text, file);
        return s.Noise is null
            ? throw new SceneException(file, "$.noise", "a run without noise (expected selfplay --noise fastfiz:K --planners noise,blind)")
            : s;
    }

    // Null when the shards are exactly the odd games (every odd K of one even N once), else what is wrong.
    private static string? OddGamesProblem(IReadOnlyList<SelfPlayShard> shards)
    {
        int n = shards[0].Count;
        if (n % 2 != 0 || shards.Any(x => x.Count != n))
        {
            return "shards of different or odd counts";
        }
        var indices = shards.Select(x => x.Index).ToList();
        if (indices.Any(k => k % 2 == 0))
        {
            return "a shard of even games";
        }
        return indices.Distinct().Count() != indices.Count ? "a shard given twice"
            : indices.Count != n / 2 ? $"{n / 2 - indices.Count} odd shards missing"
            : null;
    }

    private static string Pct(double x) => string.Create(CultureInfo.InvariantCulture, $"{100 * x:0.0} %");

    private static string Rate(int k, int n)
    {
        var (lo, hi) = Wilson(k, n);
        return string.Create(CultureInfo.InvariantCulture, $"{k} / {n} = {Pct(n > 0 ? (double)k / n : 0)} ({Pct(lo)} - {Pct(hi)})");
    }

    /// <summary>The page: one row a noise level, every rate with its 95 % interval.</summary>
    public static string ToMarkdown(IReadOnlyList<AiRun> runs)
    {
        ArgumentNullException.ThrowIfNull(runs);
        var inv = CultureInfo.InvariantCulture;
        var sb = new StringBuilder();
        sb.Append("# The computer player under execution noise\n\n");
        sb.Append("Level 5 playing for the noise (player 0) against level 5 blind to it (player 1, one exact outcome per\n");
        sb.Append("candidate), 8-ball, the break alternating; the figures are player 0's, with 95 % intervals (Wilson;\n");
        sb.Append("balls per visit: the balls taken as a Poisson count). Made by `billiards report ai` from the runs' merged\n");
        sb.Append("summaries ([computer-player.md](../computer-player.md#execution-noise)).\n\n");
        sb.Append("| noise | games | pot success | break and run (of the racks it broke) | balls per visit | wins against the blind planner | decision ms, median / p95 (noise; blind) | run wall clock |\n");
        sb.Append("|---|---:|---|---|---|---|---|---:|\n");
        foreach (var run in runs)
        {
            var r = run.Run;
            var me = r.Players.First;
            var blind = r.Players.Second;
            var (vlo, vhi) = PerVisit(me.BreakSum, me.Visits);
            sb.Append(inv, $"| `{r.Noise}` | {r.Games} | {Rate(me.Pots, me.PotAttempts)} | {Rate(run.BreakAndRuns, run.Breaks)} | ");
            sb.Append(inv, $"{me.BreakSum} / {me.Visits} = {(me.Visits > 0 ? (double)me.BreakSum / me.Visits : 0):0.00} ({vlo:0.00} - {vhi:0.00}) | {Rate(me.GamesWon, r.Games)} | ");
            sb.Append(inv, $"{me.DecisionMedianMs:0} / {me.DecisionP95Ms:0}; {blind.DecisionMedianMs:0} / {blind.DecisionP95Ms:0} | {r.Milliseconds / 60000:0} min |\n");
        }
        sb.Append("\nThe seeds and sizes of the runs: ");
        sb.Append(string.Join("; ", runs.Select(r => string.Create(inv, $"`{r.Run.Noise}` seed {r.Run.Seed}, {r.Run.RunGames} games"))));
        if (runs.Any(r => r.OtherBreaks.Count > 0))
        {
            sb.Append(". The break and run counts every rack the planner for the noise broke: its breaks in the run against the blind planner, and at ");
            sb.Append(string.Join(", ", runs.Where(r => r.OtherBreaks.Count > 0).Select(r => $"`{r.Run.Noise}`")));
            sb.Append(" every break of the same games that the blind planner broke there (the odd games), played again by the planner for the noise on both sides (`--planners noise,noise`, ");
            sb.Append(string.Join(", ", runs.Where(r => r.OtherBreaks.Count > 0).Select(r => string.Create(inv, $"`{r.Run.Noise}` {r.OtherBreaks.Sum(o => o.Games)} games, {r.OtherBreaks.Sum(o => o.Milliseconds) / 60000:0} min"))));
            sb.Append("); a rack run out from the break is the breaker's alone, whoever the opponent");
        }
        sb.Append(". The run wall clock is the sum of its shards'; the decision times are wall-clock times on a shared machine (the benchmark has the figures to compare).\n\n");
        sb.Append("![Break-and-run rate against the noise, made by `billiards report ai SUMMARY.json ... --out docs/ai`](ai-break-and-run.png)\n");
        return sb.ToString();
    }

    /// <summary>The plot: player 0's break-and-run rate with its 95 % interval against the noise scale K.</summary>
    public static byte[] ToPng(IReadOnlyList<AiRun> runs)
    {
        ArgumentNullException.ThrowIfNull(runs);
        const int W = 640, H = 420, Left = 70, Right = 30, Top = 50, Bottom = 60;
        double kMax = Math.Max(1, runs.Count > 0 ? runs.Max(r => r.Noise.Scale) : 1);
        kMax = Math.Ceiling(kMax);
        using var bitmap = new SKBitmap(W, H);
        using (var canvas = new SKCanvas(bitmap))
        {
            canvas.Clear(SKColors.White);
            var inv = CultureInfo.InvariantCulture;
            using var font = new SKFont(SKTypeface.Default, 14);
            using var small = new SKFont(SKTypeface.Default, 12);
            using var title = new SKFont(SKTypeface.Default, 16);
            using var text = new SKPaint { Color = SKColors.Black, IsAntialias = true };
            using var grid = new SKPaint { Color = new SKColor(0xdd, 0xdd, 0xdd), StrokeWidth = 1 };
            using var frame = new SKPaint { Color = SKColors.Black, Style = SKPaintStyle.Stroke, StrokeWidth = 1 };
            using var line = new SKPaint { Color = new SKColor(0x1f, 0x77, 0xb4), Style = SKPaintStyle.Stroke, StrokeWidth = 2.5f, IsAntialias = true };
            using var dot = new SKPaint { Color = new SKColor(0x1f, 0x77, 0xb4), IsAntialias = true };
            float pw = W - Left - Right, ph = H - Top - Bottom;
            float X(double k) => Left + (float)(k / kMax * pw);
            float Y(double rate) => Top + ph - (float)(rate * ph);
            canvas.DrawText("Level 5 playing for the noise: break-and-run rate (95 % interval)", W / 2f, 28, SKTextAlign.Center, title, text);
            for (int g = 0; g <= 10; g += 2)
            {
                canvas.DrawLine(Left, Y(g / 10.0), Left + pw, Y(g / 10.0), grid);
                canvas.DrawText(string.Create(inv, $"{g * 10} %"), Left - 6, Y(g / 10.0) + 4, SKTextAlign.Right, small, text);
            }
            for (int k = 0; k <= (int)kMax; k++)
            {
                canvas.DrawLine(X(k), Top, X(k), Top + ph, grid);
                canvas.DrawText(string.Create(inv, $"{k}x"), X(k), Top + ph + 16, SKTextAlign.Center, small, text);
            }
            canvas.DrawRect(Left, Top, pw, ph, frame);
            canvas.DrawText("execution noise (fastfiz:K)", Left + pw / 2, H - 20, SKTextAlign.Center, font, text);
            using var path = new SKPath();
            for (int i = 0; i < runs.Count; i++)
            {
                var run = runs[i];
                double k = run.Noise.Scale, rate = run.Breaks > 0 ? (double)run.BreakAndRuns / run.Breaks : 0;
                var (lo, hi) = Wilson(run.BreakAndRuns, run.Breaks);
                canvas.DrawLine(X(k), Y(lo), X(k), Y(hi), line);
                canvas.DrawLine(X(k) - 6, Y(lo), X(k) + 6, Y(lo), line);
                canvas.DrawLine(X(k) - 6, Y(hi), X(k) + 6, Y(hi), line);
                canvas.DrawCircle(X(k), Y(rate), 5, dot);
                if (i == 0)
                {
                    path.MoveTo(X(k), Y(rate));
                }
                else
                {
                    path.LineTo(X(k), Y(rate));
                }
            }
            canvas.DrawPath(path, line);
        }
        using var image = SKImage.FromBitmap(bitmap);
        using var data = image.Encode(SKEncodedImageFormat.Png, 100);
        return data.ToArray();
    }

    /// <summary>Every file of the report, by name (<see cref="FileNames"/>).</summary>
    public static IReadOnlyList<(string Name, byte[] Bytes)> Files(IReadOnlyList<AiRun> runs) =>
        [(FileNames[0], Encoding.UTF8.GetBytes(ToMarkdown(runs))), (FileNames[1], ToPng(runs))];
}

/// <summary>
/// One noise level of <see cref="AiReport"/>: the run of the planner for the noise against the blind
/// one, and the shards of the run of its odd games with the planner for the noise on both sides
/// (none: the rate counts player 0's breaks alone).
/// </summary>
/// <param name="Run">The merged summary of <c>--planners noise,blind</c>.</param>
/// <param name="OtherBreaks">The shard summaries of <c>--planners noise,noise</c> over the odd games of the same run.</param>
public sealed record AiRun(SelfPlaySummary Run, IReadOnlyList<SelfPlaySummary> OtherBreaks)
{
    /// <summary>The run's noise.</summary>
    public ExecutionNoise Noise => Run.Noise!;

    /// <summary>Racks the planner for the noise broke: player 0's in the run, both players' in the other shards.</summary>
    public int Breaks => Run.Players.First.Breaks + OtherBreaks.Sum(o => o.Players.First.Breaks + o.Players.Second.Breaks);

    /// <summary>Of <see cref="Breaks"/>, the racks it ran out from the break.</summary>
    public int BreakAndRuns => Run.Players.First.BreakAndRuns + OtherBreaks.Sum(o => o.Players.First.BreakAndRuns + o.Players.Second.BreakAndRuns);
}
