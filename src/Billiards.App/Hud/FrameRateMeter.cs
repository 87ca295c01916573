namespace Billiards.App.Hud;

/// <summary>
/// The frame rate, Formel 4: f = 1000 / (t_end - t_start) with times in ms. The seed measured
/// from the start of its display callback to its end, which included the buffer swap; we measure
/// from one frame's start to the next, which is the same interval. One frame's value jitters, so
/// the HUD shows an exponential average.
/// </summary>
public sealed class FrameRateMeter
{
    /// <summary>Weight of the newest frame in the average: about the last 10 frames count.</summary>
    public const double Smoothing = 0.1;

    /// <summary>The last frame's rate (frames/s), Formel 4; 0 before the first frame.</summary>
    public double Current { get; private set; }

    /// <summary>The averaged rate (frames/s); 0 before the first frame.</summary>
    public double Smoothed { get; private set; }

    /// <summary>Adds a frame that took <paramref name="milliseconds"/> (t_end - t_start); non-positive times are skipped.</summary>
    public void AddFrame(double milliseconds)
    {
        if (!(milliseconds > 0) || !double.IsFinite(milliseconds))
        {
            return;
        }
        Current = 1000 / milliseconds;
        Smoothed = Smoothed == 0 ? Current : Smoothed + Smoothing * (Current - Smoothed);
    }
}
