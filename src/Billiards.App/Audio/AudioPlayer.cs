using System.Diagnostics;
using Billiards.Core.Mathematics;

namespace Billiards.App.Audio;

/// <summary>
/// Plays the game's sound on a device: an audio thread keeps the device's small buffer queue
/// filled from an <see cref="AudioMixer"/>, and the game thread's requests (sounds, rolling,
/// listener) reach the mixer at the next buffer it renders.
/// </summary>
/// <remarks>
/// Latency: a sound requested now starts at the head of the next buffer rendered, which sounds
/// after the frames still queued ahead of it. With 3 buffers of 5 ms queued at most and the thread
/// waking every millisecond, that is at most 15 ms plus the wake-up; <see cref="MaxLatency"/>
/// measures it for every sound, from the request to the moment its first frame is due to play.
/// </remarks>
public sealed class AudioPlayer : IAudioOutput
{
    /// <summary>Volume at start.</summary>
    public const float DefaultVolume = 0.8f;

    private readonly IAudioStream _stream;
    private readonly TextWriter? _report;
    private readonly Func<string>? _describe;
    private readonly AudioMixer _mixer;
    private readonly Thread _thread;
    private readonly object _gate = new();
    private List<Request> _requests = [], _spare = [];
    private readonly float[] _mix;
    private readonly short[] _pcm;
    private volatile bool _stopping;
    private volatile float _volume = DefaultVolume;
    private volatile bool _muted;
    private double _latencySum;

    /// <summary>Starts playing on a stream.</summary>
    /// <param name="stream">The device's buffer queue; owned (disposed) by the player.</param>
    /// <param name="balls">Balls that may roll at once.</param>
    /// <param name="report">Where to write one line of statistics when disposed, or null.</param>
    /// <param name="describe">Describes the device for that line, read after the stream is stopped.</param>
    public AudioPlayer(IAudioStream stream, int balls = 16, TextWriter? report = null, Func<string>? describe = null)
    {
        _stream = stream;
        _report = report;
        _describe = describe;
        _mixer = new AudioMixer(stream.SampleRate, balls);
        _mix = new float[stream.FramesPerBuffer * 2];
        _pcm = new short[stream.FramesPerBuffer * 2];
        _thread = new Thread(Run) { IsBackground = true, Name = "audio", Priority = ThreadPriority.AboveNormal };
        _thread.Start();
    }

    /// <inheritdoc />
    public bool IsSilent => false;

    /// <inheritdoc />
    public float Volume
    {
        get => _volume;
        set => _volume = Math.Clamp(value, 0f, 1f);
    }

    /// <inheritdoc />
    public bool Muted
    {
        get => _muted;
        set => _muted = value;
    }

    /// <summary>Sounds started so far.</summary>
    public int SoundsPlayed { get; private set; }

    /// <summary>Largest latency of a sound so far (s): from its request to its first frame's turn to play.</summary>
    public double MaxLatency { get; private set; }

    /// <summary>Mean latency of the sounds so far (s).</summary>
    public double MeanLatency => SoundsPlayed == 0 ? 0 : _latencySum / SoundsPlayed;

    /// <summary>Buffers rendered so far.</summary>
    public long BuffersRendered { get; private set; }

    /// <inheritdoc />
    public void Play(in SoundCue cue)
    {
        // Synthesised here, on the game thread, so the audio thread only mixes.
        var samples = VoiceSynth.Render(cue, _stream.SampleRate);
        Add(new Request(RequestKind.Play, samples, cue.Position, 0, 0, default, Stopwatch.GetTimestamp()));
    }

    /// <inheritdoc />
    public void SetListener(Listener listener) => Add(new Request(RequestKind.Listener, null, default, 0, 0, listener, 0));

    /// <inheritdoc />
    public void SetRolling(int ball, double speed, Vec3 position) => Add(new Request(RequestKind.Rolling, null, position, ball, speed, default, 0));

    private void Add(Request request)
    {
        lock (_gate)
        {
            _requests.Add(request);
        }
    }

    private void Run()
    {
        while (!_stopping)
        {
            int free = _stream.FreeBuffers();
            for (int i = 0; i < free && !_stopping; i++)
            {
                RenderBuffer();
            }
            Thread.Sleep(1);
        }
    }

    private void RenderBuffer()
    {
        List<Request> requests;
        lock (_gate)
        {
            requests = _requests;
            _requests = _spare;
        }
        long now = Stopwatch.GetTimestamp();
        double ahead = (double)_stream.PendingFrames() / _stream.SampleRate;
        foreach (var r in requests)
        {
            switch (r.Kind)
            {
                case RequestKind.Play:
                    _mixer.Play(r.Samples!, r.Position);
                    double latency = ((now - r.Timestamp) / (double)Stopwatch.Frequency) + ahead;
                    MaxLatency = Math.Max(MaxLatency, latency);
                    _latencySum += latency;
                    SoundsPlayed++;
                    break;
                case RequestKind.Rolling:
                    _mixer.SetRolling(r.Ball, r.Speed, r.Position);
                    break;
                case RequestKind.Listener:
                    _mixer.Listener = r.Listener;
                    break;
            }
        }
        requests.Clear();
        lock (_gate)
        {
            _spare = requests;
        }
        _mixer.Render(_mix);
        float gain = _muted ? 0 : _volume;
        for (int i = 0; i < _mix.Length; i++)
        {
            _pcm[i] = WavFile.ToPcm16(_mix[i] * gain);
        }
        _stream.Submit(_pcm);
        BuffersRendered++;
    }

    /// <summary>Stops the audio thread and closes the stream.</summary>
    public void Dispose()
    {
        _stopping = true;
        _thread.Join();
        string device = _describe?.Invoke() ?? "audio";
        _stream.Dispose();
        _report?.WriteLine(string.Create(System.Globalization.CultureInfo.InvariantCulture,
            $"billiards: {device}: {SoundsPlayed} sounds, {BuffersRendered} buffers of {_stream.FramesPerBuffer} frames at {_stream.SampleRate} Hz, latency mean {MeanLatency * 1000:F1} ms, max {MaxLatency * 1000:F1} ms"));
    }

    private enum RequestKind : byte
    {
        Play,
        Rolling,
        Listener,
    }

    private readonly record struct Request(RequestKind Kind, float[]? Samples, Vec3 Position, int Ball, double Speed, Listener Listener, long Timestamp);
}
