namespace Billiards.App.Game;

/// <summary>
/// The fixed-step clock of the game (conventions.md, "Fix your timestep"): frame time is
/// accumulated, clamped at <see cref="MaxFrameTime"/>, whole physics steps of <see cref="Dt"/> are
/// run, and the remainder gives the interpolation factor <see cref="Alpha"/> for drawing.
/// Pause stops accumulating; a single step runs exactly one step on the next frame.
/// </summary>
/// <remarks>
/// The seed instead divided 250 steps per second by the measured frame rate (seed 4.3), which
/// drifts with the frame rate; a fixed step with an accumulator gives the same 250 Hz physics
/// and a deterministic simulation whatever the display does.
/// </remarks>
public sealed class FixedStepLoop
{
    /// <summary>Longest frame time accumulated at once (s), as MonoGame clamps: after a stall the game slows down instead of spiralling.</summary>
    public const double MaxFrameTime = 0.5;

    /// <summary>
    /// Rounding slack (s): 0.02 s of frame time is 5 steps of 1/250 s, but 0.02 - 4 * 0.004 is a hair
    /// under 0.004 in binary; without the slack that step would slip to the next frame.
    /// </summary>
    private const double Slack = 1e-9;

    private bool _stepRequested;

    /// <summary>Creates a loop for steps of <paramref name="dt"/> seconds.</summary>
    public FixedStepLoop(double dt)
    {
        if (!(dt > 0) || !double.IsFinite(dt))
        {
            throw new ArgumentOutOfRangeException(nameof(dt), dt, "the fixed step must be positive");
        }
        Dt = dt;
    }

    /// <summary>The fixed step (s).</summary>
    public double Dt { get; }

    /// <summary>Time accumulated and not yet stepped (s), in [0, <see cref="Dt"/>) after a frame.</summary>
    public double Accumulator { get; private set; }

    /// <summary>Interpolation factor between the previous and the current step, accumulator / dt, in [0, 1).</summary>
    public double Alpha => Accumulator / Dt;

    /// <summary>True while paused: frame time is ignored and only single steps advance.</summary>
    public bool Paused { get; set; }

    /// <summary>Total steps run.</summary>
    public long Steps { get; private set; }

    /// <summary>Flips <see cref="Paused"/>.</summary>
    public void TogglePause() => Paused = !Paused;

    /// <summary>Asks for one step on the next <see cref="Advance"/> (only while paused; running, it is ignored).</summary>
    public void RequestSingleStep()
    {
        if (Paused)
        {
            _stepRequested = true;
        }
    }

    /// <summary>
    /// Accounts for one frame of <paramref name="frameSeconds"/> and runs the whole steps it owes;
    /// with a <paramref name="timeScale"/> the game's time runs that many times faster (the frame
    /// is clamped at <see cref="MaxFrameTime"/> before it is scaled).
    /// </summary>
    /// <returns>The number of steps run.</returns>
    public int Advance(double frameSeconds, Action step, double timeScale = 1)
    {
        if (Paused)
        {
            // The accumulator is frozen, so the drawn (interpolated) picture stays where it was.
            if (!_stepRequested)
            {
                return 0;
            }
            _stepRequested = false;
            step();
            Steps++;
            return 1;
        }
        Accumulator += Math.Clamp(frameSeconds, 0, MaxFrameTime) * timeScale;
        int count = 0;
        while (Accumulator + Slack >= Dt)
        {
            step();
            Accumulator = Math.Max(Accumulator - Dt, 0);
            count++;
        }
        Steps += count;
        return count;
    }
}
