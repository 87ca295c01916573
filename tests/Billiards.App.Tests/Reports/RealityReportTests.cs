using System.Text.Json;
using Billiards.App.Reports;
using Billiards.Core.Physics;
using Billiards.Core.Table;
using SkiaSharp;

namespace Billiards.App.Tests.Reports;

/// <summary>The reality page: every measured series against the default models, each case in its band or marked beyond the model.</summary>
public class RealityReportTests
{
    private static List<RealityCase> Cases()
    {
        using var data = JsonDocument.Parse(File.ReadAllBytes(RealityReport.DataPath));
        return RealityReport.Measure(data);
    }

    [Fact]
    public void EverySeriesOfTheStandardModelIsOnThePage()
    {
        var series = Cases().Select(c => c.Series).Distinct().ToList();
        foreach (string id in (string[])["rolling-deceleration", "sliding-deceleration", "cushion-rebound", "cut-shots", "head-on", "throw-speed-30", "throw-speed-45", "throw-angle", "spin-down", "squirt"])
        {
            Assert.Contains(id, series);
        }
    }

    [Fact]
    public void WithTheDefaultModelsEveryMeasuredCaseIsInItsBandOrMarkedBeyondTheModelWithItsReason()
    {
        var cases = Cases();
        Assert.All(cases, c => Assert.True(c.Verdict != "fail", $"{c.Series} {c.Case}: engine {c.Engine} outside {c.Low}..{c.High}"));
        Assert.All(cases.Where(c => c.Verdict == "beyond"), c => Assert.False(string.IsNullOrWhiteSpace(c.Beyond)));
        // Beyond is the exception: most cases pass.
        Assert.True(cases.Count(c => c.Verdict == "pass") > 5 * cases.Count(c => c.Verdict == "beyond"));
    }

    [Fact]
    public void TheOldConstantsFailWhereTheIssueSaysTheyDid()
    {
        // With e_c constant at 0.85 the rolling ball comes back at 0.80 of its speed at every speed,
        // against 0.95 measured at 1 m/s (Mathavan 2009, Fig. 9's fit).
        var old = PhysicsParams.Default with { R = 0.02625, M = 0.1406 };
        double height = TableSpec.FromPreset(SnookerTable.Preset).CushionHeight;
        Assert.Equal(0.80, RealityReport.Rebound(1, old, height), 2);
        var snooker = Billiards.Core.Balls.BallSet.Snooker.DefaultParams;
        double fit = -0.0877 + 1.1306 - 0.0953;
        Assert.Equal(fit, RealityReport.Rebound(1, snooker, height), 2);
        // The gearing limit at 30 deg with e_b 0.95: 4.84 deg.
        Assert.Equal(4.84, RealityReport.GearingLimit(30, 0.95), 2);
    }

    [Fact]
    public void ThePageHasItsPlotsAndTable()
    {
        var (files, cases) = RealityReport.Files();
        Assert.Equal(RealityReport.FileNames, files.Select(f => f.Name));
        string md = System.Text.Encoding.UTF8.GetString(files[0].Bytes);
        foreach (var c in cases.Take(3))
        {
            Assert.Contains(c.Case, md, StringComparison.Ordinal);
        }
        foreach (var (name, bytes) in files.Where(f => f.Name.EndsWith(".png", StringComparison.Ordinal)))
        {
            using var bitmap = SKBitmap.Decode(bytes);
            Assert.True(bitmap is { Width: > 100, Height: > 100 }, name);
        }
        Assert.StartsWith("series,case,measured,low,high,engine,verdict", System.Text.Encoding.UTF8.GetString(files[1].Bytes), StringComparison.Ordinal);
    }
}
