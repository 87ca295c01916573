namespace Billiards.Core.Ai;

/// <summary>
/// How the computer player weighs a game (<see cref="Rules.IPlannerPolicy.Policy"/>): the ruleset
/// says it, so the planner never asks which game it plays. <see cref="Pool"/> is the default;
/// <see cref="Snooker"/> is for a game of points where frames turn on safety exchanges.
/// </summary>
/// <param name="OpponentWeight">What the opponent's best chance after a safety costs (<see cref="ShotPlanner.OpponentWeight"/>, <see cref="ShotPlanner.SnookerOpponentWeight"/>).</param>
/// <param name="SafetiesPerTarget">At level 3 and above, the safeties tried per ball the shooter may hit (0: the pool count, candidates / 2 + 2).</param>
/// <param name="MaxSafeties">The most safeties tried when <paramref name="SafetiesPerTarget"/> counts them.</param>
/// <param name="PlaysSafeBelowSurePot">Below the level's sure-pot chance the player would rather play safe, unless the frame is decided.</param>
/// <param name="SeesSnookers">A safety that leaves the opponent snookered scores a bonus (the game's rules know the snooker).</param>
public sealed record PlannerPolicy(double OpponentWeight, int SafetiesPerTarget, int MaxSafeties, bool PlaysSafeBelowSurePot, bool SeesSnookers)
{
    /// <summary>Pool's: an open table gives the opponent one shot.</summary>
    public static PlannerPolicy Pool { get; } = new(ShotPlanner.OpponentWeight, 0, 0, false, false);

    /// <summary>Snooker's: an open table gives the opponent a break; two safeties a ball on (up to 24), sure pots, snookers.</summary>
    public static PlannerPolicy Snooker { get; } = new(ShotPlanner.SnookerOpponentWeight, 2, 24, true, true);
}
