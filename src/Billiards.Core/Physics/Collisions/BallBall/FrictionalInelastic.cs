using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallBall;

/// <summary>
/// Frictional, inelastic collision of two equal balls: restitution e_b along the line of centres,
/// and a friction impulse that opposes the slip of the contact points, which gives cut-induced and
/// spin-induced throw.
/// </summary>
/// <remarks>
/// Sources: Alciatore, TP and A-14 (throw), extended to both balls moving with full
/// vector spin as in pooltool's <c>FrictionalInelastic</c> ball-ball model; physics-standard-model.md
/// "Ball-ball collision". The friction impulse per unit mass is mu_b |v1n' - v2n'| (the separation
/// speed, as pooltool writes it), capped by the no-slip limit |slip| / 7 for each ball, which is
/// where the contact stops slipping (each ball's contact point changes by 7/2 of its velocity
/// change, and the two add). mu_b is constant or Alciatore's fit of the slip speed.
/// </remarks>
public sealed class FrictionalInelastic : IBallBallModel
{
    /// <summary>The shared instance (the model has no state).</summary>
    public static FrictionalInelastic Instance { get; } = new();

    /// <inheritdoc />
    public string Name => "frictional-inelastic";

    /// <summary>
    /// Resolves the impact. With a ball in the air the line of centres is taken in space and the
    /// vertical impulse is kept, so a ball struck from above is driven down (into the bed, which
    /// then returns it) and one struck from below is lifted.
    /// </summary>
    public void Resolve(ref BallState a, ref BallState b, PhysicsParams p)
    {
        ArgumentNullException.ThrowIfNull(p);
        bool inSpace = a.State == MotionState.Airborne || b.State == MotionState.Airborne;
        double r = p.R;
        var n = inSpace ? (b.Position - a.Position).Normalized() : (b.Position - a.Position).XY.Normalized();
        double v1n = Vec3.Dot(a.Velocity, n);
        double v2n = Vec3.Dot(b.Velocity, n);
        double e = p.EB;
        double v1nAfter = 0.5 * ((1 - e) * v1n + (1 + e) * v2n);
        double v2nAfter = 0.5 * ((1 + e) * v1n + (1 - e) * v2n);
        var v1 = a.Velocity + n * (v1nAfter - v1n);
        var v2 = b.Velocity + n * (v2nAfter - v2n);

        // Slip of ball 1's contact point (at +R n) relative to ball 2's (at -R n); the normal
        // impulse acts through both centres and leaves it unchanged. It lies in the tangent plane
        // (horizontal tangent and z): topspin and draw slip vertically.
        var dv = v1 - v2;
        var slip = dv - n * Vec3.Dot(dv, n) + r * Vec3.Cross(a.Spin + b.Spin, n);
        double slipSpeed = slip.Length;
        var w1 = a.Spin;
        var w2 = b.Spin;
        if (slipSpeed > 1e-12)
        {
            double mu = p.BallBallMu(slipSpeed);
            double j = Math.Min(mu * Math.Abs(v1nAfter - v2nAfter), slipSpeed / 7);
            var impulse = slip * (-j / slipSpeed); // per unit mass, on ball 1
            // Each ball's spin changes by (R n x J) / I for its own contact point; for ball 2 the
            // point is -R n and the impulse -J, so both spins change alike (like meshing gears).
            var dw = Vec3.Cross(n, impulse) * (2.5 / r);
            v1 += impulse;
            v2 -= impulse;
            w1 += dw;
            w2 += dw;
        }
        // On the bed the balls stay there: the vertical part of the friction would make them hop,
        // which the model leaves out (and the bed's reaction would mostly take).
        a.Velocity = inSpace ? v1 : v1.XY;
        b.Velocity = inSpace ? v2 : v2.XY;
        a.Spin = w1;
        b.Spin = w2;
    }
}
