using Billiards.Core.Physics;
using System.Xml.Linq;
using Billiards.App.Reports;

namespace Billiards.App.Tests.Reports;

public class AccuracyReportTests
{
    [Theory]
    [InlineData(1.0)]
    [InlineData(2.0)]
    [InlineData(0.5)]
    public void ObservedOrderIsTheSlopeOfLogErrorAgainstLogDt(double order)
    {
        // error = 3 dt^p exactly: the fitted slope is p.
        var points = AccuracyReport.Steps.Select(dt => (dt, 3 * Math.Pow(dt, order)));
        Assert.Equal(order, AccuracyReport.ObservedOrder(points), 10);
    }

    [Fact]
    public void ObservedOrderIgnoresErrorsAtRoundOff()
    {
        // Errors at or below the floor say nothing about the order; the rest are first order.
        var points = new[] { (0.1, 0.2), (0.01, 0.02), (0.001, 1e-17), (0.0001, 0.0) };
        Assert.Equal(1.0, AccuracyReport.ObservedOrder(points), 10);
    }

    [Fact]
    public void MedianOfOddAndEvenCounts()
    {
        Assert.Equal(3, AccuracyReport.Median([5, 1, 3]));
        Assert.Equal(2.5, AccuracyReport.Median([4, 1, 3, 2]));
    }

    private static List<AccuracyRow> Rows() =>
    [
        new("a", ModelRegistry.Standard, ModelRegistry.Event, 0.004, 0, 100),
        new("b", ModelRegistry.Standard, ModelRegistry.Event, 0.004, 0, 300),
        new("a", ModelRegistry.Standard, ModelRegistry.Exact, 1.0 / 30, 1e-15, 10),
        new("b", ModelRegistry.Standard, ModelRegistry.Exact, 1.0 / 30, 2e-15, 30),
        new("a", ModelRegistry.Standard, ModelRegistry.Euler, 1.0 / 30, 0.1, 5),
        new("b", ModelRegistry.Standard, ModelRegistry.Euler, 1.0 / 30, 0.3, 7),
        new("a", ModelRegistry.Standard, ModelRegistry.Euler, 1.0 / 60, 0.05, 9),
        new("b", ModelRegistry.Standard, ModelRegistry.Euler, 1.0 / 60, 0.15, 11),
        new("a", ModelRegistry.Thesis, ModelRegistry.Thesis.Integrators[0], 1.0 / 30, 0.4, 2),
    ];

    [Fact]
    public void SeriesTakeTheWorstErrorAndTheMeanTimeOverTheSuite()
    {
        var series = AccuracyReport.Series(Rows());
        Assert.Equal(["euler", "event", "exact", "thesis"], series.Keys.Order(StringComparer.Ordinal));
        Assert.Equal(new AccuracyReport.SeriesPoint(0, 0, 0, 200), series["event"].Single());
        // euler at 1/30: errors 0.1 and 0.3 (worst 0.3, median 0.2), times 5 and 7 (mean 6).
        Assert.Equal([new(1.0 / 30, 0.3, 0.2, 6), new(1.0 / 60, 0.15, 0.1, 10)], series["euler"]);
    }

    [Fact]
    public void CsvHasOneLinePerRowWithRoundTripNumbers()
    {
        string[] lines = AccuracyReport.ToCsv(Rows()).TrimEnd('\n').Split('\n');
        Assert.Equal("scene,model,integrator,dt_s,steps_per_s,max_error_m,median_us", lines[0]);
        Assert.Equal(10, lines.Length);
        Assert.Equal("b,standard,euler,0.016666666666666666,60,0.15,11", lines[8]);
    }

    [Fact]
    public void SummaryStatesEulersOrderAndTheCostOfEvent()
    {
        string md = AccuracyReport.ToMarkdown(Rows(), 2);
        // euler: 0.3 at 1/30, 0.15 at 1/60, so the order is exactly 1.
        Assert.Contains("**Observed order of `euler`:** 1.00 (median over the scenes", md);
        Assert.Contains("| a | 1.00 |", md); // scene a: 0.1 at 1/30, 0.05 at 1/60
        // event 200 µs against exact 20 µs at the step nearest 1/250 (here 1/30).
        Assert.Contains("200.0 µs per shot, 10.00 times `exact`", md);
        Assert.Contains("largest difference at any step is 2.00e-15 m", md);
    }

    [Fact]
    public void PlotIsWellFormedSvgWithALinePerSeries()
    {
        var svg = XDocument.Parse(AccuracyReport.ToSvg(Rows()));
        XNamespace ns = "http://www.w3.org/2000/svg";
        Assert.Equal(4, svg.Descendants(ns + "polyline").Count());
        // One marker per (series, step): event 1, exact 1, euler 2, thesis 1.
        Assert.Equal(5, svg.Descendants(ns + "circle").Count());
    }
}
