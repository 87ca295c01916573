namespace Billiards.Core.Rules;

/// <summary>Three-cushion's own part of a ruling (scene-format.md: "point", "cushions", "innings", "run").</summary>
public sealed record ThreeCushionRulingPart : RulingPart
{
    /// <summary>The shot scored a point.</summary>
    public bool Point { get; init; }

    /// <summary>
    /// The shooter's cue ball's cushion contacts before its contact with the second object ball,
    /// or in all when it met fewer than two.
    /// </summary>
    public int Cushions { get; init; }

    /// <summary>Each player's innings after the shot (the score sheet's).</summary>
    public PerPlayer<int> Innings { get; init; }

    /// <summary>The shooter's points in this inning, this shot's included.</summary>
    public int Run { get; init; }
}
