using System.Globalization;

namespace Billiards.Core.Balls;

/// <summary>
/// Identity of a ball: 0 is the cue ball, 1 and up the numbered balls of its <see cref="BallSet"/>.
/// In scene and result files a ball id is the string "cue" or the number.
/// </summary>
public readonly record struct BallId(int Value)
{
    /// <summary>The cue ball.</summary>
    public static BallId Cue => new(0);

    /// <summary>True for the cue ball.</summary>
    public bool IsCue => Value == 0;

    /// <summary>Solids are 1..7 (and 8 for the purpose of colour only).</summary>
    public bool IsSolid => Value is >= 1 and <= 8;

    /// <summary>Stripes are 9 up to the highest ball of pool's set.</summary>
    public bool IsStripe => Value >= 9 && Value <= BallSet.Pool.HighestNumber;

    /// <summary>The id as a scene file writes it: "cue", or the number ("1", "2", ...).</summary>
    public override string ToString() => Value == 0 ? "cue" : Value.ToString(CultureInfo.InvariantCulture);

    /// <summary>Parses a ball id of pool's set (<see cref="BallSet.Pool"/>): "cue" or "1" .. "15".</summary>
    public static bool TryParse(string? text, out BallId id) => BallSet.Pool.TryParse(text, out id);
}
