using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Standard;

namespace Billiards.Core.Physics.Collisions.BallTable;

/// <summary>
/// A ball landing on the bed (or driven into it by an elevated cue): a frictional, inelastic
/// impact at the contact point below the centre. The vertical speed reverses scaled by e_t; the
/// bed's friction acts during the impulse against the contact point's slip, with Coulomb's
/// limit mu_s times the normal impulse and never beyond the impulse that stops the slip.
/// </summary>
/// <remarks>
/// Source: pooltool's frictional-inelastic ball-table model (<c>physics/resolve/ball_table</c>),
/// with the slip and no-slip cases of a rigid sphere's point impact on a plane: per unit mass the
/// normal impulse is (1 + e_t) |v_z|; a
/// tangential impulse J changes the contact point's slip u = v + R (z x w) by 7/2 J (v by J, and
/// w by -(5 / 2R) z x J), so the slip stops at |J| = 2 |u| / 7, and the impact slides throughout
/// when mu_s (1 + e_t) |v_z| is less. e_t defaults to 0.5 (Dr Dave Alciatore's measured figure).
/// </remarks>
public static class FrictionalLanding
{
    /// <summary>
    /// Lands the ball: puts its centre at z = R, applies the impact, and leaves it airborne on the
    /// rebound when that would lift it at least 5 mm, else on the bed (sliding, rolling, spinning
    /// or at rest). Returns the vertical speed at impact (m/s, not negative).
    /// </summary>
    public static double Land(ref BallState b, in MotionConstants k)
    {
        double impact = Math.Max(-b.Velocity.Z, 0);
        b.Position = b.Position with { Z = k.R };
        double normal = (1 + k.TableRestitution) * impact;
        var u = BallMotion.Slip(b, k.R);
        double slip = u.LengthXY;
        if (slip > 0 && normal > 0)
        {
            double j = Math.Min(k.MuS * normal, slip / 3.5);
            double jx = -j * u.X / slip, jy = -j * u.Y / slip;
            double spin = 2.5 / k.R;
            b.Velocity = new Vec3(b.Velocity.X + jx, b.Velocity.Y + jy, b.Velocity.Z);
            b.Spin = new Vec3(b.Spin.X + spin * jy, b.Spin.Y - spin * jx, b.Spin.Z);
        }
        double rebound = k.TableRestitution * impact;
        if (rebound >= k.BounceThreshold)
        {
            b.Velocity = b.Velocity with { Z = rebound };
            b.State = MotionState.Airborne;
        }
        else
        {
            b.Velocity = b.Velocity.XY;
            b.State = MotionState.Sliding; // whatever it was, Classify decides anew on the bed
            BallMotion.Classify(ref b, k);
        }
        return impact;
    }

    /// <summary>
    /// <see cref="Land"/>, logged: a <see cref="EventKind.BallTable"/> event with the impact speed
    /// and, when the ball bounces, a <see cref="EventKind.BallAirborne"/> event with its rebound.
    /// </summary>
    internal static void LandLogged(ref BallState b, in MotionConstants k, EventLog log, BallId id, double time)
    {
        double impact = Land(ref b, k);
        log.Add(new SimEvent(time, EventKind.BallTable, id, id, -1, impact));
        if (b.State == MotionState.Airborne)
        {
            log.Add(new SimEvent(time, EventKind.BallAirborne, id, id, -1, b.Velocity.Z));
        }
    }
}
