using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallTable;

/// <summary>
/// A ball landing on the bed or on a rail's top (or driven into the bed by an elevated cue): a
/// frictional, inelastic impact at the contact point R from the centre against the contact
/// normal. The normal speed reverses scaled by e_t; the surface's friction acts during the impulse
/// against the contact point's slip, with Coulomb's limit mu_s times the normal impulse and never
/// beyond the impulse that stops the slip.
/// </summary>
/// <remarks>
/// Source: pooltool's frictional-inelastic ball-table model (<c>physics/resolve/ball_table</c>),
/// with the slip and no-slip cases of a rigid sphere's point impact on a plane of normal n: per
/// unit mass the normal impulse is (1 + e_t) |v . n|; a tangential impulse J changes the contact
/// point's slip u = v + R (n x w) (its part across n) by 7/2 J (v by J, and w by
/// -(5 / 2R) n x J), so the slip stops at |J| = 2 |u| / 7, and the impact slides throughout when
/// mu_s (1 + e_t) |v . n| is less. e_t defaults to 0.5 (Dr Dave Alciatore's measured figure).
/// On the bed (n = z) this is exactly the planar form, bit for bit.
/// </remarks>
public sealed class FrictionalLanding : IBallTableModel
{
    /// <summary>The shared instance (the model has no state).</summary>
    public static FrictionalLanding Instance { get; } = new();

    /// <inheritdoc />
    public string Name => "frictional-inelastic";

    /// <inheritdoc />
    public double Resolve(ref BallState ball, Vec3 normal, PhysicsParams p)
    {
        ArgumentNullException.ThrowIfNull(p);
        double r = p.R;
        double impact = Math.Max(-Vec3.Dot(ball.Velocity, normal), 0);
        double normalImpulse = (1 + p.ET) * impact;
        var u = ball.Velocity + Vec3.Cross(normal, ball.Spin) * r;
        u -= normal * Vec3.Dot(u, normal);
        double slip = u.Length;
        if (slip > 0 && normalImpulse > 0)
        {
            double j = Math.Min(p.MuS * normalImpulse, slip / 3.5);
            var impulse = new Vec3(-j * u.X / slip, -j * u.Y / slip, -j * u.Z / slip);
            ball.Velocity += impulse;
            ball.Spin -= Vec3.Cross(normal, impulse) * (2.5 / r);
        }
        // The normal speed after the impact: e_t times the approach, away from the surface.
        ball.Velocity -= normal * Vec3.Dot(ball.Velocity, normal);
        ball.Velocity += normal * (p.ET * impact);
        return impact;
    }
}
