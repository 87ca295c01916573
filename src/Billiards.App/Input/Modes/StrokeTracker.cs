using Billiards.Core.Cue;

namespace Billiards.App.Input.Modes;

/// <summary>
/// The seed's stroke (seed 4.4.3, Formel 31): the mouse Y when the cue starts to move is the
/// start line, i.e. where the tip touches the ball. Pulling back (mouse towards the user, y
/// grows) draws the cue back. At the first forward move the distance d between the mouse and the
/// start line is measured and a timer started; a backward move clears both, and the next forward
/// move measures again. When the mouse passes the start line the ball is struck with
/// s = d / t * 250 (d in pixels, t in ms), capped at 800 (cm/s).
/// </summary>
/// <remarks>
/// Two cases the seed leaves open, decided here:
/// <list type="bullet">
/// <item>A single event that both starts the forward move and passes the line would give t = 0.
/// For it, d is the backswing before the event and t the time since the previous event.</item>
/// <item>A forward move while the cue already touches the ball (no backswing) cannot push the cue
/// into the ball: the start line moves with the mouse, so the next pull-back starts from there.</item>
/// </list>
/// </remarks>
public sealed class StrokeTracker
{
    private const double MillisecondsPerSecond = 1000;

    private double _startY;
    private double _lastY;
    private double _lastTime;
    private bool _measuring;
    private double _distance;
    private double _timerStart;

    /// <summary>
    /// Events delivered together (one poll of the window) carry no time between them: a push whose
    /// measured time is under a millisecond took up to this long, the last frame's duration (s), and
    /// is timed so. Without it a push polled in one frame gave t ≈ 0 and always the 8 m/s cap.
    /// </summary>
    public double MinimumInterval { get; set; }

    /// <summary>True between <see cref="Begin"/> and the strike or <see cref="Cancel"/>.</summary>
    public bool IsActive { get; private set; }

    /// <summary>How far the mouse is behind the start line (pixels, ≥ 0): the drawn backswing.</summary>
    public double PullBackPixels => IsActive ? Math.Max(_lastY - _startY, 0) : 0;

    /// <summary>The forward distance measured so far (pixels), the seed's d; 0 when not measuring.</summary>
    public double MeasuredDistance => _measuring ? _distance : 0;

    /// <summary>Starts a stroke with the cue touching the ball at mouse Y <paramref name="y"/> (pixels) at <paramref name="time"/> (s).</summary>
    public void Begin(double y, double time)
    {
        IsActive = true;
        _startY = y;
        _lastY = y;
        _lastTime = time;
        _measuring = false;
    }

    /// <summary>Abandons the stroke without striking.</summary>
    public void Cancel()
    {
        IsActive = false;
        _measuring = false;
    }

    /// <summary>
    /// Feeds a mouse position (pixels, y down) at a time (s). Returns the stroke speed in the seed's
    /// units (cm/s, Formel 31, capped at 800) when this move passes the start line, and ends the
    /// stroke; otherwise null.
    /// </summary>
    public double? Move(double y, double time)
    {
        if (!IsActive || y == _lastY)
        {
            return null; // sideways movement does not move the cue
        }
        double? speed = null;
        if (y > _lastY)
        {
            // Backward: the seed clears d and t; they are measured again at the next forward move.
            _measuring = false;
        }
        else if (_measuring)
        {
            if (y < _startY)
            {
                speed = Formel31(_distance, Interval(time - _timerStart) * MillisecondsPerSecond);
            }
        }
        else if (_lastY <= _startY)
        {
            // Forward with the tip already on the ball: the line follows the mouse (see remarks).
            _startY = y;
        }
        else if (y < _startY)
        {
            // One event from behind the line to past it: measure it from the previous event.
            speed = Formel31(_lastY - _startY, Interval(time - _lastTime) * MillisecondsPerSecond);
        }
        else
        {
            // The first forward move: d is the distance to the start line, the timer starts now.
            _measuring = true;
            _distance = y - _startY;
            _timerStart = time;
        }
        _lastY = y;
        _lastTime = time;
        if (speed is not null)
        {
            IsActive = false;
            _measuring = false;
        }
        return speed;
    }

    /// <summary>
    /// The speed (the seed's cm/s, Formel 31) the stroke is being pushed at, at time
    /// <paramref name="now"/> (s): the forward distance so far over the time since the forward
    /// move began; 0 while pulling back or before a stroke. The HUD's power meter shows it.
    /// </summary>
    public double LiveSpeed(double now)
    {
        if (!IsActive || !_measuring)
        {
            return 0;
        }
        double forward = _distance - (_lastY - _startY);
        return forward <= 0 ? 0 : Formel31(forward, Interval(now - _timerStart) * MillisecondsPerSecond);
    }

    private double Interval(double seconds) => seconds < 1e-3 ? Math.Max(seconds, MinimumInterval) : seconds;

    /// <summary>
    /// Formel 31, s = d / t * 250, capped at 800; d in pixels, t in ms, s the cue's speed at impact in cm/s
    /// (the shot's speed for every model, once in m/s). The thesis
    /// model's cue owns the formula (<see cref="ThesisCue.StrokeSpeed"/>); the game only measures d and t.
    /// </summary>
    public static double Formel31(double distancePixels, double milliseconds) =>
        ThesisCue.StrokeSpeed((float)distancePixels, (float)milliseconds);
}
