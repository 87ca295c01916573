using System.Globalization;

namespace Billiards.Core.Balls;

/// <summary>
/// Identity of a ball within its <see cref="BallSet"/>. In scene and result files a ball id is
/// the ball's name in its set ("cue", or the number in pool's). Which ball is a cue ball, what
/// it is called and how it looks are the set's to say; the members here answer for pool's set,
/// the one played now.
/// </summary>
public readonly record struct BallId(int Value)
{
    /// <summary>Pool's cue ball.</summary>
    public static BallId Cue => BallSet.Pool.CueBalls[0];

    /// <summary>True for a cue ball of pool's set.</summary>
    public bool IsCue => BallSet.Pool.IsCueBall(this);

    /// <summary>True for one of pool's stripes.</summary>
    public bool IsStripe => BallSet.Pool.Group("stripes").Contains(this);

    /// <summary>The id as a scene file writes it: the ball's name in its set ("cue", "1", "2", ..., "red-1", ..., "black").</summary>
    public override string ToString() => BallSet.NameOfAny(this);

    /// <summary>Parses a ball's name in any set (<see cref="BallSet.Pool"/>, <see cref="BallSet.Snooker"/>): "cue", "1" .. "15", "red-1" .. "black".</summary>
    public static bool TryParse(string? text, out BallId id) => BallSet.TryParseAny(text, out id);
}
