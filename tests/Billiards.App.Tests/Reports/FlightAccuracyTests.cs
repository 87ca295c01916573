using Billiards.App.Reports;
using Billiards.Core.Scenes;
using Xunit.Abstractions;

namespace Billiards.App.Tests.Reports;

public sealed class FlightAccuracyTests(ITestOutputHelper output)
{
    [Fact]
    public void FlightChecksMeetTheirAnalyticValuesWithExactContacts()
    {
        string folder = AssetFolder.Scene("flight");
        FlightAccuracy.Validate(folder);
        var rows = FlightAccuracy.Measure(folder);
        output.WriteLine(FlightAccuracy.ToMarkdown(rows));
        // Four configurations, seven timed checks, the off-table position and the jump's contacts each, the energy for three (not euler).
        Assert.Equal((4 * 9) + 3, rows.Count);
        foreach (var row in rows.Where(r => !r.Series.StartsWith("euler", StringComparison.Ordinal)))
        {
            // Exact contact times: the analytic roots to round-off (1 us is the bound);
            // the energy across a landing never above round-off.
            double bound = row.Unit == "J" ? 1e-12 : 1e-6;
            Assert.True(double.IsFinite(row.Measured), $"{row.Case}, {row.Series}: not measured");
            Assert.True(row.Error <= bound, $"{row.Case}, {row.Series}: {row.Measured} against {row.Analytic}, error {row.Error:E2}");
        }
        // Euler's step shows: its landings are late or early by up to a step, but its jump still clears the 1.
        Assert.Contains(rows, r => r.Series.StartsWith("euler", StringComparison.Ordinal) && r.Unit == "s" && r.Error > 1e-6);
        Assert.All(rows.Where(r => r.Unit == "contacts"), r => Assert.Equal(0, r.Measured));
    }
}

public sealed class SnookerReportTests
{
    [Theory]
    [InlineData("--level", "9", "--level 9: expected 1 to 5")]
    [InlineData("--positions", "0", "--positions 0: expected 1 to 1000")]
    [InlineData("--tries", "101", "--tries 101: expected 1 to 100")]
    public void BadArgumentsAreOneLineAndExitTwo(string option, string value, string message)
    {
        var (code, stdout, stderr) = Billiards.App.Tests.Cli.CliRun.Run("report", "snookers", option, value);
        Assert.Equal(2, code);
        Assert.Equal("", stdout);
        Assert.Equal($"billiards: {message}", stderr.Trim());
    }

    [Fact]
    public void TwoPositionsPrintBothPlannersAndRepeat()
    {
        var first = Billiards.App.Tests.Cli.CliRun.Run("report", "snookers", "--positions", "2", "--tries", "1");
        Assert.Equal(0, first.Code);
        Assert.Contains("| without jumps | 2 |", first.Out);
        Assert.Contains("| with jumps | 2 |", first.Out);
        Assert.Equal(first.Out, Billiards.App.Tests.Cli.CliRun.Run("report", "snookers", "--positions", "2", "--tries", "1").Out);
    }
}
