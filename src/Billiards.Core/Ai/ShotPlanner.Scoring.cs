using Billiards.Core.Balls;
using Billiards.Core.Rules;

namespace Billiards.Core.Ai;

/// <summary>How the planner scores a judged shot for the player who shot it.</summary>
public sealed partial class ShotPlanner
{
    /// <summary>Score of a won game.</summary>
    public const double WonScore = 1;

    /// <summary>Score of a lost game.</summary>
    public const double LostScore = 0;

    /// <summary>Score of a game that ended without a winner, and the quality assumed for a position a level does not look at.</summary>
    public const double EvenScore = 0.5;

    /// <summary>
    /// Score of a legal shot that leaves a game already decided for the shooter but not yet over
    /// (snooker's last black with the opponent more than 7 behind): just under a won game, so that
    /// the pot that ends it is preferred to a safety.
    /// </summary>
    public const double DecidedScore = 0.95;

    /// <summary>Score of a foul (not a loss).</summary>
    public const double FoulScore = 0.08;

    /// <summary>Score of a foul on a push-out.</summary>
    public const double PushOutFoulScore = 0.1;

    /// <summary>Score of a push-out that leaves a shot of middling ease; it falls by <see cref="PushOutSpread"/> towards an easy or a hopeless leave.</summary>
    public const double PushOutBestScore = 0.4;

    /// <summary>How much a push-out's score falls from <see cref="PushOutBestScore"/> at an easy or hopeless leave.</summary>
    public const double PushOutSpread = 0.3;

    /// <summary>Score of staying at the table before the position counts.</summary>
    public const double ContinueScore = 0.7;

    /// <summary>Weight of the next shot's position quality when the shooter stays at the table.</summary>
    public const double PositionWeight = 0.3;

    /// <summary>Cost of each ball left without a straight way to a pocket (<see cref="PlannerTable.ProblemBalls"/>).</summary>
    public const double ProblemBallCost = 0.04;

    /// <summary>Score of a legal miss (a safety) before the opponent's chances count.</summary>
    public const double SafetyScore = 0.5;

    /// <summary>Weight of the opponent's best shot after a legal miss.</summary>
    public const double OpponentWeight = 0.4;

    /// <summary>Weight of the opponent's best shot after a legal miss in a game with snookers (a leave there gives away a break).</summary>
    public const double SnookerOpponentWeight = 0.6;

    /// <summary>
    /// Score of each point a shot scores, and (less) of each point of penalty a foul gives away,
    /// in games that count points per shot (snooker's <see cref="Ruling.Points"/> and
    /// <see cref="Ruling.Penalty"/>; 0 in the pool games): a pot of the black beats a pot of the
    /// yellow of the same ease, a foul worth 7 is worse than one worth 4.
    /// </summary>
    public const double PointScore = 0.015, PenaltyScore = 0.005;

    /// <summary>
    /// Score added to a legal miss that leaves the opponent snookered (no straight line from the
    /// cue ball to any part of any ball they may strike: <see cref="PlannerTable.Snookered"/>); a
    /// snookered player fouls often and gives away a free ball's chances at most.
    /// </summary>
    public const double SnookerScore = 0.15;

    /// <summary>
    /// Score a pot attempt loses, in the final choice, for each unit of pot chance (0-1) its
    /// simulations fall short of the player's <see cref="SkillLevel.SurePotChance"/>, in the games
    /// with snookers: a pot of chance p scores its mean less <c>ShortfallWeight * (sure - p)</c>.
    /// </summary>
    public const double ShortfallWeight = 0.5;

    /// <summary>Safeties taken into the search's middle round besides its best variations, where pot attempts must be sure.</summary>
    public const int ScreenedSafeties = 8;

    /// <summary>
    /// True when the game is decided for the shooter of <paramref name="state"/> but not over: one
    /// object ball left and the opponent behind by more than the points remaining (snooker's last
    /// black with a lead of more than 7), so that no snooker can save it.
    /// </summary>
    public static bool Decided(GameState state, TablePosition position)
    {
        ArgumentNullException.ThrowIfNull(state);
        ArgumentNullException.ThrowIfNull(position);
        return Decided(state, state.Shooter, position);
    }

    // Decided for the shooter's side of the state after a shot: asked for every legal shot the
    // search judges, so it allocates nothing unless a game with snookers has one ball left.
    private static bool Decided(GameState state, int shooter, TablePosition position)
    {
        var ruleset = Ruleset.For(state.Rules);
        if (!ruleset.HasSnookers)
        {
            return false;
        }
        BallId? last = null;
        for (int i = 0; i < position.Count; i++)
        {
            if (position.Ids[i] != position.CueBall)
            {
                if (last is not null)
                {
                    return false;
                }
                last = position.Ids[i];
            }
        }
        return last is { } ball && ruleset.NeedsSnookers(state, 1 - shooter, [ball]);
    }

