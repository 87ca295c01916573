namespace Billiards.App.Audio;

/// <summary>
/// A look-ahead peak limiter that never lets a sample past <see cref="Ceiling"/>: the break's
/// dozens of simultaneous clicks are turned down, not clipped.
/// </summary>
/// <remarks>
/// The gain each sample needs (ceiling / peak, with an exponential release back to 1) goes through
/// a sliding minimum and then a moving average, both <c>L</c> samples long, and the signal is
/// delayed by <c>L - 1</c>: every gain averaged for a sample is at most the gain that sample
/// needs, so the ceiling holds exactly, while the gain ramps down smoothly over the look-ahead
/// instead of stepping (a step would itself click).
/// </remarks>
public sealed class Limiter
{
    private readonly int _length;
    private readonly float[] _delayLeft, _delayRight;
    private readonly double[] _envelopes, _minima;
    private readonly double _release;
    private double _envelope = 1;
    private int _cursor;

    /// <summary>Creates a limiter.</summary>
    /// <param name="sampleRate">Sample rate (Hz).</param>
    /// <param name="ceiling">Largest output magnitude (full scale 1).</param>
    /// <param name="lookahead">Look-ahead (s); the output is delayed by it, less one sample.</param>
    /// <param name="release">Time constant of the gain's return to 1 (s).</param>
    public Limiter(int sampleRate, float ceiling = 0.89f, double lookahead = 0.001, double release = 0.08)
    {
        _length = Math.Max(1, (int)Math.Round(lookahead * sampleRate));
        Ceiling = ceiling;
        _delayLeft = new float[_length];
        _delayRight = new float[_length];
        _envelopes = new double[_length];
        _minima = new double[_length];
        Array.Fill(_envelopes, 1.0);
        Array.Fill(_minima, 1.0);
        _release = 1 - Math.Exp(-1 / (release * sampleRate));
    }

    /// <summary>Largest output magnitude.</summary>
    public float Ceiling { get; }

    /// <summary>Delay of the output behind the input (samples).</summary>
    public int Latency => _length - 1;

    /// <summary>The gain last applied (1 when nothing is limited).</summary>
    public double Gain { get; private set; } = 1;

    /// <summary>Limits interleaved stereo samples in place (their output is delayed by <see cref="Latency"/>).</summary>
    public void Process(Span<float> interleaved)
    {
        for (int i = 0; i + 1 < interleaved.Length; i += 2)
        {
            float left = interleaved[i], right = interleaved[i + 1];
            double peak = Math.Max(Math.Abs(left), Math.Abs(right));
            double needed = peak > Ceiling ? Ceiling / peak : 1;
            _envelope = Math.Min(needed, _envelope + ((1 - _envelope) * _release));

            _envelopes[_cursor] = _envelope;
            double minimum = 1;
            foreach (double e in _envelopes)
            {
                minimum = Math.Min(minimum, e);
            }
            _minima[_cursor] = minimum;
            double sum = 0;
            foreach (double m in _minima)
            {
                sum += m;
            }
            double gain = sum / _length;
            Gain = gain;

            // The ring holds the last L inputs; the oldest, L - 1 samples back, goes out now.
            _delayLeft[_cursor] = left;
            _delayRight[_cursor] = right;
            int oldest = (_cursor + 1) % _length;
            interleaved[i] = (float)(_delayLeft[oldest] * gain);
            interleaved[i + 1] = (float)(_delayRight[oldest] * gain);
            _cursor = oldest;
        }
    }
}
