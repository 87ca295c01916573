using Billiards.Core.Mathematics;
namespace Billiards.Core.Physics;

/// <summary>How the ball-ball friction coefficient is chosen.</summary>
public enum BallBallFriction
{
    /// <summary>A constant <see cref="PhysicsParams.MuB"/>.</summary>
    Constant,
    /// <summary>Alciatore's fit: 0.009951 + 0.108 exp(-1.088 v_slip) (TP A-14).</summary>
    Alciatore,
    /// <summary>
    /// The same law fitted to measured stun throw (<see cref="PhysicsParams.MeasuredMuB"/>):
    /// 0.022 + 0.135 exp(-0.60 v_slip), from Alciatore's "Throw follow-up" I and II (Billiards Digest,
    /// July and August 2014, Diagram 2 of each) and Colenso's data in TP B.3. Symbol value "alciatore-2014".
    /// </summary>
    Measured,
}

/// <summary>Where a shot's tip offset is measured (scene-format.md).</summary>
public enum TipFrame
{
    /// <summary>In the cue's frame, from its axis through the ball's centre (the contract's).</summary>
    Cue,
    /// <summary>On the ball's face, seen from above the aim line: records made before the cue's frame (symbol value "face").</summary>
    Face,
}

/// <summary>How the ball-cushion restitution is chosen.</summary>
public enum CushionRestitution
{
    /// <summary>A constant <see cref="PhysicsParams.EC"/>.</summary>
    Constant,
    /// <summary>
    /// Falling with the normal speed as Mathavan, Jackson and Parkin (2009) measured
    /// (<see cref="PhysicsParams.MeasuredCushionRestitution"/>). Symbol value "mathavan-2009".
    /// </summary>
    Measured,
}

