using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Collisions.BallCushion;

/// <summary>
/// Mathavan, Jackson and Parkin's cushion impact: the impact integrated over the normal impulse at
/// the cushion, through compression and restitution, with Coulomb slip at the cushion contact
/// (friction f_c) and at the table contact (friction mu_s), the contact above the centre at
/// sin(theta) = h / R - 1.
/// </summary>
/// <remarks>
/// <para>Source: Mathavan, S., Jackson, M. R. and Parkin, R. M. (2010) "A theoretical analysis of
/// billiard ball dynamics under cushion impacts", Proc. IMechE Part C, J. Mechanical Engineering
/// Science 224(9), 1863-1873. The equations, per increment dP of the normal impulse at the cushion
/// contact I (frame: x into the cushion, z up; n_I = (cos theta, 0, sin theta) from the centre to I,
/// r_I = R n_I, r_C = -R z the table contact C):
/// slip at I, u_I = v + w x r_I, in I's tangent plane (directions y and t = (-sin theta, 0, cos theta));
/// slip at C, u_C = v + w x r_C; friction at I, F_I = -f_c dP u_I/|u_I|; the table's reaction from
/// vertical equilibrium, N_C = dP sin theta - F_I,z; friction at C, F_C = -mu_s N_C u_C/|u_C|;
/// m dv = (-n_I dP + F_I + F_C) in the bed plane; I dw = r_I x F_I + r_C x F_C.
/// Compression ends when the normal velocity at I, v . n_I, vanishes; restitution ends when the
/// work of the normal force since then, the integral of |v . n_I| dP, is e^2 times that of
/// compression (Stronge's energetic restitution). The authors fitted e = 0.98 and a cushion
/// friction of 0.14 to their measured rebounds and state the model for normal speeds up to
/// 2.5 m/s. Here e = e_c, the cushion friction is f_c and the table friction mu_s. pooltool's
/// <c>mathavan_2010</c> integrates the same equations.</para>
/// <para>Step: <see cref="ImpulseIntegration"/> (explicit Euler in the normal impulse, the last
/// step of each phase cut to end it exactly) with <see cref="CompressionSteps"/> equal steps of
/// m c0 / N through compression (c0: the normal approach speed at I) and as many through
/// restitution. A contact whose slip is below what one step of full friction removes (3.5 f_c dP / m
/// at I, 3.5 mu_s N_C / m at C) gets friction in proportion to its slip: a sticking contact then
/// settles instead of chattering from side to side, and the result depends smoothly on the ball's
/// state (1e-14 in, 1e-14 out), so the exact and event integrators agree. One run's error falls as
/// 1/N (5.2e-4 of the speed at N = 200, 5.1e-5 at 2000), smoothly, and that same smoothing
/// (proportional to the step) keeps a second-order step from doing better; so the model runs N and
/// 2N steps and takes Richardson's extrapolation 2 X(2N) - X(N), which cancels the 1/N term.
/// Error left, measured against the extrapolation at 16 times finer steps over speeds 0.5-4 m/s,
/// incoming angles 0-85 deg, draw to twice natural follow and side of -1..1 speed / R
/// (<c>Mathavan2010Tests.TheStepLeavesTheStatedError</c>): 2.3e-6 of the speed in velocity and
/// 1.2e-5 of speed / R in spin (bounds <see cref="StepErrorBound"/>, <see cref="SpinErrorBound"/>;
/// a single run at the former 200 steps left 5.2e-4 and 3.1e-3, millimetres over a shot). About 6
/// times the former 20-30 µs a collision (3N steps of 400). No state is kept and nothing is allocated.</para>
/// </remarks>
public sealed class Mathavan2010 : IBallCushionModel
{
    /// <summary>The shared instance (the model has no state).</summary>
    public static Mathavan2010 Instance { get; } = new();

    /// <summary>Steps of the normal impulse through compression of the coarser of the two runs (restitution takes about e times as many).</summary>
    public const int CompressionSteps = 400;

    /// <summary>The velocity error the extrapolated steps leave, as a fraction of the incoming speed (measured 2.3e-6; see the remarks).</summary>
    public const double StepErrorBound = 3e-6;

    /// <summary>The spin error the extrapolated steps leave, as a fraction of the incoming speed over R (measured 1.2e-5; see the remarks).</summary>
    public const double SpinErrorBound = 1.5e-5;

    /// <inheritdoc />
    public string Name => "mathavan-2010";

