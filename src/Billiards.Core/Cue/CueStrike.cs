using Billiards.Core.Mathematics;
using Billiards.Core.Physics;

namespace Billiards.Core.Cue;

/// <summary>
/// The cue's strike on the cue ball as an instantaneous point impulse (physics-standard-model.md,
/// "Cue strike"): ball velocity and spin from cue speed, tip offset and elevation, plus squirt, and
/// the miscue beyond the tip's limit.
/// </summary>
/// <remarks>
/// Sources: Alciatore TP A-30 (speed and spin from the tip's offset, with the tip's restitution)
/// and TP A-31 (squirt with the cue's end mass). The offset (a, b) is in the cue's frame
/// (scene-format.md, as pooltool and TP A.30 measure it): i to the right of the aim line, the
/// cue's push d = (0, cos theta, -sin theta) in (i, j = along the aim, k = up), and the cue's "up"
/// u = (0, sin theta, cos theta), perpendicular to d. The cue's axis passes a R i + b R u from the
/// centre, so it meets the sphere at P = a i + b u - c d, c = sqrt(R^2 - a^2 - b^2): tip [0, 0]
/// strikes through the centre at any elevation. The impulse F d has the lever P x d = a (i x d) +
/// b (u x d) = a (sin theta j + cos theta k) - b i and |P x d|^2 = a^2 + b^2, so the ball leaves at
/// v = (1 + e_tip) V0 / (1 + m/M + (a^2 + b^2) / (I/m)) along d and spins at
/// w = v / (I/m) (-b i + a sin theta j + a cos theta k). (The spec's face-frame formula is the same
/// after b_cue = b_face cos theta - c_face sin theta.) The impulse's downward part drives the ball
/// into the slate at v sin theta (<see cref="Outcome.IntoSlate"/>), and <see cref="Outcome.Velocity"/>
/// is the rest, v cos theta along the bed.
/// Miscue: past <see cref="PhysicsParams.MiscueLimit"/> (TP A-30 finds the tip and ball no longer
/// separate cleanly beyond about 0.5-0.7 R; Dr Dave's "maximum cue tip offset", Coriolis part IV,
/// puts the chalked tip's limit at about half the radius) the tip slides off. Our model: the tip
/// keeps only the normal part of its push, which passes through the centre (no spin), and sliding
/// off it gives up most of it: the ball leaves along the cue at <see cref="MiscueSpeedFraction"/>
/// of a centre hit's speed, without spin or squirt.
/// </remarks>
public static class CueStrike
{
    /// <summary>The ball's velocity and spin just after the strike.</summary>
    /// <param name="Velocity">Velocity of the centre (m/s), in the bed plane.</param>
    /// <param name="Spin">Angular velocity (rad/s).</param>
    /// <param name="IntoSlate">The downward speed v sin theta the strike drives the ball into the slate with (m/s).</param>
    /// <param name="Miscue">Whether the tip slid off (the offset was past the miscue limit).</param>
    public readonly record struct Outcome(Vec3 Velocity, Vec3 Spin, double IntoSlate = 0, bool Miscue = false);

    /// <summary>A miscued ball's speed as a fraction of a centre hit's (ours; see the class remarks).</summary>
    public const double MiscueSpeedFraction = 0.25;

    /// <summary>Whether the tip offset [side, height] (fractions of R) is past <paramref name="limit"/>: a miscue.</summary>
    public static bool IsMiscue(double side, double height, double limit) => (side * side) + (height * height) > limit * limit;

    /// <summary>Whether <paramref name="shot"/> miscues under <paramref name="p"/>.</summary>
    public static bool IsMiscue(ShotSpec shot, PhysicsParams p)
    {
        ArgumentNullException.ThrowIfNull(shot);
        ArgumentNullException.ThrowIfNull(p);
        return IsMiscue(shot.TipSide, shot.TipHeight, p.MiscueLimit);
    }

    /// <summary>
    /// Ball speed of TP A-30 in the cue's frame: v = (1 + e_tip) V0 / (1 + m/M + (a^2 + b^2) / (I/m)),
    /// with the offsets a (side) and b (height) in metres.
    /// </summary>
    /// <param name="cueSpeed">V0 (m/s).</param>
    /// <param name="a">Side offset of the cue's axis (m).</param>
    /// <param name="b">Height offset of the cue's axis, perpendicular to it (m).</param>
    /// <param name="p">Ball and cue masses, ball radius, tip restitution.</param>
    /// <returns>The ball speed v (m/s) along the cue.</returns>
    public static double BallSpeed(double cueSpeed, double a, double b, PhysicsParams p)
    {
        ArgumentNullException.ThrowIfNull(p);
        double inertiaPerMass = 0.4 * p.R * p.R;
        return (1 + p.ETip) * cueSpeed / (1 + p.M / p.CueMass + ((a * a) + (b * b)) / inertiaPerMass);
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
        ArgumentNullException.ThrowIfNull(shot);
        ArgumentNullException.ThrowIfNull(p);
        double r = p.R;
        double theta = shot.ElevationDeg * Math.PI / 180;
        double cos = DeterministicMath.Cos(theta);
        double sin = DeterministicMath.Sin(theta);
        if (p.Tip == TipFrame.Cue && IsMiscue(shot, p))
        {
            double weak = MiscueSpeedFraction * BallSpeed(shot.Speed, 0, 0, p);
            double aim = shot.AimDeg * Math.PI / 180;
            var along = new Vec3(DeterministicMath.Cos(aim), DeterministicMath.Sin(aim), 0);
            return new Outcome(along * (weak * cos), Vec3.Zero, weak * sin, Miscue: true);
        }
        double a = shot.TipSide * r;
        double b = shot.TipHeight * r;
        if (p.Tip == TipFrame.Face)
        {
            // A point (a, b) on the ball's face lies b cos t - c sin t above the cue's axis.
            double c = Math.Sqrt(Math.Max(0, (r * r) - (a * a) - (b * b)));
            b = (b * cos) - (c * sin);
        }
        double v = BallSpeed(shot.Speed, a, b, p);
        double k = v / (0.4 * r * r);

        // Right english squirts the ball to the left: turn the whole strike anticlockwise.
        double squirt = SquirtAngle(shot.TipSide, p.M / p.CueEndMass);
        double phi = shot.AimDeg * Math.PI / 180 + squirt;
        var j = new Vec3(DeterministicMath.Cos(phi), DeterministicMath.Sin(phi), 0);
        var i = new Vec3(j.Y, -j.X, 0);

        var velocity = j * (v * cos);
        var spin = i * (-k * b) + j * (k * a * sin) + new Vec3(0, 0, k * a * cos);
        return new Outcome(velocity, spin, v * sin);
    }
}