/// <summary>
/// Parameters of the standard model, with the defaults of physics-standard-model.md (those of
/// pooltool). SI units. A scene's <c>physics.params</c> overrides any of them by its symbol name.
/// </summary>
/// <param name="M">Ball mass m (kg). Symbol "m".</param>
/// <param name="R">Ball radius R (m). Symbol "R".</param>
/// <param name="MuS">Sliding friction, ball-cloth. Symbol "mu_s".</param>
/// <param name="MuR">Rolling resistance. Symbol "mu_r".</param>
/// <param name="MuSp">Spinning friction (m): spin about z decays at 5 mu_sp g / (2R). Symbol "mu_sp".</param>
/// <param name="MuB">Constant ball-ball friction. Symbol "mu_b" (a number, or "alciatore").</param>
/// <param name="MuBModel">Constant or Alciatore's fit.</param>
/// <param name="EB">Ball-ball restitution. Symbol "e_b".</param>
/// <param name="EC">Ball-cushion restitution. Symbol "e_c".</param>
/// <param name="FC">Ball-cushion friction. Symbol "f_c".</param>
/// <param name="G">Gravity (m/s^2). Symbol "g".</param>
/// <param name="CueMass">Cue mass M (kg). Symbol "M".</param>
/// <param name="CueEndMass">Cue end mass m_e for squirt (kg). Symbol "m_e".</param>
/// <param name="OmegaRatio">
/// Stronge's compliant cushion: the ratio omega_t / omega_n of the contact's tangential and normal
/// frequencies, in the open interval (1, 2); pooltool's default 1.8. Symbol "omega_ratio".
/// </param>
/// <param name="ET">
/// Ball-table restitution e_t: a landing ball leaves the bed again at e_t times its vertical impact
/// speed (Dr Dave's 0.5). Symbol "e_t".
/// </param>
/// <param name="ECModel">Constant e_c, or the measured fall with the normal speed (symbol "e_c": a number or "mathavan-2009").</param>
/// <param name="ETip">
/// Restitution of the cue tip on the ball: the ball leaves at (1 + e_tip) / 2 of an elastic
/// tip's speed. 1 here (TP A-30's elastic tip, pooltool's); the presets take Alciatore's 0.73 for a
/// leather tip (TP A-30, from high-speed video HSV B.42). Symbol "e_tip".
/// </param>
/// <param name="MiscueLimit">
/// The largest tip offset (fraction of R, in the cue's frame) the tip holds; beyond it the stroke
/// is a miscue (<see cref="Cue.CueStrike"/>). Symbol "miscue_limit".
/// </param>
/// <param name="Tip">
/// The frame of the tip offset: the cue's (the contract's), or the ball's face for records made
/// before it (symbol "tip_frame", "cue" or "face"; a record without "e_tip" is read as "face").
/// </param>
public sealed record PhysicsParams(
    double M = PhysicsParams.DefaultMass,
    double R = PhysicsParams.DefaultRadius,
    double MuS = 0.2,
    double MuR = 0.01,
    double MuSp = 4.0 / 9.0 * PhysicsParams.DefaultRadius,
    double MuB = 0.05,
    BallBallFriction MuBModel = BallBallFriction.Constant,
    double EB = 0.95,
    double EC = 0.85,
    double FC = 0.2,
    double G = 9.81,
    double CueMass = 0.567,
    double CueEndMass = PhysicsParams.DefaultMass / 30,
    double OmegaRatio = 1.8,
    double ET = 0.5,
    CushionRestitution ECModel = CushionRestitution.Constant,
    double ETip = 1,
    double MiscueLimit = 0.6,
    TipFrame Tip = TipFrame.Cue)
{
    /// <summary>Default ball mass (kg).</summary>
    public const double DefaultMass = 0.170097;

    /// <summary>Default ball radius (m).</summary>
    public const double DefaultRadius = 0.028575;

    /// <summary>
    /// The defaults of physics-standard-model.md's table (pooltool's): the analytic checks and the
    /// cross-checks with pooltool take these. A table's balls and cloth come from
    /// <see cref="Pool"/> or <see cref="Snooker"/> (<see cref="Balls.BallSet.DefaultParams"/>).
    /// </summary>
    public static PhysicsParams Default { get; } = new();

    /// <summary>
    /// Pool's balls and cloth, Alciatore's typical values ("Typical pool physical properties"; TP B.2
    /// and TP A-30): mu_s 0.2, mu_r 0.01, spin-down 10 rad/s^2 (TP B.2's measurement), e_b 0.95,
    /// the measured throw law (<see cref="BallBallFriction.Measured"/>), the measured cushion
    /// restitution (<see cref="CushionRestitution.Measured"/>), a 0.73 leather tip and a playing
    /// cue's end mass of m/21 (fitted to Squirt part II's large offset; see docs/reality.md).
    /// </summary>
    public static PhysicsParams Pool { get; } = new()
    {
        MuSp = SpinDecelerationToMuSp(10, DefaultRadius, 9.81),
        MuBModel = BallBallFriction.Measured,
        ECModel = CushionRestitution.Measured,
        ETip = 0.73,
        CueEndMass = DefaultMass / 21,
    };

    /// <summary>
    /// A snooker table's balls and cloth (52.5 mm, 142 g balls by default; the match set passes its
    /// own): Mathavan, Jackson and Parkin (2009) measured the rolling deceleration 0.124-0.126 m/s^2
    /// (mu_r 0.0127), the sliding one 1.75-2.40 m/s^2 (mu_s 0.212, their 2010 fit), and (2014, Fig. 4)
    /// a ball-ball restitution of 0.89 with a constant ball-ball friction of 0.05 for the clean
    /// snooker balls; the sidespin decays at 22 rad/s^2 (physics-standard-model.md).
    /// </summary>
    /// <param name="radius">Ball radius (m).</param>
    /// <param name="mass">Ball mass (kg).</param>
    public static PhysicsParams Snooker(double radius, double mass) => Pool with
    {
        R = radius,
        M = mass,
        MuS = 0.212,
        MuR = 0.0127,
        MuSp = SpinDecelerationToMuSp(22, radius, 9.81),
        EB = 0.89,
        MuB = 0.05,
        MuBModel = BallBallFriction.Constant,
        CueEndMass = mass / 21,
    };

    /// <summary>The spinning friction mu_sp (m) that decelerates spin about z at <paramref name="rate"/> (rad/s^2): 2 R rate / (5 g).</summary>
    public static double SpinDecelerationToMuSp(double rate, double radius, double g) => 2 * radius * rate / (5 * g);

    /// <summary>The deceleration of spin about z (rad/s^2): 5 mu_sp g / (2 R).</summary>
    public double SpinDeceleration => 5 * MuSp * G / (2 * R);

    /// <summary>The coefficients (a, b, c) of the measured throw law mu_b = a + b exp(-c v_slip) (<see cref="BallBallFriction.Measured"/>).</summary>
    public static (double A, double B, double C) MeasuredMuB => (0.022, 0.135, 0.60);

    /// <summary>The symbol names a scene may override, in the order of the doc's table.</summary>
    public static IReadOnlyList<string> Symbols { get; } =
        ["m", "R", "mu_s", "mu_r", "mu_sp", "mu_b", "e_b", "e_c", "f_c", "g", "M", "m_e", "omega_ratio", "e_t", "e_tip", "miscue_limit", "tip_frame"];

    /// <summary>Moment of inertia of a solid ball, 2/5 m R^2 (kg m^2).</summary>
    public double Inertia => 0.4 * M * R * R;

    /// <summary>Ball-ball friction for a given slip speed (m/s) at the contact.</summary>
    public double BallBallMu(double slipSpeed) => MuBModel switch
    {
        BallBallFriction.Alciatore => 0.009951 + 0.108 * DeterministicMath.Exp(-1.088 * slipSpeed),
        BallBallFriction.Measured => MeasuredMuB.A + (MeasuredMuB.B * DeterministicMath.Exp(-MeasuredMuB.C * slipSpeed)),
        _ => MuB,
    };

    /// <summary>The ball-cushion restitution for a normal approach speed (m/s): <see cref="EC"/>, or the measured law.</summary>
    public double CushionE(double normalSpeed) => ECModel == CushionRestitution.Measured ? MeasuredCushionRestitution(normalSpeed) : EC;

    /// <summary>
    /// The restitution that makes Han's model (<see cref="Collisions.BallCushion.Han2005"/>, nose at
    /// 0.64 of the diameter, f_c 0.2) return a rolling ball from a perpendicular cushion at the speed
    /// Mathavan, Jackson and Parkin measured (Am. J. Phys. 77 (2009) 788, Fig. 9: rebound
    /// y = -0.0877 x^2 + 1.1306 x - 0.0953 for incident speeds x of 0.28-3.5 m/s): the
    /// restitution found for each speed by bisection on the model and fitted (to 4 mm/s of the
    /// rebound) by e = 1.1955 - 0.0932 v - 0.1011 / v, capped at 1. Outside the measured speeds it
    /// keeps its value at their ends.
    /// </summary>
    /// <param name="normalSpeed">The ball's approach speed along the cushion's normal (m/s).</param>
    public static double MeasuredCushionRestitution(double normalSpeed)
    {
        double v = Math.Clamp(normalSpeed, 0.28, 3.5);
        return Math.Min(1, 1.1955 - (0.0932 * v) - (0.1011 / v));
    }
}
