using Billiards.App.Reports;
using Billiards.App.Tests.Cli;

namespace Billiards.App.Tests.Reports;

/// <summary><c>report ai</c>: the computer player under execution noise, from noisy self-play summaries.</summary>
public sealed class AiReportTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-ai-report-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string P(string name) => Path.Combine(_dir, name);

    // Wilson's 95 % interval against values computed by hand from its formula (to 1e-4).
    [Theory]
    [InlineData(0, 10, 0.0, 0.2775)]
    [InlineData(5, 10, 0.2366, 0.7634)]
    [InlineData(45, 50, 0.7864, 0.9565)]
    [InlineData(10, 10, 0.7225, 1.0)]
    public void TheWilsonIntervalIsTheTextbooks(int k, int n, double low, double high)
    {
        var (lo, hi) = AiReport.Wilson(k, n);
        Assert.Equal(low, lo, 4);
        Assert.Equal(high, hi, 4);
    }

    [Fact]
    public void ThePoissonIntervalOfBallsPerVisitIsCentredOnTheMean()
    {
        var (lo, hi) = AiReport.PerVisit(400, 100);
        Assert.Equal(4 - 1.96 * 0.2, lo, 2);
        Assert.Equal(4 + 1.96 * 0.2, hi, 2);
    }

    [Fact]
    public void TheReportTabulatesEachNoiseLevelInOrderAndPlotsIt()
    {
        foreach (string k in new[] { "2", "0" })
        {
            var run = CliRun.Run("selfplay", "--rules", "eight-ball", "--games", "2", "--levels", "1,1", "--seed", "3", "--noise", $"fastfiz:{k}", "--planners", "noise,blind", "--summary", P($"k{k}.json"));
            Assert.True(run.Code == 0, run.Err);
        }
        var report = CliRun.Run("report", "ai", P("k2.json"), P("k0.json"), "--out", P("out"));
        Assert.True(report.Code == 0, report.Err);
        string md = File.ReadAllText(P("out/ai.md"));
        Assert.Equal(md, report.Out);
        int zero = md.IndexOf("| `fastfiz:0` | 2 |", StringComparison.Ordinal), two = md.IndexOf("| `fastfiz:2` | 2 |", StringComparison.Ordinal);
        Assert.True(zero > 0 && two > zero, md);
        byte[] png = File.ReadAllBytes(P("out/ai-break-and-run.png"));
        Assert.Equal([0x89, (byte)'P', (byte)'N', (byte)'G'], png[..4]);

        // A run without noise is refused with one line, and nothing is written.
        Assert.Equal(0, CliRun.Run("selfplay", "--rules", "eight-ball", "--games", "1", "--levels", "1,1", "--seed", "3", "--summary", P("plain.json")).Code);
        var refused = CliRun.Run("report", "ai", P("plain.json"), "--out", P("out2"));
        Assert.Equal(2, refused.Code);
        Assert.Single(refused.Err.TrimEnd('\n').Split('\n'));
        Assert.StartsWith($"{P("plain.json")}: $.noise: a run without noise", refused.Err, StringComparison.Ordinal);
        Assert.False(File.Exists(P("out2/ai.md")));
    }

    // --breaks: the odd games played again by the planner for the noise on both sides count in the
    // break-and-run rate, every rack it broke; shards that are not the odd games of a run given are refused.
    [Fact]
    public void TheOddGamesBrokenByTheNoisePlannerCountInTheBreakAndRunRate()
    {
        string[] common = ["--rules", "eight-ball", "--games", "4", "--levels", "1,1", "--seed", "3", "--noise", "fastfiz:0"];
        Assert.Equal(0, CliRun.Run(["selfplay", .. common, "--planners", "noise,blind", "--summary", P("k0.json")]).Code);
        foreach (string shard in new[] { "1/4", "3/4", "0/4", "1/2" })
        {
            var run = CliRun.Run(["selfplay", .. common, "--planners", "noise,noise", "--shard", shard, "--summary", P($"b{shard.Replace('/', '-')}.json")]);
            Assert.True(run.Code == 0, run.Err);
        }
        var main = Billiards.Core.Ai.SelfPlaySummary.Parse(File.ReadAllText(P("k0.json")), "k0.json");
        var odd = new[] { "b1-4.json", "b3-4.json" }.Select(f => Billiards.Core.Ai.SelfPlaySummary.Parse(File.ReadAllText(P(f)), f)).ToList();
        int breaks = main.Players.First.Breaks + odd.Sum(o => o.Players.First.Breaks + o.Players.Second.Breaks);
        int runs = main.Players.First.BreakAndRuns + odd.Sum(o => o.Players.First.BreakAndRuns + o.Players.Second.BreakAndRuns);
        Assert.True(breaks >= 4, $"{breaks} breaks");

        var report = CliRun.Run("report", "ai", P("k0.json"), "--breaks", P("b1-4.json"), P("b3-4.json"), "--out", P("out"));
        Assert.True(report.Code == 0, report.Err);
        Assert.Contains(AiReportRate(runs, breaks), report.Out, StringComparison.Ordinal);
        // The same odd games as one shard count the same racks.
        var whole = CliRun.Run("report", "ai", P("k0.json"), "--breaks", P("b1-2.json"), "--out", P("out1"));
        Assert.Contains(AiReportRate(runs, breaks), whole.Out, StringComparison.Ordinal);

        foreach (var (files, problem) in new[]
        {
            (new[] { "b1-4.json" }, "1 odd shards missing"),
            (new[] { "b1-4.json", "b0-4.json" }, "a shard of even games"),
            (new[] { "b1-4.json", "b1-4.json" }, "a shard given twice"),
            (new[] { "k0.json" }, "expected noise,noise"),
        })
        {
            var refused = CliRun.Run(["report", "ai", P("k0.json"), "--breaks", .. files.Select(P), "--out", P("out2")]);
            Assert.Equal(2, refused.Code);
            Assert.Single(refused.Err.TrimEnd('\n').Split('\n'));
            Assert.Contains(problem, refused.Err, StringComparison.Ordinal);
            Assert.False(File.Exists(P("out2/ai.md")));
        }
    }

    private static string AiReportRate(int k, int n) =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"| {k} / {n} = {100.0 * k / n:0.0} %");
}
