namespace Billiards.Core.Rules;

/// <summary>Snooker's own part of a ruling (scene-format.md: "foul_and_miss", "free_ball").</summary>
public sealed record SnookerRulingPart : RulingPart
{
    /// <summary>The referee called a foul and a miss (<see cref="RefereeOption.Replace"/> is offered).</summary>
    public bool FoulAndMiss { get; init; }

    /// <summary>The incoming player is snookered after a foul and may nominate a free ball.</summary>
    public bool FreeBall { get; init; }

    /// <summary>
    /// After a foul and a miss: the state for the offender's next shot when the balls are replaced
    /// where they were before the shot (<see cref="RefereeOption.Replace"/>), else null.
    /// </summary>
    public GameState? Replaced { get; init; }
}
