using Billiards.App.Native;

namespace Billiards.App.Audio;

/// <summary>Opens the game's audio output: OpenAL Soft when there is a device, else silence and one line saying so.</summary>
public static class AudioOutputs
{
    /// <summary>
    /// The device's output, or <see cref="SilentAudio"/> after one line on <paramref name="stderr"/>
    /// when there is no OpenAL library or no device (a server, CI).
    /// </summary>
    /// <param name="stderr">Where the one line goes.</param>
    /// <param name="deviceName">The OpenAL device (null: the default one).</param>
    /// <param name="libraries">Library names to try (null: the platform's OpenAL Soft names).</param>
    public static IAudioOutput Open(TextWriter stderr, string? deviceName = null, string[]? libraries = null)
    {
        try
        {
            var stream = OpenAlStream.Open(deviceName, libraries ?? OpenAl.DefaultLibraries);
            // BILLIARDS_AUDIO_STATS=1: one line at the end on the sounds played and their latency.
            var report = Environment.GetEnvironmentVariable("BILLIARDS_AUDIO_STATS") is "1" ? stderr : null;
            return new AudioPlayer(stream, report: report, describe: () => $"audio on \"{stream.DeviceName}\" ({stream.BufferCount} buffers queued at most, {stream.Underruns} underruns)");
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException or BadImageFormatException or InvalidOperationException)
        {
            stderr.WriteLine($"billiards: {e.Message}; playing without sound");
            return new SilentAudio();
        }
    }
}
