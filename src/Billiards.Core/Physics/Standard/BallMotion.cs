using System.Numerics;
using System.Runtime.CompilerServices;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// The constants of ball-cloth motion, precomputed once from <see cref="PhysicsParams"/>.
/// </summary>
public readonly struct MotionConstants
{
    /// <summary>Takes the constants from the parameters.</summary>
    public MotionConstants(PhysicsParams p)
    {
        R = p.R;
        SlidingDeceleration = p.MuS * p.G;
        RollingDeceleration = p.MuR * p.G;
        SpinDeceleration = 5 * p.MuSp * p.G / (2 * p.R);
        G = p.G;
        MuS = p.MuS;
        TableRestitution = p.ET;
        BounceThreshold = Math.Sqrt(2 * p.G * BallMotion.LowestBounce);
    }

    /// <summary>Gravity g (m/s^2): a ball in the air accelerates at -g along z.</summary>
    public double G { get; }

    /// <summary>Ball-table friction mu_s, also the friction of a landing's impulse.</summary>
    public double MuS { get; }

    /// <summary>Ball-table restitution e_t.</summary>
    public double TableRestitution { get; }

    /// <summary>
    /// sqrt(2 g 0.005) (m/s): a ball leaving the bed slower than this would not rise 5 mm, and
    /// stays on the bed instead (physics-standard-model.md, "Flight").
    /// </summary>
    public double BounceThreshold { get; }

    /// <summary>Ball radius R (m).</summary>
    public double R { get; }

    /// <summary>mu_s g (m/s^2): the linear deceleration of a sliding ball.</summary>
    public double SlidingDeceleration { get; }

    /// <summary>mu_r g (m/s^2): the deceleration of a rolling ball.</summary>
    public double RollingDeceleration { get; }

    /// <summary>5 mu_sp g / (2R) (rad/s^2): the decay of spin about z, in every state.</summary>
    public double SpinDeceleration { get; }
}

/// <summary>
/// Closed-form motion of one ball on the cloth between collisions (physics-standard-model.md,
/// "Motion between collisions"): within a motion state the centre is an exact quadratic in time,
/// which is what lets the engine find contact times as polynomial roots.
/// </summary>
/// <remarks>
/// Equations from Leckie and Greenspan (2005) and Alciatore TP A-4 (sliding to rolling), as
/// pooltool's <c>evolve_ball_motion</c> uses them. Slip of the contact point:
/// u = v + R (z x w). Sliding: a = -mu_s g u_hat, dw_xy/dt = (5 mu_s g / 2R)(z x u_hat), and u
/// shrinks at 7/2 mu_s g along a fixed direction. Rolling: a = -mu_r g v_hat, w_xy = (z x v)/R.
/// </remarks>
public static class BallMotion
{
    /// <summary>Speeds (m/s) below this are zero when a state is classified after an impulse.</summary>
    public const double SpeedEpsilon = 1e-10;

    /// <summary>Spin rates (rad/s) below this are zero when a state is classified.</summary>
    public const double SpinEpsilon = 1e-10;

    /// <summary>Heights (m) of the centre above R that still count as on the bed: round-off of a landing.</summary>
    public const double HeightEpsilon = 1e-9;

    /// <summary>The lowest bounce (m) a ball rises to; a lower one ends on the bed.</summary>
    public const double LowestBounce = 0.005;

    /// <summary>Velocity of the contact point with the cloth, u = v + R (z x w), in the bed plane (m/s).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 Slip(in BallState b, double radius) =>
        new(b.Velocity.X - radius * b.Spin.Y, b.Velocity.Y + radius * b.Spin.X, 0);

    /// <summary>True for the states in which the centre moves.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Translates(MotionState s) => s is MotionState.Sliding or MotionState.Rolling or MotionState.Airborne;

    /// <summary>True for the states that end by themselves (sliding, rolling, spinning, airborne: it lands).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool IsActive(MotionState s) => s is MotionState.Sliding or MotionState.Rolling or MotionState.Spinning or MotionState.Airborne;

    /// <summary>True for the states out of play (pocketed, off the table).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool IsOut(MotionState s) => s is MotionState.Pocketed or MotionState.OffTable;