    /// <summary>
    /// The score of a judged shot for the player who shot it (see the class remarks), with the
    /// balls after it in <paramref name="after"/>, as <paramref name="level"/> judges it: levels
    /// without look-ahead see only the ruling; the others also the next shot, their own judged with
    /// their own error (<see cref="SkillLevel.PositionAimStdDeg"/>), the opponent's as if the
    /// opponent were at least as good (<see cref="SkillLevel.OpponentAimStdDeg"/>).
    /// </summary>
    public double Score(GameState before, Ruling ruling, TablePosition after, SkillLevel level)
    {
        ArgumentNullException.ThrowIfNull(before);
        ArgumentNullException.ThrowIfNull(ruling);
        ArgumentNullException.ThrowIfNull(level);
        bool look = level.LookAhead > 0;
        if (ruling.GameOver && !ruling.Legal && ruling.Winner == before.Shooter)
        {
            // A frame won by one's own foul (snooker's last black fouled by a player more than 7
            // ahead) is a foul all the same: the computer wins at the table, it does not foul on purpose.
            return FoulScore - (PenaltyScore * ruling.Penalty);
        }
        if (ruling.GameOver)
        {
            return ruling.Winner is not { } w ? EvenScore : w == before.Shooter ? WonScore : LostScore;
        }
        if (ruling.Legal && Decided(ruling.Next, before.Shooter, after))
        {
            // The last ball left and the opponent more than its points behind: the frame is won
            // whatever the shot leaves; a pot that ends it now is still the better (WonScore).
            return DecidedScore;
        }
        if (level.Break is { } breakWeights && Ruleset.For(before.Rules).IsPowerBreak(before))
        {
            return BreakScore(before, ruling, after, level, breakWeights, look);
        }
        if (before.PushOut)
        {
            if (!ruling.Legal)
            {
                return PushOutFoulScore;
            }
            // The opponent shoots a good leave and hands back a bad one: leave one in between.
            double q = look ? Table.BestEase(after, ruling.Next) : EvenScore;
            return PushOutBestScore - PushOutSpread * Math.Abs(2 * q - 1);
        }
        if (ruling.Continue)
        {
            // Position counts, but less than the pot: for a strong player a moderate next shot is
            // still likely, and the pot in hand is certain. Each ball left without a straight way
            // to a pocket costs a little, so that shots which free a cluster are preferred.
            return StayScore(level.Leave.Stay, level.Leave.Position, ruling, after, level, look) + (PointScore * ruling.Points);
        }
        if (!ruling.Legal)
        {
            return FoulScore - (PenaltyScore * ruling.Penalty);
        }
        double opponent = look ? Table.BestEase(after, ruling.Next, level.OpponentAimStdDeg) : EvenScore;
        double snookered = look && Table.Snookered(after, ruling.Next) ? SnookerScore : 0;
        // In a game of points (snooker) an open table gives the opponent a break, not one shot: it costs more.
        double weight = Ruleset.For(before.Rules).Policy.OpponentWeight;
        return SafetyScore - weight * opponent + snookered;
    }

    // A shot that keeps its player at the table: stay plus position times the next position's quality
    // (the level's leave weights and aim error), less each problem ball's cost.
    private double StayScore(double stay, double position, Ruling ruling, TablePosition after, SkillLevel level, bool look)
    {
        var leave = level.Leave;
        double q = look ? Table.PositionQuality(after, ruling.Next, level.PositionAimStdDeg, leave.BestShot, leave.SecondShot) : EvenScore;
        double problems = look ? ProblemBallCost * Table.ProblemBalls(after, ruling.Next) : 0;
        return stay + position * q - problems;
    }

    // A break as the planner that plays for the noise scores it (BreakSearch): kept table, dry, foul.
    private double BreakScore(GameState before, Ruling ruling, TablePosition after, SkillLevel level, BreakSearch weights, bool look)
    {
        if (ruling.Continue)
        {
            return StayScore(weights.Stay, weights.Position, ruling, after, level, look);
        }
        if (!ruling.Legal)
        {
            return weights.Foul;
        }
        double opponent = look ? Table.BestEase(after, ruling.Next, level.OpponentAimStdDeg) : EvenScore;
        return weights.Dry - weights.Opponent * opponent;
    }
}