    /// <inheritdoc />
    public void Resolve(ref BallState ball, Vec3 normal, double height, PhysicsParams p) =>
        ResolveExtrapolated(ref ball, normal, height, p, CompressionSteps);

    /// <summary>The impact by Richardson's extrapolation of runs of <paramref name="steps"/> and twice as many steps: 2 X(2N) - X(N).</summary>
    public static void ResolveExtrapolated(ref BallState ball, Vec3 normal, double height, PhysicsParams p, int steps)
    {
        var coarse = ball;
        var fine = ball;
        Resolve(ref coarse, normal, height, p, steps);
        Resolve(ref fine, normal, height, p, 2 * steps);
        ball.Velocity = (fine.Velocity * 2) - coarse.Velocity;
        ball.Spin = (fine.Spin * 2) - coarse.Spin;
    }

    /// <summary>The impact integrated with <paramref name="steps"/> steps through compression (for measuring the step's error).</summary>
    public static void Resolve(ref BallState ball, Vec3 normal, double height, PhysicsParams p, int steps)
    {
        ArgumentNullException.ThrowIfNull(p);
        ArgumentOutOfRangeException.ThrowIfLessThan(steps, 1);
        var frame = new CushionFrame(normal, height, p.R);
        var state = new Motion(frame.In(ball.Velocity) with { Z = 0 }, frame.In(ball.Spin));
        double approach = Vec3.Dot(state.V, frame.ContactNormal);
        if (approach <= 0)
        {
            return; // not approaching: no impact
        }
        double step = p.M * approach / steps;
        state = ImpulseIntegration.Run(state, new Impact(frame, p, step), step, p.EC);
        ball.Velocity = frame.Out(state.V with { Z = 0 });
        ball.Spin = frame.Out(state.W);
    }

    // The ball's velocity and spin in the cushion frame (or their rates per unit impulse).
    private readonly record struct Motion(Vec3 V, Vec3 W);

    private readonly struct Impact : IImpact<Motion>
    {
        private readonly Vec3 _nI;
        private readonly Vec3 _rI;
        private readonly Vec3 _rC;
        private readonly Vec3 _t2;
        private readonly double _muCushion, _muTable, _invM, _invI, _stickI, _stickC;

        public Impact(CushionFrame frame, PhysicsParams p, double step)
        {
            _nI = frame.ContactNormal;
            _rI = _nI * p.R;
            _rC = new Vec3(0, 0, -p.R);
            // Tangent plane at I: the cushion's direction y, and the direction in the xz plane normal to n_I.
            _t2 = new Vec3(-frame.SinTheta, 0, frame.CosTheta);
            _muCushion = p.FC;
            _muTable = p.MuS;
            _invM = 1 / p.M;
            _invI = 1 / p.Inertia;
            // Below these slips one step of full friction would reverse the slip (the contact
            // point's inverse mass is 7 / 2m): friction then falls in proportion to the slip, so
            // that a sticking contact settles instead of chattering, and the result depends
            // smoothly on the ball's state (the event engine's integrators then agree).
            _stickI = 3.5 * _muCushion * step * _invM;
            _stickC = 3.5 * _muTable * step * _invM;
        }

        public double Approach(in Motion s) => Vec3.Dot(s.V, _nI);

        public Motion Add(in Motion s, in Motion rates, double h) => new(s.V + rates.V * h, s.W + rates.W * h);

        // The rates of velocity and spin per unit normal impulse at I, from the slips at I and C and
        // the table's reaction (the equations of the remarks).
        public Motion Slopes(in Motion s)
        {
            var uI = s.V + Vec3.Cross(s.W, _rI);
            double s1 = uI.Y, s2 = Vec3.Dot(uI, _t2);
            double sI = Math.Sqrt(s1 * s1 + s2 * s2);
            double dI = Math.Max(sI, _stickI);
            var fI = dI > 0 ? (new Vec3(0, s1, 0) + _t2 * s2) * (-_muCushion / dI) : Vec3.Zero;

            // The table presses up as much as the cushion's normal and friction forces press down.
            double reaction = Math.Max(0, _nI.Z - fI.Z);
            var uC = s.V + Vec3.Cross(s.W, _rC);
            double sC = uC.LengthXY;
            double dC = Math.Max(sC, _stickC * reaction);
            var fC = dC > 0 ? uC.XY * (-_muTable * reaction / dC) : Vec3.Zero;

            return new Motion((fI + fC - _nI).XY * _invM, (Vec3.Cross(_rI, fI) + Vec3.Cross(_rC, fC)) * _invI);
        }
    }
}
