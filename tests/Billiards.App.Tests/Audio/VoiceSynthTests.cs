using Billiards.App.Audio;
using Billiards.Core.Mathematics;
using Xunit.Abstractions;

namespace Billiards.App.Tests.Audio;

public sealed class VoiceSynthTests(ITestOutputHelper output)
{
    private const int Rate = 48000;

    private static float[] Sound(SoundKind kind, double speed, uint seed = 7, bool rattle = false) =>
        VoiceSynth.Render(new SoundCue(0, kind, speed, Vec3.Zero, rattle, seed), Rate);

    private static double Peak(float[] x) => x.Max(Math.Abs);

    [Theory]
    [InlineData(SoundKind.BallClick)]
    [InlineData(SoundKind.CushionThud)]
    [InlineData(SoundKind.JawKnock)]
    [InlineData(SoundKind.CueStrike)]
    [InlineData(SoundKind.PocketDrop)]
    [InlineData(SoundKind.TableLanding)]
    public void PeakLoudnessRisesWithImpactSpeed(SoundKind kind)
    {
        double[] speeds = [0.5, 1, 2, 4, 8];
        // A different seed for every speed: the variations (+-0.6 dB) must not undo a doubling of speed.
        double[] peaks = speeds.Select((v, i) => Peak(Sound(kind, v, seed: (uint)(100 + i)))).ToArray();
        output.WriteLine(string.Join(", ", peaks.Select(p => p.ToString("F4"))));
        for (int i = 1; i < peaks.Length; i++)
        {
            Assert.True(peaks[i] > peaks[i - 1], $"{kind}: peak at {speeds[i]} m/s ({peaks[i]:F4}) not above {speeds[i - 1]} m/s ({peaks[i - 1]:F4})");
        }
        // Doubling the speed adds several dB (the level law is speed^0.7 for impacts: 4.2 dB), not a trace.
        double perDoubling = 20 * Math.Log10(peaks[3] / peaks[1]) / 2;
        Assert.True(perDoubling > (kind == SoundKind.PocketDrop ? 1.5 : 2.5), $"{kind}: {perDoubling:F2} dB per doubling");
    }

    [Fact]
    public void ABallClickIsBrighterThanACushionThud()
    {
        foreach (double speed in new[] { 0.2, 2, 8 })
        {
            double click = WavAnalysis.Centroid(Sound(SoundKind.BallClick, speed), Rate);
            double thud = WavAnalysis.Centroid(Sound(SoundKind.CushionThud, speed), Rate);
            double clickPower = WavAnalysis.Centroid(Sound(SoundKind.BallClick, speed), Rate, byPower: true);
            double thudPower = WavAnalysis.Centroid(Sound(SoundKind.CushionThud, speed), Rate, byPower: true);
            output.WriteLine($"{speed} m/s: centroid click {click:F0} Hz, thud {thud:F0} Hz; by power {clickPower:F0} Hz, {thudPower:F0} Hz");
            Assert.True(click > 1.5 * thud, $"{speed} m/s: click {click:F0} Hz, thud {thud:F0} Hz");
            // Where the energy is: a phenolic click rings at a few kHz, cushion rubber on wood at a few hundred Hz.
            Assert.InRange(clickPower, 3000, 6500);
            Assert.InRange(thudPower, 100, 500);
        }
    }

    [Fact]
    public void ALandingOnTheBedIsADullThumpBelowAClick()
    {
        foreach (double speed in new[] { 0.4, 1, 3 })
        {
            double landing = WavAnalysis.Centroid(Sound(SoundKind.TableLanding, speed), Rate, byPower: true);
            double click = WavAnalysis.Centroid(Sound(SoundKind.BallClick, speed), Rate, byPower: true);
            output.WriteLine($"{speed} m/s: landing {landing:F0} Hz, click {click:F0} Hz");
            // Ball on cloth over slate: the energy is in the low hundreds of Hz, far below the phenolic ring.
            Assert.InRange(landing, 60, 400);
            Assert.True(click > 5 * landing, $"{speed} m/s: click {click:F0} Hz, landing {landing:F0} Hz");
        }
    }

    [Fact]
    public void TheCentroidOfASineIsItsFrequency()
    {
        var sine = Enumerable.Range(0, 4096).Select(i => (float)Math.Sin(2 * Math.PI * 1500 * i / Rate)).ToArray();
        Assert.Equal(1500, WavAnalysis.Centroid(sine, Rate, byPower: true), 1500 * 0.01);
    }

