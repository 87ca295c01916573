using Billiards.Core.Mathematics;
using NAudio.Dsp;

namespace Billiards.App.Audio;

/// <summary>
/// Mixes the sounds of a table into interleaved stereo: the one-shot voices of events (started
/// at the next sample rendered), a quiet rolling noise per moving ball, and the
/// <see cref="Limiter"/>. The game renders it block by block on its audio thread; render-audio
/// renders it offline, starting each voice on the exact sample of its event. Not thread-safe:
/// one owner at a time.
/// </summary>
public sealed class AudioMixer
{
    /// <summary>Rolling noise level at 1 m/s, full scale at 1 m (quiet under the clicks).</summary>
    public const double RollingLevel = 0.010;

    private readonly List<Voice> _voices = [];
    private readonly Rolling[] _rolling;
    private readonly Limiter _limiter;
    private readonly double _smoothing;

    /// <summary>Creates a mixer.</summary>
    /// <param name="sampleRate">Sample rate (Hz).</param>
    /// <param name="balls">How many balls may roll at once.</param>
    /// <param name="limit">False leaves out the limiter (tests compare the raw mix with it).</param>
    public AudioMixer(int sampleRate, int balls, bool limit = true)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(sampleRate, 1000);
        SampleRate = sampleRate;
        _limiter = new Limiter(sampleRate);
        Limit = limit;
        _rolling = new Rolling[balls];
        for (int i = 0; i < balls; i++)
        {
            _rolling[i] = new Rolling(sampleRate, (uint)(0xB0A1 + i));
        }
        // Rolling gains glide over about 10 ms, so a ball's speed arriving once a physics step never clicks.
        _smoothing = 1 - Math.Exp(-1 / (0.010 * sampleRate));
    }

    /// <summary>Sample rate (Hz).</summary>
    public int SampleRate { get; }

    /// <summary>Frames rendered so far.</summary>
    public long Position { get; private set; }

    /// <summary>Where the sounds are heard from.</summary>
    public Listener Listener { get; set; } = new(new Vec3(-2, 0, 1.5), Vec3.Zero);

    /// <summary>True when the limiter is applied.</summary>
    public bool Limit { get; }

    /// <summary>Delay of the output behind the mix (frames): the limiter's look-ahead.</summary>
    public int Latency => Limit ? _limiter.Latency : 0;

    /// <summary>Voices still sounding.</summary>
    public int ActiveVoices => _voices.Count;

    /// <summary>The limiter's gain after the last frame (1 when nothing is limited).</summary>
    public double LimiterGain => _limiter.Gain;

    /// <summary>Starts a cue's sound at the next frame rendered, placed by the listener as it is now.</summary>
    public void Play(in SoundCue cue) => Play(VoiceSynth.Render(cue, SampleRate), cue.Position);

    /// <summary>Starts an already synthesised mono sound at the next frame rendered.</summary>
    public void Play(float[] samples, Vec3 position)
    {
        var (left, right) = Listener.Gains(position);
        _voices.Add(new Voice(samples, left, right));
    }

    /// <summary>Sets a ball's rolling noise: its speed (m/s; 0 when it rests or has dropped) and where it is (m).</summary>
    public void SetRolling(int ball, double speed, Vec3 position)
    {
        if ((uint)ball >= (uint)_rolling.Length)
        {
            return;
        }
        double level = RollingLevel * Math.Min(Math.Max(speed, 0), 4);
        var (left, right) = Listener.Gains(position);
        _rolling[ball].TargetLeft = (float)(level * left);
        _rolling[ball].TargetRight = (float)(level * right);
    }

    /// <summary>Silences every ball's rolling at once (a new table).</summary>
    public void StopRolling()
    {
        foreach (var r in _rolling)
        {
            r.TargetLeft = r.TargetRight = 0;
        }
    }

    /// <summary>Renders the next frames into interleaved stereo (left, right, ...), full scale 1.</summary>
    public void Render(Span<float> interleaved)
    {
        interleaved.Clear();
        int frames = interleaved.Length / 2;
        for (int v = _voices.Count - 1; v >= 0; v--)
        {
            var voice = _voices[v];
            int n = Math.Min(frames, voice.Samples.Length - voice.Next);
            for (int i = 0; i < n; i++)
            {
                float x = voice.Samples[voice.Next + i];
                interleaved[2 * i] += x * voice.Left;
                interleaved[(2 * i) + 1] += x * voice.Right;
            }
            voice.Next += n;
            if (voice.Next >= voice.Samples.Length)
            {
                _voices.RemoveAt(v);
            }
        }
        foreach (var r in _rolling)
        {
            r.Add(interleaved, frames, (float)_smoothing);
        }
        if (Limit)
        {
            _limiter.Process(interleaved);
        }
        Position += frames;
    }

    private sealed class Voice(float[] samples, float left, float right)
    {
        public float[] Samples { get; } = samples;

        public float Left { get; } = left;

        public float Right { get; } = right;

        public int Next { get; set; }
    }

    /// <summary>One ball's rolling: low-passed noise, the cloth and slate under it, at a gliding gain.</summary>
    private sealed class Rolling(int rate, uint seed)
    {
        private readonly BiQuadFilter _low = BiQuadFilter.LowPassFilter(rate, 320, 0.7071f);
        private Noise _noise = new(seed);
        private float _left, _right;

        public float TargetLeft { get; set; }

        public float TargetRight { get; set; }

        public void Add(Span<float> interleaved, int frames, float smoothing)
        {
            if (_left == 0 && _right == 0 && TargetLeft == 0 && TargetRight == 0)
            {
                return;
            }
            for (int i = 0; i < frames; i++)
            {
                _left += (TargetLeft - _left) * smoothing;
                _right += (TargetRight - _right) * smoothing;
                // The low-pass keeps a sixth of white noise's level at 320 Hz of 48 kHz: scale it back.
                float x = _low.Transform(_noise.Next()) * 6f;
                interleaved[2 * i] += x * _left;
                interleaved[(2 * i) + 1] += x * _right;
            }
            if (TargetLeft == 0 && TargetRight == 0 && Math.Abs(_left) + Math.Abs(_right) < 1e-6f)
            {
                _left = _right = 0;
            }
        }
    }
}