    /// <summary>
    /// Sets the state from the velocities after an impulse (strike or collision): airborne when the
    /// centre is above R or moves up (or down into the bed, which a landing at once resolves);
    /// otherwise sliding when the contact point slips, rolling when it does not, spinning when only
    /// w_z remains, stationary otherwise. Snaps the quantities the state implies (w_xy = z x v / R
    /// when rolling).
    /// </summary>
    public static void Classify(ref BallState b, in MotionConstants k)
    {
        if (IsOut(b.State))
        {
            return;
        }
        if (b.Position.Z > k.R + HeightEpsilon || b.Velocity.Z > SpeedEpsilon || b.Velocity.Z < -SpeedEpsilon)
        {
            b.State = MotionState.Airborne;
            return;
        }
        b.Velocity = b.Velocity.XY;
        var u = Slip(b, k.R);
        if (u.LengthXY > SpeedEpsilon)
        {
            b.State = MotionState.Sliding;
        }
        else if (b.Velocity.LengthXY > SpeedEpsilon)
        {
            b.State = MotionState.Rolling;
            b.Spin = new Vec3(-b.Velocity.Y / k.R, b.Velocity.X / k.R, b.Spin.Z);
        }
        else
        {
            b.Velocity = Vec3.Zero;
            b.State = Math.Abs(b.Spin.Z) > SpinEpsilon ? MotionState.Spinning : MotionState.Stationary;
            b.Spin = new Vec3(0, 0, b.State == MotionState.Spinning ? b.Spin.Z : 0);
        }
    }

    /// <summary>
    /// Time (s) until the current state ends by itself: sliding lasts 2|u|/(7 mu_s g), rolling
    /// |v|/(mu_r g), spinning |w_z| / (5 mu_sp g / 2R). Infinite for stationary and pocketed
    /// balls, or when the friction that would end the state is zero.
    /// </summary>
    public static double StateDuration(in BallState b, in MotionConstants k) => b.State switch
    {
        MotionState.Sliding => Duration(Slip(b, k.R).LengthXY, 3.5 * k.SlidingDeceleration),
        MotionState.Rolling => Duration(b.Velocity.LengthXY, k.RollingDeceleration),
        MotionState.Spinning => Duration(Math.Abs(b.Spin.Z), k.SpinDeceleration),
        MotionState.Airborne => LandingTime(b.Position.Z - k.R, b.Velocity.Z, k.G),
        _ => double.PositiveInfinity,
    };

    /// <summary>
    /// Time (s) until a ball whose centre is <paramref name="height"/> above its resting height,
    /// rising at <paramref name="vz"/>, lands: the positive root of height + vz t - g t^2 / 2,
    /// (vz + s) / g with s = sqrt(vz^2 + 2 g height), written as 2 height / (s - vz) when vz &lt; 0
    /// so that no digits cancel. 0 for a ball at the bed moving down.
    /// </summary>
    public static double LandingTime(double height, double vz, double g)
    {
        double h = Math.Max(height, 0);
        double s = Math.Sqrt(vz * vz + 2 * g * h);
        return vz >= 0 ? (vz + s) / g : 2 * h / (s - vz);
    }

    private static double Duration(double amount, double rate) => rate > 0 ? amount / rate : double.PositiveInfinity;

    /// <summary>
    /// Acceleration of the centre in the current state (m/s^2), constant until the state ends:
    /// r(t) = r0 + v0 t + a t^2 / 2.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vec3 Acceleration(in BallState b, in MotionConstants k)
    {
        switch (b.State)
        {
            case MotionState.Sliding:
                {
                    var u = Slip(b, k.R);
                    double s = u.LengthXY;
                    return s > 0 ? u * (-k.SlidingDeceleration / s) : Vec3.Zero;
                }
            case MotionState.Rolling:
                {
                    double s = b.Velocity.LengthXY;
                    return s > 0 ? b.Velocity * (-k.RollingDeceleration / s) : Vec3.Zero;
                }
            case MotionState.Airborne:
                return new Vec3(0, 0, -k.G);
            default:
                return Vec3.Zero;
        }
    }

    /// <summary>
    /// Advances the ball by <paramref name="dt"/> seconds in closed form, assuming its state does
    /// not end before then (the engine stops at state transitions). Spin about z decays to zero
    /// and then stays there. Integrates the orientation when <paramref name="trackOrientation"/>.
    /// </summary>
    public static void Advance(ref BallState b, double dt, in MotionConstants k, bool trackOrientation) =>
        Advance(ref b, dt, k, trackOrientation, Acceleration(b, k));

