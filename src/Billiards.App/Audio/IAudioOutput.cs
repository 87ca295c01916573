using Billiards.Core.Mathematics;

namespace Billiards.App.Audio;

/// <summary>
/// Where the game's sounds go: a device (<see cref="AudioPlayer"/>) or nowhere
/// (<see cref="SilentAudio"/>). Called from the game thread.
/// </summary>
public interface IAudioOutput : IDisposable
{
    /// <summary>True when nothing is heard (no device).</summary>
    bool IsSilent { get; }

    /// <summary>Volume, 0 to 1.</summary>
    float Volume { get; set; }

    /// <summary>True while muted (the volume is kept).</summary>
    bool Muted { get; set; }

    /// <summary>Starts a cue's sound as soon as possible.</summary>
    void Play(in SoundCue cue);

    /// <summary>Moves the listener (the camera).</summary>
    void SetListener(Listener listener);

    /// <summary>Sets a ball's rolling noise: speed (m/s; 0 when at rest or dropped) and place (m).</summary>
    void SetRolling(int ball, double speed, Vec3 position);
}

/// <summary>No device: every sound is dropped; volume and mute are still kept.</summary>
public sealed class SilentAudio : IAudioOutput
{
    /// <inheritdoc />
    public bool IsSilent => true;

    /// <inheritdoc />
    public float Volume { get; set; } = AudioPlayer.DefaultVolume;

    /// <inheritdoc />
    public bool Muted { get; set; }

    /// <inheritdoc />
    public void Play(in SoundCue cue)
    {
    }

    /// <inheritdoc />
    public void SetListener(Listener listener)
    {
    }

    /// <inheritdoc />
    public void SetRolling(int ball, double speed, Vec3 position)
    {
    }

    /// <inheritdoc />
    public void Dispose()
    {
    }
}
