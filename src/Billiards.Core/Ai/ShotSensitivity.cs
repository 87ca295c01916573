using Billiards.Core.Cue;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Ai;

/// <summary>Where one sample of <see cref="ShotPlanner.Sensitivity"/> left the balls.</summary>
/// <param name="Shot">The shot as struck: the planned one with the level's error drawn for this sample.</param>
/// <param name="Potted">True when this sample potted (the target, or any object ball without a target) and kept the cue ball on the table.</param>
/// <param name="Cue">Where the cue ball stopped (m), or null when it left the table.</param>
/// <param name="Target">Where the target ball stopped (m), or null when it was potted or there is no target.</param>
public sealed record ShotEnding(ShotSpec Shot, bool Potted, Vec3? Cue, Vec3? Target);

/// <summary>How sure a shot is: the planner's samples of it with a level's error, and how many potted.</summary>
/// <param name="Level">The level whose error was sampled.</param>
/// <param name="Endings">Every sample, in order.</param>
public sealed record ShotSensitivity(SkillLevel Level, IReadOnlyList<ShotEnding> Endings)
{
    /// <summary>How many samples potted.</summary>
    public int Pots => Endings.Count(e => e.Potted);

    /// <summary>The share of samples that potted, 0..1 (0 without samples).</summary>
    public double PotRate => Endings.Count == 0 ? 0 : (double)Pots / Endings.Count;
}
