using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>
/// What the computer player does at the table: where it puts the cue ball (ball in hand), what it
/// calls, whether it pushes out, and the shot it means to strike (before its own error).
/// </summary>
/// <param name="Shot">The planned strike (cue speed m/s, aim deg, tip fractions of R, elevation deg).</param>
/// <param name="Place">The cue ball's placement (m, z = R) with ball in hand or on the break, else null.</param>
/// <param name="Call">The call for the referee (ball and pocket, or a safety), or null where the game calls nothing.</param>
/// <param name="PushOut">9-ball and 10-ball: this shot is declared a push-out.</param>
/// <param name="Kind">The kind of shot chosen.</param>
/// <param name="Target">The first ball the cue ball is meant to touch (the cue ball when there is none).</param>
/// <param name="Pocket">The pocket meant, or <see cref="PocketId.None"/>.</param>
/// <param name="ExpectedPot">Fraction of the search's simulations of this shot, with the player's error, after which the shooter stays at the table (or wins).</param>
/// <param name="ExpectedScore">The search's mean score of the shot (0 = a lost game, 1 = a won game).</param>
/// <param name="Simulations">Simulations run for the decision.</param>
/// <param name="Milliseconds">Wall-clock time of the decision (ms).</param>
public sealed record Decision(
    ShotSpec Shot,
    Vec3? Place,
    Call? Call,
    bool PushOut,
    ShotKind Kind,
    BallId Target,
    PocketId Pocket,
    double ExpectedPot,
    double ExpectedScore,
    int Simulations,
    double Milliseconds)
{
    /// <summary>The referee's ruling on the planned shot simulated without error, or null.</summary>
    public Ruling? ExpectedRuling { get; init; }
}

/// <summary>How much the planner may spend on one decision.</summary>
/// <param name="Milliseconds">Wall-clock cap (ms). The level's own search normally ends well within it; a search cut short by it is no longer reproducible.</param>
/// <param name="Threads">Search threads; 0 uses every processor.</param>
public sealed record PlannerBudget(int Milliseconds = PlannerBudget.DefaultMilliseconds, int Threads = 0)
{
    /// <summary>The default cap (ms).</summary>
    public const int DefaultMilliseconds = 3000;

    /// <summary>The default budget.</summary>
    public static PlannerBudget Default { get; } = new();
}
