using Billiards.App.Audio;
using Billiards.Core.Mathematics;

namespace Billiards.App.Tests.Audio;

/// <summary>A device queue that takes every buffer at once and keeps them.</summary>
internal sealed class CapturingStream : IAudioStream
{
    private readonly object _gate = new();
    private readonly List<short[]> _buffers = [];

    public int SampleRate => 48000;

    public int FramesPerBuffer => 240;

    public bool Disposed { get; private set; }

    public int FreeBuffers() => 1;

    public int PendingFrames() => 0;

    public void Submit(ReadOnlySpan<short> interleaved)
    {
        lock (_gate)
        {
            _buffers.Add(interleaved.ToArray());
        }
    }

    public short[] Captured()
    {
        lock (_gate)
        {
            return _buffers.SelectMany(b => b).ToArray();
        }
    }

    public void Dispose() => Disposed = true;
}

public sealed class AudioPlayerTests
{
    private static short[] PlayAClick(Action<AudioPlayer> configure)
    {
        var stream = new CapturingStream();
        using (var player = new AudioPlayer(stream))
        {
            configure(player);
            player.SetListener(new Listener(new Vec3(-1, 0, 0), Vec3.Zero));
            player.Play(new SoundCue(0, SoundKind.BallClick, 2, Vec3.Zero, false, 1));
            // Wait (not time) for the click to have been mixed: until the player has rendered it.
            SpinWait.SpinUntil(() => player.SoundsPlayed == 1 && player.BuffersRendered > 20, TimeSpan.FromSeconds(30));
            Assert.Equal(1, player.SoundsPlayed);
        }
        Assert.True(stream.Disposed);
        return stream.Captured();
    }

    [Fact]
    public void ARequestedSoundReachesTheDevice()
    {
        short[] pcm = PlayAClick(_ => { });
        int peak = pcm.Max(s => Math.Abs((int)s));
        // The click from 1 m straight ahead: equal-power centre (sqrt 1/2) at the default volume.
        float voicePeak = VoiceSynth.Render(new SoundCue(0, SoundKind.BallClick, 2, Vec3.Zero, false, 1), 48000).Max(Math.Abs);
        double expected = voicePeak * Math.Sqrt(0.5) * AudioPlayer.DefaultVolume * 32767;
        Assert.InRange(peak, expected - 2, expected + 2);
    }

    [Fact]
    public void MuteSilencesAndVolumeScales()
    {
        Assert.All(PlayAClick(p => p.Muted = true), s => Assert.Equal(0, s));
        int full = PlayAClick(p => p.Volume = 1).Max(s => Math.Abs((int)s));
        int half = PlayAClick(p => p.Volume = 0.5f).Max(s => Math.Abs((int)s));
        Assert.InRange(half, (full / 2) - 1, (full / 2) + 1);
    }

    [Fact]
    public void VolumeIsClampedToZeroToOne()
    {
        using var player = new AudioPlayer(new CapturingStream());
        player.Volume = 3;
        Assert.Equal(1, player.Volume);
        player.Volume = -1;
        Assert.Equal(0, player.Volume);
    }
}
