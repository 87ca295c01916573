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
}

/// <summary>A rack placed by the Initializer, with the seed of its jitter.</summary>
public sealed record RackSpec(RackGame Game, int Seed);
