namespace Billiards.Core.Rules;

/// <summary>Who plays a seat's shots, and so where its shots come from (<see cref="Session.Submit"/>).</summary>
public enum SeatKind
{
    /// <summary>A person at this machine: the keys and the mouse.</summary>
    Person,
    /// <summary>The computer player at a level 1-5.</summary>
    Computer,
    /// <summary>An input script standing in for a person (its keys and strokes are a person's).</summary>
    Script,
    /// <summary>A player elsewhere whose shots arrive from the network.</summary>
    Remote,
}

/// <summary>A seat at the table: who sits in it and the name shown for them.</summary>
/// <param name="Name">The name shown on the HUD.</param>
/// <param name="ComputerLevel">The computer's level 1-5, or null for anyone else.</param>
public sealed record Seat(string Name, int? ComputerLevel = null)
{
    /// <summary>Who plays the seat: the computer with a level, else a person (a script or a remote player where set).</summary>
    public SeatKind Kind { get; init; } = ComputerLevel is null ? SeatKind.Person : SeatKind.Computer;

    /// <summary>True for anyone but the computer.</summary>
    public bool IsHuman => Kind != SeatKind.Computer;

    /// <summary>Longest player name (characters).</summary>
    public const int MaxNameLength = 24;

    /// <summary>
    /// True when a shot from <paramref name="source"/> is this seat's: the computer's from the
    /// computer, a remote player's from the network, a person's from the keys and the mouse (an
    /// input script types and strokes as a person does).
    /// </summary>
    public bool Accepts(SeatKind source) => Kind switch
    {
        SeatKind.Person or SeatKind.Script => source is SeatKind.Person or SeatKind.Script,
        _ => source == Kind,
    };

    /// <summary>Two seats of <paramref name="kind"/> named <paramref name="names"/>.</summary>
    public static IReadOnlyList<Seat> Of(PerPlayer<string> names, SeatKind kind) =>
        [new Seat(names.First) { Kind = kind }, new Seat(names.Second) { Kind = kind }];

    /// <summary>
    /// Parses a seat: <c>human</c> (named "Player N"), <c>computer:LEVEL</c> or <c>cpu:LEVEL</c>
    /// (level 1-5), or any other name, a person of that name; null when it is none of them
    /// (empty, too long, a control character, or a computer without a level 1-5).
    /// </summary>
    public static Seat? Parse(string text, int seat)
    {
        ArgumentNullException.ThrowIfNull(text);
        string name = text.Trim();
        string t = name.ToLowerInvariant();
        if (t == "human")
        {
            return new Seat($"Player {seat + 1}");
        }
        foreach (string prefix in (string[])["computer:", "cpu:"])
        {
            if (t.StartsWith(prefix, StringComparison.Ordinal))
            {
                return int.TryParse(t[prefix.Length..], out int level) && level is >= 1 and <= 5
                    ? new Seat($"Computer L{level}", level)
                    : null;
            }
        }
        return name.Length is > 0 and <= MaxNameLength && !name.Any(char.IsControl) ? new Seat(name) : null;
    }
}
