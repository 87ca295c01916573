using System.Numerics;
using Billiards.Core.Balls;

namespace Billiards.App.Camera;

/// <summary>
/// The view while the balls roll, as a television camera follows a shot: from the stroke's
/// view behind the cue it rises and backs off along the shot's line, and looks at the moving
/// balls (their centre, weighted by speed, so the fastest leads), farther back the more they
/// spread. It eases towards that view (it never jumps), stays below the lamps and above the rail
/// and inside the room, and holds where the last ball stopped.
/// </summary>
public sealed class ChaseView
{
    /// <summary>Speed below which a ball is not followed (m/s).</summary>
    public const double MovingSpeed = 0.02;

    /// <summary>Angle the view looks down at the balls once it has risen (deg).</summary>
    public const double PitchDegrees = 32;

    /// <summary>Nearest and farthest distance from the followed point (m).</summary>
    public const double MinDistance = 0.9, MaxDistance = 1.7;

    /// <summary>Metres of distance per metre the moving balls spread from their centre.</summary>
    public const double SpreadFactor = 0.8;

    /// <summary>Highest eye above the bed (m): below the lamps' shades, which hang at 0.9 m.</summary>
    public const double MaxHeight = 0.78;

    /// <summary>Time constant with which the looked-at point follows the balls (s).</summary>
    public const double FollowSeconds = 0.35;

    /// <summary>Time constant with which the eye moves to its place (s).</summary>
    public const double EyeSeconds = 0.6;

    private Vector3 _direction;
    private double _distance;

    /// <summary>The eye (m).</summary>
    public Vector3 Eye { get; private set; }

    /// <summary>The point looked at (m).</summary>
    public Vector3 Target { get; private set; }

    /// <summary>Starts from the view at the stroke: the eye behind the cue, looking at the cue ball.</summary>
    public void Start(Vector3 eye, Vector3 target)
    {
        Eye = eye;
        Target = target;
        var along = new Vector3(target.X - eye.X, target.Y - eye.Y, 0);
        _direction = along.LengthSquared() > 1e-8f ? Vector3.Normalize(along) : Vector3.UnitX;
        _distance = Math.Clamp(new Vector2(along.X, along.Y).Length(), MinDistance, MaxDistance);
    }

    /// <summary>
    /// Moves the view on by <paramref name="dt"/> seconds towards the balls now rolling;
    /// <paramref name="halfLength"/> and <paramref name="halfWidth"/> are the bed's (m), the eye kept
    /// within <paramref name="wallClearance"/> of the bed's edges and above <paramref name="lowest"/> (m).
    /// </summary>
    public void Follow(ReadOnlySpan<BallState> balls, double dt, double halfLength, double halfWidth, double wallClearance, double lowest)
    {
        var sum = Vector3.Zero;
        double weights = 0;
        foreach (var b in balls)
        {
            double speed = b.Velocity.Length;
            if (b.IsPocketed || speed < MovingSpeed || Math.Abs(b.Position.X) > halfLength + 0.3 || Math.Abs(b.Position.Y) > halfWidth + 0.3)
            {
                continue;
            }
            sum += b.Position.ToVector3() * (float)speed;
            weights += speed;
        }
        if (weights <= 0)
        {
            return; // nothing rolls on the bed: hold the view
        }
        var focus = sum / (float)weights;
        double spread = 0;
        foreach (var b in balls)
        {
            if (!b.IsPocketed && b.Velocity.Length >= MovingSpeed && Math.Abs(b.Position.X) <= halfLength + 0.3 && Math.Abs(b.Position.Y) <= halfWidth + 0.3)
            {
                spread = Math.Max(spread, Vector3.Distance(b.Position.ToVector3(), focus));
            }
        }
        float follow = (float)(1 - Math.Exp(-dt / FollowSeconds));
        float ease = (float)(1 - Math.Exp(-dt / EyeSeconds));
        Target += (focus - Target) * follow;
        _distance += (Math.Clamp(MinDistance + (SpreadFactor * spread), MinDistance, MaxDistance) - _distance) * ease;
        double pitch = PitchDegrees * Math.PI / 180;
        var wanted = Target - (_direction * (float)(_distance * Math.Cos(pitch))) + new Vector3(0, 0, (float)(_distance * Math.Sin(pitch)));
        wanted.X = (float)Math.Clamp(wanted.X, -(halfLength + wallClearance), halfLength + wallClearance);
        wanted.Y = (float)Math.Clamp(wanted.Y, -(halfWidth + wallClearance), halfWidth + wallClearance);
        wanted.Z = (float)Math.Clamp(wanted.Z, lowest, Math.Max(lowest, MaxHeight));
        Eye += (wanted - Eye) * ease;
    }
}
