namespace Billiards.Core.Balls;

/// <summary>
/// Identity of a ball within its <see cref="BallSet"/>. Which balls are cue balls, what each is
/// called in files and how it looks are the set's to say (<see cref="BallSet.IsCueBall"/>,
/// <see cref="BallSet.NameOf"/>, <see cref="BallSet.TryParse"/>); which cue ball a player strikes
/// is the game's (<see cref="Rules.Ruleset.CueBall"/>).
/// </summary>
public readonly record struct BallId(int Value)
{
    /// <summary>No ball (a safety's call names none).</summary>
    public static BallId None { get; } = new(-1);

    /// <summary>
    /// The id for messages: the ball's name in the set that has it ("cue", "1", ..., "red-1", ...,
    /// "black"; ids are unique across the sets), else its number. Files name balls through their
    /// own set (<see cref="BallSet.NameOf"/>).
    /// </summary>
    public override string ToString() => BallSet.NameOfAny(this);
}
