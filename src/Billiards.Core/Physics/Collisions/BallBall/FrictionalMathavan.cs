using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallBall;

/// <summary>
/// Mathavan, Jackson and Parkin's collision of two balls on a rough table: the impact integrated
/// over the normal impulse through compression and restitution, with Coulomb slip between the
/// balls (mu_b) and, for the ball that the vertical part of that friction presses into the cloth,
/// between the ball and the table (mu_s).
/// </summary>
/// <remarks>
/// <para>Source: Mathavan, S., Jackson, M. R. and Parkin, R. M. (2014) "Numerical simulations of the
/// frictional collisions of solid balls on a rough surface", Sports Engineering 17(4), 227-237. The
/// equations, per increment dP of the normal impulse along the line of centres n (from a to b):
/// the slip of a's contact point over b's, u = v_a - v_b + R (w_a + w_b) x n, in the tangent plane;
/// the balls' friction on a, F = -mu_b dP u/|u| (on b, -F); its vertical part presses one ball into
/// the cloth, whose reaction |F_z| brings table friction -mu_s |F_z| s/|s| on that ball (s: the
/// slip of its table contact, v + w x (-R z)), and lifts the other, which has no table friction;
/// m dv_a = -n dP + F + F_table,a and m dv_b = n dP - F + F_table,b in the bed plane;
/// I dw = R n x F + (-R z) x F_table for both balls. Compression ends when the normal approach
/// speed vanishes; restitution ends when the work of the normal force since then is e^2 times that
/// of compression. Here e = e_b, the balls' friction is mu_b (constant, or Alciatore's fit of the
/// slip speed at each step) and the table friction mu_s. pooltool's <c>frictional_mathavan</c>
/// integrates the same equations.</para>
/// <para>Step: <see cref="ImpulseIntegration"/> (explicit Euler in the normal impulse, the last
/// step of each phase cut to end it exactly) with <see cref="CompressionSteps"/> equal steps of
/// m v_n / (2 N) through compression (m v_n / 2 is the compression impulse of two free equal balls)
/// and as many through restitution; below the slip that one step of full friction removes, friction
/// is in proportion to the slip (no chatter; the result depends smoothly on the state). Error left by the step, measured against 64 times finer steps
/// over speeds 0.5-8 m/s, cut angles 0-80 deg, draw, stun and follow with side of -1..1 speed / R
/// (<c>BallBallModelTests.TheMathavanStepLeavesTheStatedError</c>): 9.6e-5 of the speed in
/// velocity (bound <see cref="StepErrorBound"/>); it falls about as 1/N (4.8e-5 at N = 100). About
/// 4-8 µs a collision on the reference machine. No state is kept and nothing is allocated.</para>
/// <para>With a ball in the air the line of centres is taken in space and the balls move in space:
/// a ball in the air has no table friction, one on the bed has it only while the impact presses
/// it into the cloth.</para>
/// </remarks>
public sealed class FrictionalMathavan : IBallBallModel
{
    /// <summary>The shared instance (the model has no state).</summary>
    public static FrictionalMathavan Instance { get; } = new();

    /// <summary>Steps of the normal impulse through compression (restitution takes about e times as many).</summary>
    public const int CompressionSteps = 50;

    /// <summary>The velocity error the step leaves, as a fraction of the approach speed (measured 9.6e-5; see the remarks).</summary>
    public const double StepErrorBound = 2e-4;

    /// <inheritdoc />
    public string Name => "frictional-mathavan";

    /// <inheritdoc />
    public void Resolve(ref BallState a, ref BallState b, PhysicsParams p) => Resolve(ref a, ref b, p, CompressionSteps);

    /// <summary>The collision integrated with <paramref name="steps"/> steps through compression (for measuring the step's error).</summary>
    public static void Resolve(ref BallState a, ref BallState b, PhysicsParams p, int steps)
    {
        ArgumentNullException.ThrowIfNull(p);
        ArgumentOutOfRangeException.ThrowIfLessThan(steps, 1);
        // With a ball in the air the line of centres leaves the bed plane (see Impact.Slopes).
        var air = (a.State == MotionState.Airborne, b.State == MotionState.Airborne);
        bool inSpace = air.Item1 || air.Item2;
        var n = inSpace ? (b.Position - a.Position).Normalized() : (b.Position - a.Position).XY.Normalized();
        var state = inSpace ? new Pair(a.Velocity, a.Spin, b.Velocity, b.Spin) : new Pair(a.Velocity.XY, a.Spin, b.Velocity.XY, b.Spin);
        double approach = Vec3.Dot(state.Va - state.Vb, n);
        if (approach <= 0)
        {
            return; // separating: no impact
        }
        double step = 0.5 * p.M * approach / steps;
        state = ImpulseIntegration.Run(state, new Impact(n, p, step, inSpace, air.Item1, air.Item2), step, p.EB);
        a.Velocity = inSpace ? state.Va : state.Va.XY;
        a.Spin = state.Wa;
        b.Velocity = inSpace ? state.Vb : state.Vb.XY;
        b.Spin = state.Wb;
    }

