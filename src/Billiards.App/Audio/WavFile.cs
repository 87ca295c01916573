using NAudio.Wave;

namespace Billiards.App.Audio;

/// <summary>16-bit PCM WAV files through NAudio's <see cref="WaveFileWriter"/>.</summary>
public static class WavFile
{
    /// <summary>A float sample (full scale 1) as a 16-bit sample, rounded, clamped at full scale.</summary>
    public static short ToPcm16(float x) => (short)Math.Clamp(Math.Round(x * 32767.0), -32767, 32767);

    /// <summary>The bytes of a 16-bit PCM WAV file of interleaved samples.</summary>
    /// <param name="interleaved">Samples, full scale 1, interleaved by channel.</param>
    /// <param name="sampleRate">Sample rate (Hz).</param>
    /// <param name="channels">Channels.</param>
    public static byte[] Encode(ReadOnlySpan<float> interleaved, int sampleRate, int channels)
    {
        var pcm = new short[interleaved.Length];
        for (int i = 0; i < pcm.Length; i++)
        {
            pcm[i] = ToPcm16(interleaved[i]);
        }
        using var memory = new MemoryStream((pcm.Length * 2) + 64);
        // The writer completes the RIFF header when disposed, and leaves a stream it was given open.
        using (var writer = new WaveFileWriter(memory, new WaveFormat(sampleRate, 16, channels)))
        {
            writer.WriteSamples(pcm, 0, pcm.Length);
        }
        return memory.ToArray();
    }
}
