using System.Globalization;
using Billiards.Core.Cue;

namespace Billiards.Core.Ai;

/// <summary>
/// Execution noise (scene-format.md, <c>--noise NAME[:K]</c>): independent zero-mean Gaussian
/// errors on the five parameters of a stroke, added to every stroke the computer plays (the break
/// too) before it is simulated. <c>fastfiz</c> is the computational-pool tournaments' model
/// (FastFiz's <c>Noise.h</c>): at 1x the standard deviations are aim 0.125 deg, cue elevation
/// 0.1 deg, cue speed 0.075 m/s, tip side and tip height 0.5 mm each; <see cref="Scale"/> multiplies
/// every one of them (<c>fastfiz:5</c> is the tournaments' high-noise setting).
/// </summary>
/// <remarks>
/// Each error is clamped to four standard deviations, as the levels' own errors are
/// (<see cref="SkillLevel"/>); the struck shot keeps a speed of at least 0.05 m/s, an elevation
/// from 0 to 89 deg, and its tip inside the miscue limit (<see cref="SkillLevel.MaxTip"/>): the noise
/// moves the stroke, it never turns it into one the cue cannot play.
/// </remarks>
/// <param name="Name">The model's name (<c>fastfiz</c>).</param>
/// <param name="Scale">The factor K on every standard deviation (0 or more).</param>
public sealed record ExecutionNoise(string Name, double Scale)
{
    /// <summary>The one model there is: the computational-pool tournaments' (FastFiz).</summary>
    public const string FastFiz = "fastfiz";

    /// <summary>The largest scale accepted.</summary>
    public const double MaxScale = 100;

    /// <summary>The aim's standard deviation at 1x (deg).</summary>
    public const double AimStdDeg1x = 0.125;

    /// <summary>The cue elevation's standard deviation at 1x (deg).</summary>
    public const double ElevationStdDeg1x = 0.1;

    /// <summary>The cue speed's standard deviation at 1x (m/s).</summary>
    public const double SpeedStd1x = 0.075;

    /// <summary>The standard deviation of each tip offset (side, height) at 1x (m).</summary>
    public const double TipStd1x = 0.0005;

    /// <summary>The aim's standard deviation (deg).</summary>
    public double AimStdDeg => AimStdDeg1x * Scale;

    /// <summary>The cue elevation's standard deviation (deg).</summary>
    public double ElevationStdDeg => ElevationStdDeg1x * Scale;

    /// <summary>The cue speed's standard deviation (m/s).</summary>
    public double SpeedStd => SpeedStd1x * Scale;

    /// <summary>The standard deviation of each tip offset (m).</summary>
    public double TipStd => TipStd1x * Scale;

    /// <summary>The model as the command line and the summary name it: <c>fastfiz:K</c>.</summary>
    public override string ToString() => string.Create(CultureInfo.InvariantCulture, $"{Name}:{Scale:R}");

    /// <summary>
    /// Parses <c>NAME[:K]</c> (<c>fastfiz</c>, <c>fastfiz:5</c>, <c>fastfiz:0.5</c>); null with
    /// <paramref name="problem"/> saying what is wrong.
    /// </summary>
    public static ExecutionNoise? TryParse(string text, out string problem)
    {
        ArgumentNullException.ThrowIfNull(text);
        int colon = text.IndexOf(':', StringComparison.Ordinal);
        string name = colon < 0 ? text : text[..colon];
        if (name != FastFiz)
        {
            problem = $"unknown noise model \"{name}\" (expected {FastFiz} or {FastFiz}:K)";
            return null;
        }
        double scale = 1;
        if (colon >= 0)
        {
            string k = text[(colon + 1)..];
            if (!double.TryParse(k, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out scale)
                || !double.IsFinite(scale) || scale < 0 || scale > MaxScale)
            {
                problem = $"the scale \"{k}\" is not a number from 0 to {MaxScale.ToString(CultureInfo.InvariantCulture)}";
                return null;
            }
        }
        problem = "";
        return new ExecutionNoise(name, scale);
    }

    /// <summary>
    /// The stroke struck when <paramref name="planned"/> is meant, on a ball of radius
    /// <paramref name="ballRadius"/> (m): five errors drawn from <paramref name="random"/> in the
    /// order aim, elevation, speed, tip side, tip height.
    /// </summary>
    public ShotSpec Apply(ShotSpec planned, PlannerRandom random, double ballRadius)
    {
        ArgumentNullException.ThrowIfNull(planned);
        ArgumentNullException.ThrowIfNull(random);
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(ballRadius);
        double aim = planned.AimDeg + AimStdDeg * random.NextClampedGaussian();
        double elevation = planned.ElevationDeg + ElevationStdDeg * random.NextClampedGaussian();
        double speed = planned.Speed + SpeedStd * random.NextClampedGaussian();
        double tip = TipStd / ballRadius;
        double side = planned.TipSide + tip * random.NextClampedGaussian();
        double height = planned.TipHeight + tip * random.NextClampedGaussian();
        (side, height) = SkillLevel.InsideMiscueLimit(side, height);
        return planned with
        {
            AimDeg = aim,
            ElevationDeg = Math.Clamp(elevation, 0, MaxElevationDeg),
            Speed = Math.Max(MinSpeed, speed),
            TipSide = side,
            TipHeight = height,
        };
    }

    /// <summary>The slowest stroke the noise leaves (m/s).</summary>
    public const double MinSpeed = 0.05;

    /// <summary>The steepest cue the noise leaves (deg).</summary>
    public const double MaxElevationDeg = 89;
}
