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
}
