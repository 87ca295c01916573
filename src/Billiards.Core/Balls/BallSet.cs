using System.Globalization;

namespace Billiards.Core.Balls;

/// <summary>
/// The balls a kind of billiards is played with: the cue ball ("cue", id 0) and the numbered
/// balls 1 .. <see cref="HighestNumber"/>. Pool's set is the one played now; snooker's 22 and
/// carom's 3 will be sets of their own.
/// </summary>
public sealed class BallSet
{
    private BallSet(string name, int highestNumber)
    {
        Name = name;
        HighestNumber = highestNumber;
        Ids = [.. Enumerable.Range(0, highestNumber + 1).Select(n => new BallId(n))];
    }

    /// <summary>Pool: the cue ball and the balls 1 .. 15.</summary>
    public static BallSet Pool { get; } = new("pool", 15);

    /// <summary>The set's name.</summary>
    public string Name { get; }

    /// <summary>The highest ball number.</summary>
    public int HighestNumber { get; }

    /// <summary>Every ball of the set, the cue ball first.</summary>
    public IReadOnlyList<BallId> Ids { get; }

    /// <summary>Number of balls, the cue ball included.</summary>
    public int Count => Ids.Count;

    /// <summary>How the set's ids are written, for messages: "cue" or "1" .. "15".</summary>
    public string Describe() => string.Create(CultureInfo.InvariantCulture, $"\"cue\" or \"1\" .. \"{HighestNumber}\"");

    /// <summary>True when <paramref name="id"/> is a ball of the set.</summary>
    public bool Contains(BallId id) => id.Value >= 0 && id.Value <= HighestNumber;

    /// <summary>Parses "cue" or one of the set's numbers, written without leading zeros.</summary>
    public bool TryParse(string? text, out BallId id)
    {
        id = default;
        if (text == "cue")
        {
            id = BallId.Cue;
            return true;
        }
        if (text is null || text.Length is 0 or > 9 || text[0] == '0' || !text.All(char.IsAsciiDigit))
        {
            return false;
        }
        int n = int.Parse(text, CultureInfo.InvariantCulture);
        if (n < 1 || n > HighestNumber)
        {
            return false;
        }
        id = new BallId(n);
        return true;
    }
}
