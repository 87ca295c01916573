using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallCushion;

/// <summary>
/// Stronge's compliant frictional impact of a sphere on a half-space: a normal spring whose
/// restitution phase gives back e^2 of the compression energy, a tangential spring that stores
/// part of the contact's slip, and Coulomb friction (f_c) that limits the tangential spring's
/// force. The contact sticks and slips in turn; what the tangential spring gives back makes the
/// ball leave with more or less running spin than the rigid models say. The contact geometry is
/// Han's (the cushion touches the ball above its centre at sin(theta) = h / R - 1).
/// </summary>
/// <remarks>
/// <para>Source: Stronge, W. J. (2000) "Impact Mechanics", Cambridge University Press, the collinear
/// impact of compliant bodies with friction, as pooltool's <c>stronge_compliant</c> resolves it
/// (its default since 2026). Per unit mass, with beta_n = 1 and beta_t = 7/2 (a solid sphere's
/// contact point), time in units of 1/omega_n and velocities of the approach speed c:
/// the normal force is sin t in compression (t &lt;= pi/2) and sin(phi), phi = t/e + (pi/2)(1 - 1/e),
/// in restitution, which ends at t_f = (1 + e) pi/2 with the separation speed e c; the normal impulse
/// is 1 - cos t, then 1 - e cos phi. While the contact slides the tangential force is
/// -mu f_n (the slip g falls at mu beta_t f_n); while it sticks the slip and the tangential spring's
/// deflection u oscillate at omega_t (g' = -omega_t^2 u, u' = g). The contact sticks when the slip
/// meets the spring's rate (at once for g0 &lt;= mu eta^2 c, in compression for g0 &lt;= mu beta_t c, in
/// restitution for g0 &lt;= mu ((1 + e) beta_t - eta^2 / e) c, else never: gross slip), and slips again
/// when |u| reaches mu eta^2 f_n. The impact is collinear: the slip keeps its initial direction. The
/// frequency ratio omega_t / omega_n = <see cref="PhysicsParams.OmegaRatio"/> (pooltool's default
/// 1.8) sets the stiffness ratio eta^2 = beta_t / (beta_n ratio^2); the analysis holds for ratios in
/// (1, 2), where the contact sticks at most once and slips again at most once.</para>
/// <para>Every phase is in closed form; only the instant the stuck contact slips again is a root,
/// found by sampling the restitution period in 64 steps and bisecting to 1e-12 of the contact's
/// duration. Nothing is allocated.</para>
/// </remarks>
public sealed class StrongeCompliant : IBallCushionModel
{
    /// <summary>The shared instance (the model has no state).</summary>
    public static StrongeCompliant Instance { get; } = new();

    /// <summary>beta_t / beta_n of a solid sphere's contact point: 1 + m R^2 / I.</summary>
    public const double MassRatio = 3.5;

    private const int Samples = 64;

    /// <inheritdoc />
    public string Name => "stronge-compliant";

    /// <inheritdoc />
    public void Resolve(ref BallState ball, Vec3 normal, double height, PhysicsParams p)
    {
        ArgumentNullException.ThrowIfNull(p);
        var frame = new CushionFrame(normal, height, p.R);
        var v = frame.In(ball.Velocity) with { Z = 0 };
        var w = frame.In(ball.Spin);
        var n = frame.ContactNormal;
        var rc = n * p.R;
        double approach = Vec3.Dot(v, n);
        if (approach <= 0)
        {
            return; // not approaching: no impact
        }
        var contact = v + Vec3.Cross(w, rc);
        var slip = contact - n * Vec3.Dot(contact, n);
        double slipSpeed = slip.Length;
        var direction = slipSpeed > 1e-12 * approach ? slip / slipSpeed : Vec3.Zero;
        double finalSlip = approach * FinalSlip(slipSpeed / approach, p.FC, p.EC, p.OmegaRatio);

        // Normal impulse (1 + e) m c along -n; tangential impulse that changes the slip by
        // finalSlip - slipSpeed along its direction (the contact point's inverse mass is 7 / 2m).
        var impulse = n * (-(1 + p.EC) * p.M * approach) + direction * (p.M * (finalSlip - slipSpeed) / MassRatio);
        v += impulse / p.M;
        w += Vec3.Cross(rc, impulse) / p.Inertia;
        ball.Velocity = frame.Out(v with { Z = 0 });
        ball.Spin = frame.Out(w);
    }