    // Both balls' velocities and spins (or their rates per unit impulse).
    private readonly record struct Pair(Vec3 Va, Vec3 Wa, Vec3 Vb, Vec3 Wb);

    // Below the slips of one step of full friction (the balls' relative slip has inverse mass 7/m,
    // a table contact 7/2m), friction falls in proportion to the slip, so that a sticking contact
    // settles instead of chattering and the result depends smoothly on the balls' state.
    private readonly struct Impact(Vec3 n, PhysicsParams p, double step, bool inSpace, bool airA, bool airB) : IImpact<Pair>
    {
        public double Approach(in Pair s) => Vec3.Dot(s.Va - s.Vb, n);

        public Pair Add(in Pair s, in Pair rates, double h) =>
            new(s.Va + rates.Va * h, s.Wa + rates.Wa * h, s.Vb + rates.Vb * h, s.Wb + rates.Wb * h);

        // The rates of both balls' velocities and spins per unit normal impulse (the equations of the remarks).
        public Pair Slopes(in Pair s)
        {
            double r = p.R;
            // Slip of ball a's contact point (at +R n) over ball b's (at -R n), in the contact's tangent plane.
            var u = s.Va - s.Vb + Vec3.Cross(s.Wa + s.Wb, n) * r;
            u -= n * Vec3.Dot(u, n);
            double slip = u.Length;
            double mu = p.BallBallMu(slip);
            double d = Math.Max(slip, 7 * mu * step / p.M);
            var fa = d > 0 ? u * (-mu / d) : Vec3.Zero; // friction on a

            Vec3 ta, tb, forceA, forceB;
            if (inSpace)
            {
                // The line of centres in space (a ball in the air): each ball takes the whole force
                // of the normal impulse and the balls' friction, in space; a ball on the bed that
                // this force presses into the cloth gets the cloth's reaction (it stays on the bed)
                // and the table's friction with it; a ball in the air, or one the force lifts, has
                // no table contact.
                forceA = fa - n;
                forceB = n - fa;
                bool pressedA = !airA && forceA.Z < 0 && s.Va.Z <= 0;
                bool pressedB = !airB && forceB.Z < 0 && s.Vb.Z <= 0;
                ta = pressedA ? TableFriction(s.Va, s.Wa, -forceA.Z) : Vec3.Zero;
                tb = pressedB ? TableFriction(s.Vb, s.Wb, -forceB.Z) : Vec3.Zero;
                forceA = pressedA ? (forceA + ta).XY : forceA;
                forceB = pressedB ? (forceB + tb).XY : forceB;
            }
            else
            {
                // The vertical part of the friction presses one ball into the cloth, whose reaction brings
                // table friction on that ball; it lifts the other, which then has no table contact.
                ta = fa.Z < 0 ? TableFriction(s.Va, s.Wa, -fa.Z) : Vec3.Zero;
                tb = fa.Z > 0 ? TableFriction(s.Vb, s.Wb, fa.Z) : Vec3.Zero;
                forceA = (fa + ta - n).XY;
                forceB = (tb - fa + n).XY;
            }

            double invM = 1 / p.M, invI = 1 / p.Inertia;
            var down = new Vec3(0, 0, -r);
            var torqueBalls = Vec3.Cross(n * r, fa); // the same on both balls: (-R n) x (-fa)
            return new Pair(
                forceA * invM,
                (torqueBalls + Vec3.Cross(down, ta)) * invI,
                forceB * invM,
                (torqueBalls + Vec3.Cross(down, tb)) * invI);
        }

        // Friction of the table on a ball pressed into it with the given reaction.
        private Vec3 TableFriction(Vec3 v, Vec3 w, double reaction)
        {
            var slip = v + Vec3.Cross(w, new Vec3(0, 0, -p.R));
            double speed = slip.LengthXY;
            double d = Math.Max(speed, 3.5 * p.MuS * reaction * step / p.M);
            return d > 0 ? slip.XY * (-p.MuS * reaction / d) : Vec3.Zero;
        }
    }
}
