namespace Billiards.App.Rendering;

/// <summary>
/// Chooses the resolution a moving camera is drawn at on a software rasteriser, so that its
/// frames fit their time: a frame over <see cref="HighShare"/> of its budget lowers the scale by
/// <see cref="Down"/>, one under <see cref="LowShare"/> raises it by <see cref="Up"/>, within
/// [<see cref="Min"/>, <see cref="Max"/>]. It falls fast and climbs slowly, so that a slow frame is
/// answered at once and the picture does not pump. A frame's cost on such a rasteriser is mostly
/// its pixels, which go with the square of the scale; how fast the machine is, and how busy, it
/// learns from the frames themselves.
/// </summary>
internal sealed class ResolutionGovernor
{
    /// <summary>The lowest scale (of the window's width and height).</summary>
    public const float Min = 0.3f;

    /// <summary>The highest scale: full resolution (then nothing is reduced).</summary>
    public const float Max = 1f;

    /// <summary>The scale a moving camera starts at.</summary>
    public const float Start = 0.5f;

    /// <summary>The factor a slow frame scales by.</summary>
    public const float Down = 0.9f;

    /// <summary>The factor a quick frame scales by.</summary>
    public const float Up = 1.02f;

    /// <summary>Share of the budget above which a frame is slow.</summary>
    public const double HighShare = 0.9;

    /// <summary>Share of the budget below which a frame is quick.</summary>
    public const double LowShare = 0.6;

    /// <summary>The scale now.</summary>
    public float Scale { get; private set; } = Start;

    /// <summary>Takes the time a reduced frame took (s) against its budget (s).</summary>
    public void Report(double seconds, double budget)
    {
        if (!(budget > 0) || !double.IsFinite(seconds))
        {
            return;
        }
        if (seconds > HighShare * budget)
        {
            Scale = Math.Max(Min, Scale * Down);
        }
        else if (seconds < LowShare * budget)
        {
            Scale = Math.Min(Max, Scale * Up);
        }
    }
}
