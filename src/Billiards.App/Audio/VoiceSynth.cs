using NAudio.Dsp;

namespace Billiards.App.Audio;

/// <summary>
/// Synthesises one sound as a mono waveform (full scale 1 at 1 m from the listener), by kind:
/// damped modes for the ringing bodies, short noise bursts for the contact, filtered noise for
/// rumbles. Every sound starts with a broadband contact transient on its first sample, so its
/// onset is the event's time to within a sample; anything that follows later (a rattle, the
/// return's rumble) starts softly and stays below a few kHz.
/// </summary>
/// <remarks>
/// The phenolic click is mostly the rigid-body "acceleration noise" of the contact (Hertz contact
/// of about 0.2 ms, shorter the faster the impact, Koss and Alfredson 1973 for colliding spheres):
/// a sharp pulse, then a few kHz of ring that dies within a few milliseconds. A cushion is rubber
/// on wood: a low body that the rubber damps. Loudness grows as speed^0.7, a compromise between
/// the pressure's linear growth and the ear's compression, so a kiss is still heard beside a break.
/// </remarks>
public static class VoiceSynth
{
    /// <summary>Delay from a pocket drop to the ball rolling along the return (s).</summary>
    public const double ReturnDelay = 0.35;

    /// <summary>Peak level of a sound of <paramref name="kind"/> at <paramref name="speed"/> before variations (full scale at 1 m).</summary>
    public static double Level(SoundKind kind, double speed)
    {
        double v = Math.Max(speed, 0);
        return kind switch
        {
            SoundKind.BallClick => 0.55 * Math.Pow(v / 4, 0.7),
            SoundKind.CushionThud => 0.40 * Math.Pow(v / 2, 0.7),
            SoundKind.JawKnock => 0.40 * Math.Pow(v / 2, 0.7),
            SoundKind.CueStrike => 0.30 * Math.Pow(v / 4, 0.7),
            SoundKind.Miscue => 0.25 * Math.Pow(v / 4, 0.7),
            // Even a ball that trickles in drops the pocket's depth: never silent.
            SoundKind.PocketDrop => 0.30 * Math.Pow(Math.Max(v, 0.4) / 1.5, 0.5),
            // Scaled by the vertical impact speed: a hop of 5 cm lands at 1 m/s.
            SoundKind.TableLanding => 0.45 * Math.Pow(v / 1.5, 0.7),
            _ => 0,
        };
    }

    /// <summary>The sound of a cue at a sample rate (Hz), as a new mono buffer.</summary>
    public static float[] Render(in SoundCue cue, int sampleRate)
    {
        var noise = new Noise(cue.Seed);
        // Small seeded variations: +-3 % pitch, +-12 % decay, +-0.6 dB level.
        double pitch = 1 + (0.03 * noise.Vary());
        double decay = 1 + (0.12 * noise.Vary());
        double level = Level(cue.Kind, cue.Speed) * (1 + (0.07 * noise.Vary()));
        var s = new Synth(sampleRate, noise);
        switch (cue.Kind)
        {
            case SoundKind.BallClick:
                Click(ref s, cue.Speed, level, pitch, decay);
                break;
            case SoundKind.CushionThud:
                s.Allocate(0.16);
                // Rubber spreads the contact over about a millisecond: a soft-edged pulse, little treble.
                s.Pulse(0.0012, 0.30 * level);
                s.Mode(0, 145 * pitch, 0.028 * decay, 0.75 * level);
                s.Mode(0, 265 * pitch, 0.016 * decay, 0.45 * level);
                s.Mode(0, 540 * pitch, 0.006 * decay, 0.20 * level);
                s.Rumble(0, 380, 0.010 * decay, 0.35 * level, attack: 0);
                break;
            case SoundKind.JawKnock:
                s.Allocate(0.10);
                s.Pulse(0.0006, 0.35 * level);
                s.Burst(0, 0.06 * level, 0.0002);
                s.Mode(0, 430 * pitch, 0.012 * decay, 0.60 * level);
                s.Mode(0, 790 * pitch, 0.008 * decay, 0.45 * level);
                s.Mode(0, 1380 * pitch, 0.004 * decay, 0.30 * level);
                break;
            case SoundKind.CueStrike:
                s.Allocate(0.08);
                s.Burst(0, 0.40 * level, 0.0003);
                s.Mode(0, 1850 * pitch, 0.0028 * decay, 0.55 * level);
                s.Mode(0, 3050 * pitch, 0.0016 * decay, 0.30 * level);
                // The shaft's low knock.
                s.Mode(0, 190 * pitch, 0.012 * decay, 0.35 * level);
                break;
            case SoundKind.Miscue:
                s.Allocate(0.09);
                s.Burst(0, 0.35 * level, 0.0002);
                s.Mode(0, 1850 * pitch, 0.0020 * decay, 0.20 * level);
                // The tip skidding across the ball: a bright scrape that swells and fades.
                s.Scrape(0.001, 0.030 * decay, 4200 * pitch, 0.55 * level);
                s.Mode(0.002, 5300 * pitch, 0.018 * decay, 0.12 * level);
                break;
            case SoundKind.PocketDrop:
                Drop(ref s, cue.Rattle, level, pitch, decay);
                break;
            case SoundKind.TableLanding:
                s.Allocate(0.14);
                // The cloth spreads the contact over a millisecond or two (less when the ball comes
                // down hard); the thick slate answers low and dies fast, the ball itself knocks higher.
                s.Pulse(Math.Clamp(0.0018 * Math.Pow(Math.Max(cue.Speed, 0.05), -0.2), 0.0008, 0.003), 0.40 * level);
                s.Mode(0, 95 * pitch, 0.030 * decay, 0.70 * level);
                s.Mode(0, 210 * pitch, 0.018 * decay, 0.45 * level);
                s.Mode(0, 720 * pitch, 0.005 * decay, 0.18 * level);
                s.Rumble(0, 300, 0.012 * decay, 0.30 * level, attack: 0);
                break;
        }
        return s.Buffer;
    }

