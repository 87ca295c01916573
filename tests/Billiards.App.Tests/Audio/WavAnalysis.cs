using System.Numerics;
using NAudio.Wave;

namespace Billiards.App.Tests.Audio;

/// <summary>A WAV file read back, and the measurements the sound tests make on it.</summary>
internal sealed class WavAnalysis
{
    private WavAnalysis(int rate, int channels, short[] samples)
    {
        Rate = rate;
        Channels = channels;
        Samples = samples;
        Mono = new double[samples.Length / channels];
        for (int i = 0; i < Mono.Length; i++)
        {
            double sum = 0;
            for (int c = 0; c < channels; c++)
            {
                sum += samples[(i * channels) + c];
            }
            Mono[i] = sum / channels;
        }
    }

    public int Rate { get; }

    public int Channels { get; }

    public int BitsPerSample { get; private init; }

    /// <summary>Interleaved 16-bit samples.</summary>
    public short[] Samples { get; }

    /// <summary>The channels' mean, in 16-bit units.</summary>
    public double[] Mono { get; }

    public static WavAnalysis Read(string path)
    {
        using var reader = new WaveFileReader(path);
        var format = reader.WaveFormat;
        var bytes = new byte[reader.Length];
        int read = reader.Read(bytes, 0, bytes.Length);
        var samples = new short[read / 2];
        Buffer.BlockCopy(bytes, 0, samples, 0, read);
        return new WavAnalysis(format.SampleRate, format.Channels, samples) { BitsPerSample = format.BitsPerSample };
    }

    /// <summary>
    /// The onset nearest after <paramref name="time"/> - 5 ms (s), or null: the first sample whose
    /// second difference (a high-pass that keeps the contact transients and drops rumbles) exceeds
    /// 3 times the largest one in the 3 ms before the search, and an absolute floor.
    /// </summary>
    public double? Onset(double time)
    {
        int Index(double t) => Math.Clamp((int)Math.Round(t * Rate), 2, Mono.Length - 1);
        double Hp(int n) => Math.Abs(Mono[n] - (2 * Mono[n - 1]) + Mono[n - 2]);
        double baseline = 0;
        for (int n = Index(time - 0.008); n < Index(time - 0.005); n++)
        {
            baseline = Math.Max(baseline, Hp(n));
        }
        double threshold = Math.Max(3 * baseline, 12);
        for (int n = Index(time - 0.005); n < Index(time + 0.008); n++)
        {
            if (Hp(n) > threshold)
            {
                return (double)n / Rate;
            }
        }
        return null;
    }

    /// <summary>Largest magnitude of the mono signal in [from, to) (s), 16-bit units.</summary>
    public double Peak(double from, double to)
    {
        double peak = 0;
        for (int n = Math.Max(0, (int)(from * Rate)); n < Math.Min(Mono.Length, (int)(to * Rate)); n++)
        {
            peak = Math.Max(peak, Math.Abs(Mono[n]));
        }
        return peak;
    }

    /// <summary>
    /// Spectral centroid (Hz) of a mono signal: the mean frequency of its zero-padded FFT weighted
    /// by magnitude (the usual definition), or by power (where the energy is: an abrupt onset's
    /// 1/f tail weighs less).
    /// </summary>
    public static double Centroid(ReadOnlySpan<float> signal, int rate, bool byPower = false)
    {
        int size = 1;
        while (size < signal.Length)
        {
            size *= 2;
        }
        var padded = new double[size];
        for (int i = 0; i < signal.Length; i++)
        {
            padded[i] = signal[i];
        }
        Complex[] spectrum = FftSharp.FFT.ForwardReal(padded);
        double[] magnitude = FftSharp.FFT.Magnitude(spectrum);
        double weighted = 0, total = 0;
        for (int k = 0; k < magnitude.Length; k++)
        {
            double weight = byPower ? magnitude[k] * magnitude[k] : magnitude[k];
            weighted += (double)k * rate / size * weight;
            total += weight;
        }
        return weighted / total;
    }
}
