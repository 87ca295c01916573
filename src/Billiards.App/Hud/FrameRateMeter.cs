namespace Billiards.App.Hud;

/// <summary>
/// The frame rate, Formel 4: f = 1000 / (t_end - t_start) with times in ms. The seed measured
/// from the start of its display callback to its end, which included the buffer swap; we measure
/// from one frame's start to the next, which is the same interval. One frame's value jitters, so
/// the HUD shows frames counted over a window of wall time (<see cref="WindowSeconds"/>).
/// </summary>
/// <remarks>
/// An average over the last frames (an exponential one, weight 0.1 per frame, was used before)
/// misleads exactly when it matters: after a few hundred fast frames it takes tens of slow
/// frames, i.e. tens of seconds at 2 FPS, to come down, and looks like a frame rate collapsing
/// over half a minute when it was low all along. Counting over time shows a slow rate at once.
/// </remarks>
public sealed class FrameRateMeter
{
    /// <summary>Length of the counting window (s).</summary>
    public const double WindowSeconds = 0.5;

    private double _windowSeconds;
    private int _windowFrames;
    private bool _windowCompleted;

    /// <summary>The last frame's rate (frames/s), Formel 4; 0 before the first frame.</summary>
    public double Current { get; private set; }

    /// <summary>
    /// Frames per second over the last completed window; before the first window completes, over
    /// all frames so far; 0 before the first frame.
    /// </summary>
    public double Smoothed { get; private set; }

    /// <summary>Adds a frame that took <paramref name="milliseconds"/> (t_end - t_start); non-positive times are skipped.</summary>
    public void AddFrame(double milliseconds)
    {
        if (!(milliseconds > 0) || !double.IsFinite(milliseconds))
        {
            return;
        }
        Current = 1000 / milliseconds;
        _windowSeconds += milliseconds / 1000;
        _windowFrames++;
        if (_windowSeconds >= WindowSeconds)
        {
            Smoothed = _windowFrames / _windowSeconds;
            _windowCompleted = true;
            _windowSeconds = 0;
            _windowFrames = 0;
        }
        else if (!_windowCompleted)
        {
            Smoothed = _windowFrames / _windowSeconds;
        }
    }
}