    [Fact]
    public void AClickIsShortAndAThudIsLonger()
    {
        // Time for the level to fall 40 dB below its peak.
        static double DecayTime(float[] x)
        {
            double limit = Peak(x) * 0.01;
            int last = Array.FindLastIndex(x, s => Math.Abs(s) > limit);
            return (double)last / Rate;
        }
        double click = DecayTime(Sound(SoundKind.BallClick, 2));
        double thud = DecayTime(Sound(SoundKind.CushionThud, 2));
        Assert.InRange(click, 0.002, 0.025);
        Assert.True(thud > 2 * click, $"thud {thud * 1000:F1} ms, click {click * 1000:F1} ms");
    }

    [Fact]
    public void AMiscueSoundsBrighterAndLongerThanAGoodStrike()
    {
        var good = Sound(SoundKind.CueStrike, 4);
        var miscue = Sound(SoundKind.Miscue, 4);
        double goodCentroid = WavAnalysis.Centroid(good, Rate, byPower: true);
        double miscueCentroid = WavAnalysis.Centroid(miscue, Rate, byPower: true);
        output.WriteLine($"power centroid: strike {goodCentroid:F0} Hz, miscue {miscueCentroid:F0} Hz");
        Assert.True(miscueCentroid > goodCentroid + 500);
        // The scrape keeps sounding after 10 ms, when the good strike's tock has died.
        // Energy of the first difference (a high-pass: the shaft's low knock barely counts).
        static double Energy(float[] x, double from, double to)
        {
            double sum = 0;
            for (int i = (int)(from * Rate); i < (int)(to * Rate); i++)
            {
                sum += (double)(x[i] - x[i - 1]) * (x[i] - x[i - 1]);
            }
            return sum;
        }
        Assert.True(Energy(miscue, 0.010, 0.030) > 10 * Energy(good, 0.010, 0.030));
    }

    [Fact]
    public void ARattledDropHasExtraKnocksAfterItsThump()
    {
        var plain = Sound(SoundKind.PocketDrop, 1);
        var rattled = Sound(SoundKind.PocketDrop, 1, rattle: true);
        Assert.Equal(plain.Length, rattled.Length);
        // Same seed: identical until the first rattle knock (21 ms), different after.
        int firstKnock = (int)(0.019 * Rate);
        Assert.Equal(plain.AsSpan(0, firstKnock).ToArray(), rattled.AsSpan(0, firstKnock).ToArray());
        // The knocks ring near 1 kHz, the thump near 120 Hz: compare the first difference's energy, a high-pass.
        static double Band(float[] x)
        {
            double sum = 0;
            for (int i = (int)(0.020 * Rate); i < (int)(0.070 * Rate); i++)
            {
                sum += (double)(x[i] - x[i - 1]) * (x[i] - x[i - 1]);
            }
            return sum;
        }
        Assert.True(Band(rattled) > 2 * Band(plain));
    }

    [Fact]
    public void ADropRollsAlongTheReturnAfterwards()
    {
        var drop = Sound(SoundKind.PocketDrop, 1);
        double Rms(double from, double to) => Math.Sqrt(drop.Skip((int)(from * Rate)).Take((int)((to - from) * Rate)).Average(s => (double)s * s));
        // Silence between the thump and the roll, then the roll.
        Assert.True(Rms(VoiceSynth.ReturnDelay + 0.1, VoiceSynth.ReturnDelay + 0.4) > 10 * Rms(VoiceSynth.ReturnDelay - 0.1, VoiceSynth.ReturnDelay - 0.02));
    }

    [Fact]
    public void SeedsVaryRepeatedClicksSlightlyAndTheSameSeedRepeatsExactly()
    {
        var a = Sound(SoundKind.BallClick, 2, seed: 1);
        var b = Sound(SoundKind.BallClick, 2, seed: 2);
        Assert.Equal(a, Sound(SoundKind.BallClick, 2, seed: 1));
        Assert.NotEqual(a, b);
        // Slightly: within about 1 dB of each other.
        Assert.InRange(20 * Math.Log10(Peak(a) / Peak(b)), -1.5, 1.5);
    }

    [Fact]
    public void EverySoundStartsOnItsFirstSample()
    {
        foreach (var kind in Enum.GetValues<SoundKind>())
        {
            var x = Sound(kind, 1);
            // The contact transient: the first sample carries a sizeable share of the peak.
            Assert.True(Math.Abs(x[0]) > 0.2 * x.Take(Rate / 100).Max(Math.Abs), $"{kind}: {x[0]}");
        }
    }
}