    /// <summary>
    /// As <see cref="Advance(ref BallState, double, in MotionConstants, bool)"/>, with the state's
    /// acceleration already known (<see cref="Acceleration"/> when the state began, constant until
    /// it ends): no square root or normalisation per call, which is what a fixed step costs.
    /// </summary>
    public static void Advance(ref BallState b, double dt, in MotionConstants k, bool trackOrientation, Vec3 acceleration)
    {
        if (dt <= 0)
        {
            return;
        }
        var spin0 = b.Spin;
        switch (b.State)
        {
            case MotionState.Sliding:
                {
                    b.Position += b.Velocity * dt + acceleration * (0.5 * dt * dt);
                    b.Velocity += acceleration * dt;
                    // dw_xy/dt = (5 mu_s g / 2R) (z x u_hat) with a = -mu_s g u_hat: (5 / 2R) (a_y, -a_x).
                    double alpha = 2.5 / k.R * dt;
                    b.Spin = new Vec3(b.Spin.X + alpha * acceleration.Y, b.Spin.Y - alpha * acceleration.X, b.Spin.Z);
                    break;
                }
            case MotionState.Rolling:
                b.Position += b.Velocity * dt + acceleration * (0.5 * dt * dt);
                b.Velocity += acceleration * dt;
                b.Spin = new Vec3(-b.Velocity.Y / k.R, b.Velocity.X / k.R, b.Spin.Z);
                break;
            case MotionState.Spinning:
                break;
            case MotionState.Airborne:
                // A parabola; nothing touches the ball, so its spin stays as it is.
                b.Position += b.Velocity * dt + acceleration * (0.5 * dt * dt);
                b.Velocity += acceleration * dt;
                if (trackOrientation)
                {
                    Rotate(ref b.Orientation, b.Spin * dt);
                }
                return;
            default:
                return;
        }
        DecaySpinZ(ref b, dt, k);
        if (trackOrientation)
        {
            Rotate(ref b.Orientation, (spin0 + b.Spin) * (0.5 * dt));
        }
    }

    /// <summary>Decays the spin about z by 5 mu_sp g / (2R) over <paramref name="dt"/> (s), stopping at zero.</summary>
    public static void DecaySpinZ(ref BallState b, double dt, in MotionConstants k)
    {
        double wz = b.Spin.Z;
        double decay = k.SpinDeceleration * dt;
        b.Spin = new Vec3(b.Spin.X, b.Spin.Y, Math.Abs(wz) > decay ? wz - Math.CopySign(decay, wz) : 0);
    }

    /// <summary>
    /// Rotates an orientation by the angle vector <paramref name="phi"/> (rad: axis times angle),
    /// in the table frame. Callers pass the mean angular velocity times the interval, which is exact
    /// for a spin along a fixed axis; its small change of axis while sliding does not matter for drawing.
    /// </summary>
    public static void Rotate(ref Quaternion q, Vec3 phi)
    {
        double angle = phi.Length;
        if (angle < 1e-12)
        {
            return;
        }
        var axis = phi / angle;
        // Quaternion.CreateFromAxisAngle's, with the sine and cosine of DeterministicMath (its
        // MathF calls differ across C runtimes).
        float half = (float)angle * 0.5f;
        var dq = new Quaternion(new Vector3((float)axis.X, (float)axis.Y, (float)axis.Z) * (float)DeterministicMath.Sin(half), (float)DeterministicMath.Cos(half));
        q = Quaternion.Normalize(dq * q);
    }

    /// <summary>
    /// Ends the current state at its transition time: sliding becomes rolling (or spinning or
    /// stationary when no velocity is left), rolling and spinning become spinning or stationary.
    /// Snaps the small remainders that round-off leaves, so the new state starts exactly.
    /// </summary>
    public static void EndState(ref BallState b, in MotionConstants k)
    {
        switch (b.State)
        {
            case MotionState.Sliding:
                if (b.Velocity.LengthXY > SpeedEpsilon)
                {
                    b.State = MotionState.Rolling;
                    b.Spin = new Vec3(-b.Velocity.Y / k.R, b.Velocity.X / k.R, b.Spin.Z);
                }
                else
                {
                    StopTranslation(ref b);
                }
                break;
            case MotionState.Rolling:
                StopTranslation(ref b);
                break;
            case MotionState.Spinning:
                b.Spin = Vec3.Zero;
                b.State = MotionState.Stationary;
                break;
        }
    }

    private static void StopTranslation(ref BallState b)
    {
        b.Velocity = Vec3.Zero;
        b.Spin = new Vec3(0, 0, Math.Abs(b.Spin.Z) > SpinEpsilon ? b.Spin.Z : 0);
        b.State = b.Spin.Z != 0 ? MotionState.Spinning : MotionState.Stationary;
    }
}
