using Billiards.App.Audio;

namespace Billiards.App.Tests.Audio;

public sealed class LimiterTests
{
    [Fact]
    public void NoSampleEverPassesTheCeiling()
    {
        var limiter = new Limiter(48000);
        var noise = new Noise(3);
        var signal = new float[2 * 48000];
        for (int i = 0; i < signal.Length; i++)
        {
            // Bursts up to 8 times full scale, at random.
            float burst = (i / 2000 % 3) == 0 ? 8 : 0.3f;
            signal[i] = burst * noise.Next();
        }
        limiter.Process(signal);
        Assert.True(signal.Max(Math.Abs) <= limiter.Ceiling * (1 + 1e-6));
    }

    [Fact]
    public void AQuietSignalPassesUnchangedButDelayed()
    {
        var limiter = new Limiter(48000);
        var input = new float[2000];
        var noise = new Noise(5);
        for (int i = 0; i < input.Length; i++)
        {
            input[i] = 0.5f * noise.Next();
        }
        var buffer = (float[])input.Clone();
        limiter.Process(buffer);
        int delay = 2 * limiter.Latency;
        Assert.Equal(47, limiter.Latency); // 1 ms look-ahead at 48 kHz, less one sample
        for (int i = delay; i < input.Length; i++)
        {
            Assert.Equal(input[i - delay], buffer[i]);
        }
    }

    [Fact]
    public void TheGainRampsDownBeforeAPeakInsteadOfStepping()
    {
        var limiter = new Limiter(48000);
        var buffer = new float[2 * 400];
        Array.Fill(buffer, 0.5f);
        for (int i = 2 * 200; i < 2 * 210; i++)
        {
            buffer[i] = 4f;
        }
        limiter.Process(buffer);
        // Output frame n is input frame n - 47: the peak leaves at frame 247; the 0.5 before it
        // is turned down step by step over the look-ahead, never by more than 1/48 of the way at once.
        for (int n = 201; n < 247; n++)
        {
            float step = buffer[2 * (n - 1)] - buffer[2 * n];
            Assert.InRange(step, -1e-6f, 0.5f / 40);
        }
        Assert.True(buffer[2 * 246] < 0.5f * 0.3f);
        Assert.True(buffer[2 * 247] <= limiter.Ceiling + 1e-6f);
    }
}
