using Billiards.Core.Mathematics;
using Billiards.Core.Cue;

namespace Billiards.Core.Ai;

/// <summary>
/// A computer player's level, 1 (beginner) to 5 (strong professional): the human-like error of
/// its stroke and how hard it thinks.
/// </summary>
/// <remarks>
/// The error model: every executed shot is the planned one with independent Gaussian errors
/// added, zero mean, with the standard deviations below (the same in the search, which samples
/// the player's own error, and in play, where the error is applied to the shot actually struck).
/// <list type="table">
/// <listheader><term>level</term><description>aim (deg), speed (fraction of the cue speed), tip (fraction of R, each of side and height)</description></listheader>
/// <item><term>1</term><description>1.00, 0.12, 0.10</description></item>
/// <item><term>2</term><description>0.55, 0.08, 0.07</description></item>
/// <item><term>3</term><description>0.30, 0.05, 0.05</description></item>
/// <item><term>4</term><description>0.16, 0.035, 0.03</description></item>
/// <item><term>5</term><description>0.08, 0.02, 0.015</description></item>
/// </list>
/// The error is clamped to four standard deviations, and the tip to the miscue limit (0.6 R
/// from the centre). Lower levels also search less: fewer candidate shots, speeds, spins and
/// samples of their own error; levels 1 and 2 judge a shot by the referee's ruling alone, levels
/// 3 to 5 also by the next shot it leaves (one shot ahead), and a safety by the opponent's best reply;
/// levels 3 to 5 also aim by trial (<see cref="AimTrials"/>): they know where a shot really goes,
/// where levels 1 and 2 aim by the geometry. In the games with snookers level 5 attempts a pot only
/// when it is nearly sure (<see cref="SurePotChance"/>) or nothing else is much better, and plays safe otherwise.
/// </remarks>
/// <param name="Level">1 to 5.</param>
/// <param name="AimStdDeg">Standard deviation of the aim angle (deg).</param>
/// <param name="SpeedStdFraction">Standard deviation of the cue speed, as a fraction of the planned speed.</param>
/// <param name="TipStdFraction">Standard deviation of each tip offset (side, height), as a fraction of R.</param>
/// <param name="Candidates">Shots (target, pocket, kind) searched after the geometric ranking.</param>
/// <param name="Speeds">Speeds tried per candidate.</param>
/// <param name="Spins">Spin and elevation variants tried per candidate (1: centre ball only).</param>
/// <param name="Samples">Simulations per variant in the first round, each with its own error sample.</param>
/// <param name="RefineTop">Variants simulated again in the last round, from which the shot is chosen.</param>
/// <param name="RefineSamples">Extra simulations per variant of the last round.</param>
/// <param name="LookAhead">0: judge a shot by its ruling only; 1: also by the next shot it leaves.</param>
/// <param name="Placements">Cue-ball placements searched with ball in hand.</param>
/// <param name="ScreenTop">Variants simulated again in a middle round between the first and the last (0: none).</param>
/// <param name="ScreenSamples">Extra simulations per variant of the middle round.</param>
/// <param name="AimTrials">
/// Aims tried without error either side of each pot's geometric aim, <see cref="ShotPlanner.AimTrialStepDeg"/>
/// apart, to play the middle of the range that pots (0: the geometric aim as it is).
/// </param>
/// <param name="SurePotChance">
/// In the games whose policy plays safe below it (<see cref="PlannerPolicy.PlaysSafeBelowSurePot"/>), the pot chance below which
/// this player would rather play safe: a pot attempt loses <see cref="ShotPlanner.ShortfallWeight"/>
/// of score per unit of chance short of it (0: none; the pool games never use it).
/// </param>
/// <param name="FirstRoundSimulations">
/// Cap on the first round's simulations: with many variations (ball in hand searches several
/// placements) each gets fewer samples, at least one, and the later rounds sort them out.
/// </param>
public sealed partial record SkillLevel(
    int Level,
    double AimStdDeg,
    double SpeedStdFraction,
    double TipStdFraction,
    int Candidates,
    int Speeds,
    int Spins,
    int Samples,
    int RefineTop,
    int RefineSamples,
    int LookAhead,
    int Placements,
    int ScreenTop = 0,
    int ScreenSamples = 0,
    int AimTrials = 0,
    int FirstRoundSimulations = 1500,
    double SurePotChance = 0)
{
    /// <summary>
    /// The aim error (deg) a position is judged with when this player will shoot the next shot: the
    /// player's own aim error widened 2.5 times for the errors of speed and spin the look-ahead
    /// does not model, so that a strong player still prefers the easier of two shots it would make.
    /// </summary>
    public double PositionAimStdDeg => 2.5 * AimStdDeg;

    /// <summary>
    /// The aim error (deg) the opponent's reply to a miss or a safety is judged with: the player
    /// assumes an opponent at least as good as itself (<see cref="PositionAimStdDeg"/>) and at least
    /// as good as the reference player (<see cref="PlannerTable.ReferenceAimStdDeg"/>), so that a
    /// strong player fears leaving an open table more than a beginner does.
    /// </summary>
    public double OpponentAimStdDeg => Math.Min(PositionAimStdDeg, PlannerTable.ReferenceAimStdDeg);

    /// <summary>The lowest level.</summary>
    public const int Min = 1;

    /// <summary>The highest level.</summary>
    public const int Max = 5;

    /// <summary>The largest tip offset from the centre (fraction of R) before a miscue.</summary>
    public const double MaxTip = 0.6;

    /// <summary>Cue elevation (deg) from which a stroke counts as a jump stroke.</summary>
    public const double JumpTipElevationDeg = 30;

    private static readonly SkillLevel[] All =
    [
        new(1, 1.00, 0.12, 0.10, Candidates: 4, Speeds: 2, Spins: 1, Samples: 1, RefineTop: 2, RefineSamples: 2, LookAhead: 0, Placements: 2),
        new(2, 0.55, 0.08, 0.07, Candidates: 6, Speeds: 3, Spins: 1, Samples: 2, RefineTop: 3, RefineSamples: 4, LookAhead: 0, Placements: 3),
        new(3, 0.30, 0.05, 0.05, Candidates: 8, Speeds: 3, Spins: 3, Samples: 2, RefineTop: 6, RefineSamples: 8, LookAhead: 1, Placements: 4, AimTrials: 4),
        new(4, 0.16, 0.035, 0.03, Candidates: 10, Speeds: 4, Spins: 4, Samples: 3, RefineTop: 6, RefineSamples: 24, LookAhead: 1, Placements: 5, ScreenTop: 20, ScreenSamples: 6, AimTrials: 4),
        new(5, 0.08, 0.02, 0.015, Candidates: 16, Speeds: 7, Spins: 10, Samples: 3, RefineTop: 10, RefineSamples: 60, LookAhead: 1, Placements: 6, ScreenTop: 40, ScreenSamples: 10, AimTrials: 4, FirstRoundSimulations: 4000, SurePotChance: 0.9),
    ];

    /// <summary>The level <paramref name="level"/> (1 to 5).</summary>
    /// <exception cref="ArgumentOutOfRangeException">Outside 1 to 5.</exception>
    public static SkillLevel Of(int level)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(level, Min);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(level, Max);
        return All[level - 1];
    }

    /// <summary>
    /// The shot as this player strikes it when aiming for <paramref name="planned"/>: the error
    /// model of the class remarks, drawn from <paramref name="random"/>.
    /// </summary>
    public ShotSpec Execute(ShotSpec planned, PlannerRandom random)
    {
        ArgumentNullException.ThrowIfNull(planned);
        ArgumentNullException.ThrowIfNull(random);
        double aim = planned.AimDeg + AimStdDeg * random.NextClampedGaussian();
        double speed = planned.Speed * (1 + SpeedStdFraction * random.NextClampedGaussian());
        double side = planned.TipSide + TipStdFraction * random.NextClampedGaussian();
        double height = planned.TipHeight + TipStdFraction * random.NextClampedGaussian();
        (side, height) = InsideMiscueLimit(side, height);
        return planned with { AimDeg = aim, Speed = Math.Max(0.05, speed), TipSide = side, TipHeight = height };
    }

    // The tip is in the cue's frame (scene-format.md), so the miscue limit is a circle about
    // [0, 0] at any elevation: the player never strikes past it.
    internal static (double Side, double Height) InsideMiscueLimit(double side, double height)
    {
        double r = Math.Sqrt(side * side + height * height);
        if (r > MaxTip)
        {
            // Just inside the limit, so that rounding never makes it a miscue.
            double k = MaxTip / r * (1 - 1e-12);
            side *= k;
            height *= k;
        }
        return (side, height);
    }
}
