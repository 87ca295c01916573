namespace Billiards.App.Platform;

/// <summary>
/// Caps the frame rate: after each frame, how long to wait before the next may start, so that
/// frames start at most <see cref="CapFps"/> times a second. The starts keep to a schedule of one
/// period apart (a frame that waits a little too long is made up by the next), and a frame that
/// runs over its period starts the schedule again from its end rather than hurrying the frames
/// after it. Without a cap the game would draw as fast as it can and keep every core busy.
/// </summary>
public sealed class FramePacer
{
    private double? _scheduled;

    /// <summary>A pacer for at most <paramref name="capFps"/> frames a second; 0 (or less) paces nothing.</summary>
    public FramePacer(double capFps) => CapFps = Math.Max(0, capFps);

    /// <summary>The cap (frames/s), 0 for none.</summary>
    public double CapFps { get; }

    /// <summary>
    /// The seconds to wait after a frame that ended at <paramref name="now"/> (s, any monotonic
    /// clock) before the next starts: the next start on the schedule less <paramref name="now"/>,
    /// 0 when it is already due or there is no cap.
    /// </summary>
    public double WaitAfter(double now)
    {
        if (CapFps <= 0)
        {
            return 0;
        }
        double next = _scheduled is { } s ? s + (1 / CapFps) : now;
        if (next < now)
        {
            next = now;
        }
        _scheduled = next;
        return next - now;
    }
}
