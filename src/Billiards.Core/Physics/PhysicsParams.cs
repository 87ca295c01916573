using Billiards.Core.Mathematics;
namespace Billiards.Core.Physics;

/// <summary>How the ball-ball friction coefficient is chosen.</summary>
public enum BallBallFriction
{
    /// <summary>A constant <see cref="PhysicsParams.MuB"/>.</summary>
    Constant,
    /// <summary>Alciatore's fit: 0.009951 + 0.108 exp(-1.088 v_slip) (TP A-14).</summary>
    Alciatore,
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
    double ET = 0.5)
{
    /// <summary>Default ball mass (kg).</summary>
    public const double DefaultMass = 0.170097;

    /// <summary>Default ball radius (m).</summary>
    public const double DefaultRadius = 0.028575;

    /// <summary>The defaults.</summary>
    public static PhysicsParams Default { get; } = new();

    /// <summary>The symbol names a scene may override, in the order of the doc's table.</summary>
    public static IReadOnlyList<string> Symbols { get; } =
        ["m", "R", "mu_s", "mu_r", "mu_sp", "mu_b", "e_b", "e_c", "f_c", "g", "M", "m_e", "omega_ratio", "e_t"];

    /// <summary>Moment of inertia of a solid ball, 2/5 m R^2 (kg m^2).</summary>
    public double Inertia => 0.4 * M * R * R;

    /// <summary>Ball-ball friction for a given slip speed (m/s) at the contact.</summary>
    public double BallBallMu(double slipSpeed) =>
        MuBModel == BallBallFriction.Alciatore ? 0.009951 + 0.108 * DeterministicMath.Exp(-1.088 * slipSpeed) : MuB;
}