    /// <summary>
    /// The slip speed at the end of the impact, as a fraction of the normal approach speed, for an
    /// initial slip of <paramref name="slipRatio"/> times the approach speed (>= 0, along the
    /// slip's initial direction; negative when the contact leaves slipping backwards).
    /// </summary>
    /// <param name="slipRatio">Initial slip speed over normal approach speed.</param>
    /// <param name="mu">Friction coefficient of the contact.</param>
    /// <param name="e">Normal restitution (energetic).</param>
    /// <param name="omegaRatio">omega_t / omega_n, in (1, 2).</param>
    public static double FinalSlip(double slipRatio, double mu, double e, double omegaRatio)
    {
        // Time in units of 1 / omega_n, velocities in units of the approach speed; beta_n = 1.
        e = Math.Max(e, 1e-6);
        const double B = MassRatio;
        double r = omegaRatio;
        double eta2 = B / (r * r);
        double q = slipRatio;
        double tc = Math.PI / 2, tf = (1 + e) * tc;
        if (mu <= 0)
        {
            return q; // no friction: the slip is untouched
        }

        // When the contact stops slipping: at once (q <= mu eta^2, the tangential spring takes the
        // slip), during compression (q <= mu B), during restitution, or never (gross slip).
        double ts;
        if (q <= mu * eta2)
        {
            ts = 0;
        }
        else if (q <= mu * B)
        {
            ts = DeterministicMath.Acos(Math.Clamp((q / mu - B) / (eta2 - B), -1, 1));
        }
        else
        {
            double d = eta2 / e - e * B;
            double x = d < 0 ? (q / mu - B) / d : double.NegativeInfinity;
            if (x < -1)
            {
                return q - mu * B * (1 + e); // gross slip: Coulomb friction throughout
            }
            ts = e * (DeterministicMath.Acos(x) - tc) + tc;
        }

        // Stuck: the tangential spring (deflection u) and the slip oscillate at omega_t from the
        // state where sliding stopped, where the spring force equals the friction limit.
        double gs = q - mu * B * NormalImpulse(ts, e);
        double us = mu * eta2 * NormalForce(ts, e);

        // The contact slips again when the spring's force reaches the friction limit once more:
        // the first root after ts of |u(t)| - mu eta^2 f_n(t) (it is >= 0 at tf, where f_n = 0).
        double lo = ts, hi = tf;
        for (int k = 1; k <= Samples; k++)
        {
            double t = ts + (tf - ts) * k / Samples;
            if (Excess(t, ts, gs, us, r, mu * eta2, e) >= 0)
            {
                hi = t;
                break;
            }
            lo = t;
        }
        for (int k = 0; k < 60 && hi - lo > 1e-12 * tf; k++)
        {
            double mid = 0.5 * (lo + hi);
            if (Excess(mid, ts, gs, us, r, mu * eta2, e) >= 0)
            {
                hi = mid;
            }
            else
            {
                lo = mid;
            }
        }
        double tr = hi;
        double phase = r * (tr - ts);
        double gr = gs * DeterministicMath.Cos(phase) - r * us * DeterministicMath.Sin(phase);
        double ur = us * DeterministicMath.Cos(phase) + gs / r * DeterministicMath.Sin(phase);

        // Slipping to the end with the spring's force at the friction limit.
        return gr - Math.Sign(ur) * mu * B * (NormalImpulse(tf, e) - NormalImpulse(tr, e));
    }

    private static double Excess(double t, double ts, double gs, double us, double r, double limit, double e)
    {
        double phase = r * (t - ts);
        double u = us * DeterministicMath.Cos(phase) + gs / r * DeterministicMath.Sin(phase);
        return Math.Abs(u) - limit * NormalForce(t, e);
    }

    // The restitution phase runs at omega_n / e, so that the spring gives back e^2 of the energy.
    private static double RestitutionPhase(double t, double e) => t / e + Math.PI / 2 * (1 - 1 / e);

    // Normal force per unit mass (in units of omega_n times the approach speed).
    private static double NormalForce(double t, double e) =>
        t <= Math.PI / 2 ? DeterministicMath.Sin(t) : Math.Max(0, DeterministicMath.Sin(RestitutionPhase(t, e)));

    // Normal impulse per unit mass since contact (in units of the approach speed): (1 + e) at the end.
    private static double NormalImpulse(double t, double e) =>
        t <= Math.PI / 2 ? 1 - DeterministicMath.Cos(t) : 1 - e * DeterministicMath.Cos(RestitutionPhase(t, e));
}