    private static void Click(ref Synth s, double speed, double level, double pitch, double decay)
    {
        s.Allocate(0.03);
        // Hertz contact time falls as v^-1/5; a shorter contact excites the higher ring more.
        double contact = Math.Clamp(0.00025 * Math.Pow(Math.Max(speed, 0.01), -0.2), 0.0001, 0.0006);
        double bright = Math.Clamp(0.00025 / contact, 0.6, 1.6);
        s.Pulse(contact, 0.55 * level);
        s.Burst(0, 0.06 * level, 0.0002);
        s.Mode(0, 3900 * pitch, 0.0024 * decay, 0.60 * level);
        s.Mode(0, 6200 * pitch, 0.0015 * decay, 0.30 * level * bright);
        s.Mode(0, 9400 * pitch, 0.0009 * decay, 0.12 * level * bright);
        s.Mode(0, 2300 * pitch, 0.0030 * decay, 0.20 * level);
    }

    private static void Drop(ref Synth s, bool rattle, double level, double pitch, double decay)
    {
        s.Allocate(ReturnDelay + 0.95);
        // The ball lands in the pocket: a hollow thump.
        s.Pulse(0.001, 0.30 * level);
        s.Mode(0, 118 * pitch, 0.045 * decay, 0.70 * level);
        s.Mode(0, 236 * pitch, 0.025 * decay, 0.40 * level);
        s.Rumble(0, 700, 0.020 * decay, 0.40 * level, attack: 0);
        if (rattle)
        {
            // Rattled in the jaws: it bounces a few times in the throat, muffled, before settling.
            double[] at = [0.021, 0.039, 0.053, 0.064];
            for (int k = 0; k < at.Length; k++)
            {
                double a = level * 0.45 * Math.Pow(0.7, k);
                s.Tap(at[k] * decay, (950 + (130 * k)) * pitch, 0.006, a);
            }
        }
        // Then it rolls along the return under the table and stops against the balls already there.
        s.Rumble(ReturnDelay, 260, 0.32 * decay, 0.12 * level, attack: 0.06);
        s.Tap(ReturnDelay + (0.75 * decay), 620 * pitch, 0.012, 0.15 * level);
    }

    /// <summary>A mono buffer and the generators that add into it.</summary>
    private struct Synth(int rate, Noise noise)
    {
        private Noise _noise = noise;

        public float[] Buffer { get; private set; } = [];

        public void Allocate(double seconds) => Buffer = new float[(int)Math.Ceiling(seconds * rate)];

        private readonly int Index(double t) => (int)Math.Round(t * rate);

