using Billiards.App.Reports;
using Billiards.Core.Physics;
using Billiards.Core.Table;
using SkiaSharp;

namespace Billiards.App.Tests.Reports;

public class CushionReportTests
{
    private static readonly double Height = TableSpec.FromPreset("pool-9ft").CushionHeight;

    [Fact]
    public void EveryModelSpeedAndSpinHasACurveOverTheIncomingAngles()
    {
        var curves = CushionReport.Curves(PhysicsParams.Default, Height);
        Assert.Equal(ModelRegistry.BallCushionModels.Count * CushionReport.Speeds.Count * CushionReport.Spins.Count, curves.Count);
        foreach (var ((model, speed, spin), points) in curves)
        {
            Assert.Equal(CushionReport.Angles, points.Select(p => p.IncomingDeg));
            // Spin can be turned into speed, so the rebound speed is not bounded by the incoming one:
            // what always holds is a finite speed and an angle below 90.
            Assert.All(points, p => Assert.True(p.Speed > 0 && double.IsFinite(p.Speed) && p.ReboundDeg < 90, $"{model} {speed} {spin}: {p}"));
        }
        // A head-on stun ball comes straight back, at less than its speed, with every model.
        foreach (var model in ModelRegistry.BallCushionNames)
        {
            var headOn = curves[(model, 1, "no spin")][0];
            Assert.Equal(0, headOn.ReboundDeg, 9);
            Assert.InRange(headOn.Speed, 0.5, 1);
        }
    }

    [Fact]
    public void StrongeCompliantPartsFromHanWhereTheContactsSlipIsSmallAndAgreesUnderGrossSlip()
    {
        var curves = CushionReport.Curves(PhysicsParams.Default, Height);
        foreach (double speed in CushionReport.Speeds)
        {
            double Largest(string spin, Func<Rebound, double> of) =>
                curves[("han-2005", speed, spin)].Zip(curves[("stronge-compliant", speed, spin)], (h, s) => Math.Abs(of(h) - of(s))).Max();
            foreach (string spin in (string[])["no spin", "low slip"])
            {
                Assert.True(Largest(spin, r => r.ReboundDeg) > 2, $"{spin} at {speed} m/s: the models agree");
            }
            foreach (string spin in (string[])["running english", "reverse english"])
            {
                Assert.True(Largest(spin, r => r.ReboundDeg) < 1e-6 && Largest(spin, r => r.Speed) < 1e-9, $"{spin} at {speed} m/s: gross slip, yet the models differ");
            }
        }
        Assert.Contains("Where stronge-compliant differs from han-2005", CushionReport.ToMarkdown(curves, PhysicsParams.Default, Height), StringComparison.Ordinal);
    }

    [Fact]
    public void RunningEnglishWidensTheReboundAndReverseNarrowsIt()
    {
        // Up to 50 deg off the normal: nearer the rail a rolling ball sticks to the cushion with
        // either english and the two rebounds meet.
        var curves = CushionReport.Curves(PhysicsParams.Default, Height);
        foreach (var model in ModelRegistry.BallCushionNames)
        {
            for (int i = 0; CushionReport.Angles[i] <= 50; i += 5)
            {
                double running = curves[(model, 1, "running english")][i].ReboundDeg;
                double reverse = curves[(model, 1, "reverse english")][i].ReboundDeg;
                Assert.True(running > reverse, $"{model} at {CushionReport.Angles[i]} deg: running {running}, reverse {reverse}");
            }
        }
    }

    [Fact]
    public void ThePageNamesItsPlotsAndThePlotsArePictures()
    {
        var files = CushionReport.Files();
        Assert.Equal(CushionReport.FileNames, files.Select(f => f.Name));
        string page = System.Text.Encoding.UTF8.GetString(files[0].Bytes);
        foreach (double speed in CushionReport.Speeds)
        {
            Assert.Contains($"]({CushionReport.PlotName(speed)})", page);
        }
        foreach (var (_, bytes) in files.Skip(1))
        {
            using var bitmap = SKBitmap.Decode(bytes);
            Assert.NotNull(bitmap);
            Assert.True(bitmap.Width > 800 && bitmap.Height > 500);
            // Not a blank frame: the model colours are drawn.
            int coloured = 0;
            for (int y = 0; y < bitmap.Height; y += 3)
            {
                for (int x = 0; x < bitmap.Width; x += 3)
                {
                    var c = bitmap.GetPixel(x, y);
                    coloured += Math.Abs(c.Red - c.Green) > 60 || Math.Abs(c.Green - c.Blue) > 60 ? 1 : 0;
                }
            }
            Assert.True(coloured > 500, $"{coloured} coloured samples");
        }
    }
}
