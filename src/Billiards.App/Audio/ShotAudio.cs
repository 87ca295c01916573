using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Audio;

/// <summary>
/// The offline sound of a scene's shot, the same synthesis the game plays: the scene is simulated
/// step by step (its events, and every ball's speed and place after each step for the rolling
/// noise), then mixed with each voice starting on the sample nearest its event's time. Pure
/// computation: the same scene and rate give the same samples, bit for bit.
/// </summary>
public static class ShotAudio
{
    /// <summary>Sound kept after the last ball comes to rest (s): the last drop rolling along the return.</summary>
    public const double Tail = 1.4;

    /// <summary>Longest shot rendered (s).</summary>
    public const double MaxDuration = 60;

    /// <summary>The listener of an offline render: the eye of <c>render</c>'s default camera (16:9, 45 degrees).</summary>
    public static Listener DefaultListener(Scene scene)
    {
        var (eye, target) = RenderMath.DefaultCamera(scene.Table, 16f / 9f, 45f);
        return new Listener(new Vec3(eye.X, eye.Y, eye.Z), new Vec3(target.X, target.Y, target.Z));
    }

    /// <summary>Renders the scene's shot as interleaved stereo at <paramref name="sampleRate"/> (Hz), full scale 1.</summary>
    /// <param name="scene">The scene; its shot, if any, is struck at time 0.</param>
    /// <param name="sampleRate">Sample rate (Hz).</param>
    /// <param name="limit">False renders without the limiter (to show what it prevents).</param>
    public static float[] Render(Scene scene, int sampleRate, bool limit = true)
    {
        var score = Score(scene);
        var mixer = new AudioMixer(sampleRate, score.Balls, limit) { Listener = DefaultListener(scene) };
        long frames = (long)Math.Ceiling((score.EndTime + Tail) * sampleRate);
        int latency = mixer.Latency;
        var output = new float[frames * 2];
        // The limiter delays its output: render that much longer and drop the start, so every
        // voice sounds at its event's own sample.
        var scratch = new float[(frames + latency) * 2];
        int cue = 0, roll = 0;
        long position = 0;
        long total = frames + latency;
        while (position < total)
        {
            while (cue < score.Cues.Count && SampleOf(score.Cues[cue].Time, sampleRate) <= position)
            {
                mixer.Play(score.Cues[cue++]);
            }
            while (roll < score.Rolls.Count && SampleOf(score.Rolls[roll].Time, sampleRate) <= position)
            {
                var r = score.Rolls[roll++];
                mixer.SetRolling(r.Ball, r.Speed, r.Position);
            }
            long next = total;
            if (cue < score.Cues.Count)
            {
                next = Math.Min(next, SampleOf(score.Cues[cue].Time, sampleRate));
            }
            if (roll < score.Rolls.Count)
            {
                next = Math.Min(next, SampleOf(score.Rolls[roll].Time, sampleRate));
            }
            next = Math.Max(next, position + 1);
            mixer.Render(scratch.AsSpan((int)(position * 2), (int)((next - position) * 2)));
            position = next;
        }
        Array.Copy(scratch, latency * 2, output, 0, output.Length);
        return output;
    }

    /// <summary>The sound cues and rolling updates of the scene's shot, in time order.</summary>
    public static ShotScore Score(Scene scene)
    {
        var sim = SimulationFactory.Create(scene);
        var voicing = new EventVoicing(sim.FeatureName);
        var cues = new List<SoundCue>();
        var rolls = new List<RollUpdate>();
        var previous = sim.Balls.ToArray();
        int seen = 0;
        if (scene.Shot is { } shot)
        {
            sim.Strike(shot);
        }
        while (true)
        {
            // Events logged by the strike or the last step, placed where their balls were then
            // (linear between the step's ends is well under a centimetre off).
            var log = sim.Events;
            for (; seen < log.Count; seen++)
            {
                var e = log[seen];
                if (voicing.Voice(e, EventPosition(sim, previous, e), scene.Shot) is { } c)
                {
                    cues.Add(c);
                }
            }
            var balls = sim.Balls;
            for (int i = 0; i < balls.Length; i++)
            {
                rolls.Add(new RollUpdate(sim.Time, i, RollingSpeed(balls[i]), balls[i].Position));
            }
            if (sim.IsAtRest || sim.Time >= MaxDuration)
            {
                break;
            }
            sim.Balls.CopyTo(previous);
            sim.Step();
        }
        // Several events may share a step; a stable sort keeps their logged order.
        var ordered = cues.OrderBy(c => c.Time).ToList();
        return new ShotScore(ordered, rolls, sim.Time, sim.Balls.Length);
    }

    /// <summary>The frame at which a sound of time <paramref name="time"/> (s) starts.</summary>
    public static long SampleOf(double time, int sampleRate) => (long)Math.Round(Math.Max(time, 0) * sampleRate);

    /// <summary>A ball's rolling-noise speed: its speed on the cloth; 0 once it drops.</summary>
    public static double RollingSpeed(in BallState ball) => ball.IsPocketed ? 0 : ball.Velocity.LengthXY;

    private static Vec3 EventPosition(Simulation sim, BallState[] before, in SimEvent e)
    {
        double time = e.Time;
        Vec3 At(BallId id)
        {
            int i = sim.IndexOf(id);
            if (i < 0)
            {
                return Vec3.Zero;
            }
            var now = sim.Balls[i].Position;
            double span = sim.Dt;
            double u = span > 0 ? Math.Clamp(1 - ((sim.Time - time) / span), 0, 1) : 1;
            return before[i].Position + ((now - before[i].Position) * u);
        }
        return e.Kind == EventKind.BallBall ? (At(e.A) + At(e.B)) * 0.5 : At(e.A);
    }
}

/// <summary>A shot's sounds: cues in time order, rolling updates after each step, when the balls came to rest (s), how many balls.</summary>
public sealed record ShotScore(IReadOnlyList<SoundCue> Cues, IReadOnlyList<RollUpdate> Rolls, double EndTime, int Balls);

/// <summary>A ball's rolling speed (m/s) and place (m) from <paramref name="Time"/> (s) on.</summary>
public readonly record struct RollUpdate(double Time, int Ball, double Speed, Vec3 Position);
