using Billiards.Core.Mathematics;
using Billiards.Core.Physics;

namespace Billiards.Core.Cue;

/// <summary>
/// The cue's strike on the cue ball as an instantaneous point impulse (physics-standard-model.md,
/// "Cue strike"): ball velocity and spin from cue speed, tip offset and elevation, plus squirt.
/// </summary>
/// <remarks>
/// Sources: Alciatore TP A-30 (speed and spin from the tip's offset; Leckie and Greenspan's form
/// with elevation, as pooltool's <c>cue_strike</c>) and TP A-31 (squirt with the cue's end mass).
/// Frame used here: i to the right of the aim line, j along it, k up; the tip touches the sphere at
/// (a, -c, b) from the centre and pushes along (0, cos theta, -sin theta). The impulse's torque
/// gives w = v / (I/m) ((c sin theta - b cos theta) i + a sin theta j + a cos theta k), which is
/// the spec's (-c sin theta + b cos theta, a sin theta, -a cos theta) written in the pooltool frame
/// (x to the left, y back along the cue, z up) where a is measured to the left. The impulse's
/// downward part drives the ball into the slate at v sin theta (<see cref="Outcome.IntoSlate"/>),
/// and <see cref="Outcome.Velocity"/> is the rest, v cos theta along the bed. The standard model
/// lands the ball at once on the slate, which returns it with e_t and its friction (a steep, fast
/// stroke jumps); a model without flight lets the bed take the downward part.
/// </remarks>
public static class CueStrike
{
    /// <summary>The ball's velocity and spin just after the strike.</summary>
    /// <param name="Velocity">Velocity of the centre (m/s), in the bed plane.</param>
    /// <param name="Spin">Angular velocity (rad/s).</param>
    /// <param name="IntoSlate">The downward speed v sin theta the strike drives the ball into the slate with (m/s).</param>
    public readonly record struct Outcome(Vec3 Velocity, Vec3 Spin, double IntoSlate = 0);

    /// <summary>
    /// Speed factor of TP A-30: v = 2 V0 / (1 + m/M + (a^2 + (b cos t)^2 + (c sin t)^2 - 2 b c cos t sin t) / (I/m)),
    /// with the offsets a (side) and b (height) in metres and c the contact's depth behind the centre.
    /// </summary>
    /// <param name="cueSpeed">V0 (m/s).</param>
    /// <param name="a">Side offset of the contact (m).</param>
    /// <param name="b">Height offset of the contact (m).</param>
    /// <param name="elevation">Cue elevation theta (rad).</param>
    /// <param name="p">Ball and cue masses, ball radius.</param>
    /// <returns>The ball speed v (m/s) along the cue.</returns>
    public static double BallSpeed(double cueSpeed, double a, double b, double elevation, PhysicsParams p)
    {
        double r = p.R;
        double c = Math.Sqrt(Math.Max(0, r * r - a * a - b * b));
        double cos = DeterministicMath.Cos(elevation);
        double sin = DeterministicMath.Sin(elevation);
        double lever = a * a + (b * cos) * (b * cos) + (c * sin) * (c * sin) - 2 * b * c * cos * sin;
        double inertiaPerMass = 0.4 * r * r;
        return 2 * cueSpeed / (1 + p.M / p.CueMass + lever / inertiaPerMass);
    }

    /// <summary>
    /// Squirt angle (rad, TP A-31): atan(2.5 a sqrt(1 - a^2) / (1 + m/m_e + 2.5 (1 - a^2))), with a
    /// the side offset as a fraction of R. Positive for a positive offset; the ball then leaves
    /// on the other side of the aim line.
    /// </summary>
    /// <param name="side">Side offset as a fraction of R (positive to the right).</param>
    /// <param name="massRatio">m / m_e, ball mass over the cue's end mass.</param>
    public static double SquirtAngle(double side, double massRatio)
    {
        double oneMinus = 1 - side * side;
        return DeterministicMath.Atan(2.5 * side * Math.Sqrt(Math.Max(0, oneMinus)) / (1 + massRatio + 2.5 * oneMinus));
    }

    /// <summary>The cue ball's velocity and spin from a shot (see the class remarks for the frame).</summary>
    public static Outcome Strike(ShotSpec shot, PhysicsParams p)
    {
        double r = p.R;
        double a = shot.TipSide * r;
        double b = shot.TipHeight * r;
        double c = Math.Sqrt(Math.Max(0, r * r - a * a - b * b));
        double theta = shot.ElevationDeg * Math.PI / 180;
        double cos = DeterministicMath.Cos(theta);
        double sin = DeterministicMath.Sin(theta);
        double v = BallSpeed(shot.Speed, a, b, theta, p);
        double k = v / (0.4 * r * r);

        // Right english squirts the ball to the left: turn the whole strike anticlockwise.
        double squirt = SquirtAngle(shot.TipSide, p.M / p.CueEndMass);
        double phi = shot.AimDeg * Math.PI / 180 + squirt;
        var j = new Vec3(DeterministicMath.Cos(phi), DeterministicMath.Sin(phi), 0);
        var i = new Vec3(j.Y, -j.X, 0);

        var velocity = j * (v * cos);
        var spin = i * (k * (c * sin - b * cos)) + j * (k * a * sin) + new Vec3(0, 0, k * a * cos);
        return new Outcome(velocity, spin, v * sin);
    }
}
