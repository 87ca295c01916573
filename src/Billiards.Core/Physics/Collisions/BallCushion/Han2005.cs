using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallCushion;

/// <summary>
/// Han's ball-cushion impact: the cushion touches the ball above its centre, at angle
/// theta_a = asin(h / R - 1); a normal impulse with restitution e_c and a Coulomb friction impulse
/// (coefficient f_c) that either stops the contact's slip (sticking) or slides along it.
/// </summary>
/// <remarks>
/// Source: Han, I. (2005) "Dynamics in carom and three cushion billiards", Journal of Mechanical
/// Science and Technology 19(4), 976-984, eqs. 14-20, in the form of physics-standard-model.md and
/// pooltool's <c>han_2005</c> (which the spec follows except that the sliding impulse is along the
/// slip s/|s|, as in Han's paper). Cushion frame: x along the normal into the cushion, z up,
/// y = z x x. The impulse only changes v_x, v_y (the ball stays on the bed) and w. The restitution
/// is the parameters' <see cref="PhysicsParams.CushionE"/>: Han's constant e_c, or the presets'
/// restitution falling with the normal speed as measured (Mathavan, Jackson and Parkin 2009).
/// </remarks>
public sealed class Han2005 : IBallCushionModel
{
    /// <summary>The shared instance (the model has no state).</summary>
    public static Han2005 Instance { get; } = new();

    /// <inheritdoc />
    public string Name => "han-2005";

    /// <inheritdoc />
    public void Resolve(ref BallState ball, Vec3 normal, double height, PhysicsParams p)
    {
        double r = p.R;
        double m = p.M;
        double sinA = Math.Clamp(height / r - 1, -1, 1);
        double cosA = Math.Sqrt(1 - sinA * sinA);

        // Frame: ex into the cushion, ey = z x ex, ez = z. Both the velocity and the spin
        // (a pseudovector) transform alike under this proper rotation.
        var ex = -normal.XY.Normalized();
        var ey = new Vec3(-ex.Y, ex.X, 0);
        var v = new Vec3(Vec3.Dot(ball.Velocity, ex), Vec3.Dot(ball.Velocity, ey), ball.Velocity.Z);
        var w = new Vec3(Vec3.Dot(ball.Spin, ex), Vec3.Dot(ball.Spin, ey), ball.Spin.Z);

        // Slip of the contact point in the contact plane, and the normal approach speed (eq. 14).
        double sx = v.X * sinA - v.Z * cosA + r * w.Y;
        double sy = -v.Y - r * w.Z * cosA + r * w.X * sinA;
        double c = v.X * cosA;
        if (c <= 0)
        {
            return; // not approaching: no impact
        }

        // Effective inverse masses for the tangential (A) and normal (B) directions (eq. 16).
        double invA = 2 * m / 7;
        double invB = m;
        // e_c is constant, or falls with the normal approach speed as measured (PhysicsParams.CushionE).
        double pzE = (1 + p.CushionE(v.X)) * c * invB;
        double s = Math.Sqrt(sx * sx + sy * sy);
        double pzS = s * invA;
        double pxE, pyE;
        if (pzS <= p.FC * pzE)
        {
            // Sticking: the friction impulse stops the slip.
            pxE = sx * invA;
            pyE = sy * invA;
        }
        else
        {
            // Sliding: Coulomb friction along the slip.
            pxE = p.FC * pzE * sx / s;
            pyE = p.FC * pzE * sy / s;
        }

        // Back to the cushion frame: the impulse on the ball.
        double px = -pxE * sinA - pzE * cosA;
        double py = pyE;
        double pz = pxE * cosA - pzE * sinA;

        var vNew = new Vec3(v.X + px / m, v.Y + py / m, 0);
        // Angular impulse R (cos a, 0, sin a) x P over I.
        double k = r / p.Inertia;
        var wNew = new Vec3(
            w.X - k * py * sinA,
            w.Y + k * (px * sinA - pz * cosA),
            w.Z + k * py * cosA);

        ball.Velocity = ex * vNew.X + ey * vNew.Y;
        ball.Spin = ex * wNew.X + ey * wNew.Y + new Vec3(0, 0, wNew.Z);
    }
}
