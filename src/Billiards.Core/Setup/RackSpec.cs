namespace Billiards.Core.Setup;

/// <summary>The games whose racks the Initializer can place.</summary>
public enum RackGame
{
    /// <summary>15 balls in a triangle, the 8 in the centre.</summary>
    EightBall,
    /// <summary>9 balls in a diamond, the 1 at the apex, the 9 in the centre.</summary>
    NineBall,
    /// <summary>10 balls in a triangle, the 1 at the apex, the 10 in the centre.</summary>
    TenBall,
    /// <summary>15 balls in a triangle in random order (14.1 continuous).</summary>
    StraightPool,
    /// <summary>Snooker's 22: the reds in a triangle behind the pink, the colours on their spots, the cue ball in the D.</summary>
    Snooker,
    /// <summary>Three-cushion's break: the red on the foot spot, the opponent's ball on the head spot, the breaker's beside it on the head string.</summary>
    ThreeCushion,
}

/// <summary>A rack placed by the Initializer, with the seed of its jitter.</summary>
/// <param name="Game">The rack's shape.</param>
/// <param name="Seed">The seed of its jitter (three-cushion's break has none).</param>
/// <param name="Breaker">Three-cushion: the breaker's cue ball (carom's white by default); the other cue ball is the opponent's.</param>
public sealed record RackSpec(RackGame Game, int Seed, Balls.BallId? Breaker = null);
