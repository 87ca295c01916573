namespace Billiards.App.Audio;

/// <summary>
/// A device's queue of small 16-bit stereo buffers (OpenAL's buffer queue on a streaming source);
/// <see cref="AudioPlayer"/> keeps it filled. Called from the audio thread only.
/// </summary>
public interface IAudioStream : IDisposable
{
    /// <summary>Sample rate (Hz).</summary>
    int SampleRate { get; }

    /// <summary>Frames in one buffer.</summary>
    int FramesPerBuffer { get; }

    /// <summary>Buffers that may be filled now (played ones reclaimed, never queued ones).</summary>
    int FreeBuffers();

    /// <summary>Frames queued and not yet played: how long a buffer submitted now waits before it sounds.</summary>
    int PendingFrames();

    /// <summary>Queues one buffer (<see cref="FramesPerBuffer"/> interleaved stereo frames) and keeps the stream playing.</summary>
    void Submit(ReadOnlySpan<short> interleaved);
}