        /// <summary>Exponentially decaying sinusoid from t0 (s), starting at its peak's phase so the onset is sharp.</summary>
        public readonly void Mode(double t0, double frequency, double tau, double amplitude)
        {
            if (frequency >= rate / 2.0)
            {
                return;
            }
            var b = Buffer;
            int start = Index(t0);
            double w = 2 * Math.PI * frequency / rate;
            double damp = Math.Exp(-1 / (tau * rate));
            // Recursive oscillator: cheap and exact to round-off over these short lengths.
            double c = Math.Cos(w), sn = Math.Sin(w);
            double re = amplitude, im = 0;
            int end = Math.Min(b.Length, start + (int)(tau * rate * 9));
            for (int i = start; i < end; i++)
            {
                b[i] += (float)re;
                double r = ((re * c) - (im * sn)) * damp;
                im = ((re * sn) + (im * c)) * damp;
                re = r;
            }
        }

        /// <summary>A short decaying white-noise burst at t0: the contact's broadband crack.</summary>
        public void Burst(double t0, double amplitude, double tau)
        {
            var b = Buffer;
            int start = Index(t0);
            double damp = Math.Exp(-1 / (tau * rate));
            double a = amplitude;
            int end = Math.Min(b.Length, start + (int)(tau * rate * 8));
            for (int i = start; i < end; i++)
            {
                // The first sample is a full-size spike in the sense of the contact's push, so the onset is exact.
                float n = i == start ? 1f : _noise.Next();
                b[i] += (float)(a * n);
                a *= damp;
            }
        }

        /// <summary>
        /// The pressure of a contact force of <paramref name="contact"/> seconds: about its
        /// derivative, a cosine half-wave, tapered to end at 0 so that only its start is abrupt.
        /// </summary>
        public readonly void Pulse(double contact, double amplitude)
        {
            var b = Buffer;
            int n = Math.Max(2, (int)Math.Round(contact * rate));
            for (int i = 0; i < n && i < b.Length; i++)
            {
                double u = (double)i / n;
                b[i] += (float)(amplitude * Math.Cos(Math.PI * u) * (1 - (u * u)));
            }
        }

        /// <summary>Low-passed noise from t0 with an exponential decay, after an optional linear fade-in (s).</summary>
        public void Rumble(double t0, double cutoff, double tau, double amplitude, double attack)
        {
            var b = Buffer;
            int start = Index(t0);
            var low = BiQuadFilter.LowPassFilter(rate, (float)cutoff, 0.7071f);
            var low2 = BiQuadFilter.LowPassFilter(rate, (float)cutoff, 0.7071f);
            double damp = Math.Exp(-1 / (tau * rate));
            int fade = Math.Max(1, (int)(attack * rate));
            // Narrow low-passed noise loses level; bring it back to about the asked amplitude.
            double gain = amplitude * Math.Sqrt(rate / (2.0 * cutoff)) * 0.5;
            double env = 1;
            int end = Math.Min(b.Length, start + (int)(tau * rate * 8) + fade);
            for (int i = start; i < end; i++)
            {
                int k = i - start;
                double shape = attack > 0 ? Math.Min(1.0, (double)k / fade) * (k < fade ? 1 : env) : env;
                if (attack <= 0 || k >= fade)
                {
                    env *= damp;
                }
                float x = low2.Transform(low.Transform(_noise.Next()));
                b[i] += (float)(gain * shape * x);
            }
        }

        /// <summary>Band-passed noise that swells over 1/4 of its time and decays: a skid.</summary>
        public void Scrape(double t0, double length, double centre, double amplitude)
        {
            var b = Buffer;
            int start = Index(t0);
            int n = Math.Min(b.Length - start, (int)(length * rate));
            var band = BiQuadFilter.BandPassFilterConstantPeakGain(rate, (float)centre, 1.2f);
            for (int i = 0; i < n; i++)
            {
                double u = (double)i / n;
                double env = u < 0.25 ? u / 0.25 : Math.Exp(-(u - 0.25) * 5);
                b[start + i] += (float)(amplitude * 2.5 * env * band.Transform(_noise.Next()));
            }
        }

        /// <summary>A muffled knock with a raised-cosine attack of 2 ms: heard, but no sharp onset of its own.</summary>
        public readonly void Tap(double t0, double frequency, double tau, double amplitude)
        {
            var b = Buffer;
            int start = Index(t0);
            int rise = (int)(0.002 * rate);
            double w = 2 * Math.PI * frequency / rate;
            int end = Math.Min(b.Length, start + rise + (int)(tau * rate * 8));
            for (int i = start; i < end; i++)
            {
                int k = i - start;
                double env = k < rise ? 0.5 - (0.5 * Math.Cos(Math.PI * k / rise)) : Math.Exp(-(k - rise) / (tau * rate));
                b[i] += (float)(amplitude * env * Math.Sin(w * k));
            }
        }
    }
}
