using Billiards.Core.Balls;

namespace Billiards.Core.Tests;

/// <summary>Pool's balls by role, for tests that play pool (which ball is the cue ball is the set's: <see cref="BallSet.CueBalls"/>).</summary>
internal static class PoolBalls
{
    /// <summary>Pool's one cue ball.</summary>
    public static BallId Cue => BallSet.Pool.CueBalls[0];

    /// <summary>True for pool's cue ball.</summary>
    public static bool IsCue(BallId id) => BallSet.Pool.IsCueBall(id);
}
