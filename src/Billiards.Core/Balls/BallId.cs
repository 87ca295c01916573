using System.Globalization;

namespace Billiards.Core.Balls;

/// <summary>
/// Identity of a ball: 0 is the cue ball, 1..15 the numbered balls. In scene and result files a
/// ball id is the string "cue" or "1".."15".
/// </summary>
public readonly record struct BallId(int Value)
{
    /// <summary>The highest ball number.</summary>
    public const int MaxNumber = 15;

    /// <summary>The cue ball.</summary>
    public static BallId Cue => new(0);

    /// <summary>True for the cue ball.</summary>
    public bool IsCue => Value == 0;

    /// <summary>Solids are 1..7 (and 8 for the purpose of colour only).</summary>
    public bool IsSolid => Value is >= 1 and <= 8;

    /// <summary>Stripes are 9..15.</summary>
    public bool IsStripe => Value is >= 9 and <= 15;

    /// <summary>The id as a scene file writes it: "cue", "1" .. "15".</summary>
    public override string ToString() => Value == 0 ? "cue" : Value.ToString(CultureInfo.InvariantCulture);

    /// <summary>Parses "cue" or "1".."15".</summary>
    public static bool TryParse(string? text, out BallId id)
    {
        id = default;
        if (text == "cue")
        {
            id = Cue;
            return true;
        }
        if (text is null || text.Length is 0 or > 2 || text[0] == '0' || !text.All(char.IsAsciiDigit))
        {
            return false;
        }
        int n = int.Parse(text, CultureInfo.InvariantCulture);
        if (n is < 1 or > MaxNumber)
        {
            return false;
        }
        id = new BallId(n);
        return true;
    }
}
