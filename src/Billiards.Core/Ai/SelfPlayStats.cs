using Billiards.Core.Rules;

namespace Billiards.Core.Ai;

/// <summary>One player's figures over a series of self-play games.</summary>
/// <param name="Level">The player's level.</param>
/// <param name="GamesWon">Games won.</param>
/// <param name="Shots">Shots taken (breaks included).</param>
/// <param name="PotAttempts">Shots meant to pot a ball (not breaks, safeties or push-outs).</param>
/// <param name="Pots">Of those, the shots after which the player stayed at the table or won.</param>
/// <param name="Fouls">Shots with a foul.</param>
/// <param name="Breaks">Breaks taken.</param>
/// <param name="PottingBreaks">Breaks that kept the breaker at the table.</param>
/// <param name="BreakAndRuns">Games won by the breaker's own shots without the opponent taking one.</param>
/// <param name="RunOuts">Games won by the player's own last shot in a visit that started after the opponent had been at the table (the visit cleared what was left).</param>
/// <param name="DecisionMedianMs">Median decision time (ms).</param>
/// <param name="DecisionP95Ms">95th percentile of the decision time (ms).</param>
/// <param name="ExpectedPotRate">The planner's mean expected pot probability over the attempted pots (against <see cref="Pots"/> / <see cref="PotAttempts"/> it shows how far the search's estimate is from what happened).</param>
public sealed record PlayerStats(int Level, int GamesWon, int Shots, int PotAttempts, int Pots, int Fouls, int Breaks, int PottingBreaks, int BreakAndRuns, int RunOuts, double DecisionMedianMs, double DecisionP95Ms, double ExpectedPotRate);

/// <summary>Sums up self-play games per player.</summary>
public static class SelfPlayStats
{
    /// <summary>The figures of player <paramref name="player"/> (0 or 1) over <paramref name="games"/>.</summary>
    public static PlayerStats Of(IReadOnlyList<PlayedGame> games, int player)
    {
        ArgumentNullException.ThrowIfNull(games);
        int won = 0, shots = 0, attempts = 0, pots = 0, fouls = 0, breaks = 0, pottingBreaks = 0, bnr = 0, runOuts = 0;
        var times = new List<double>();
        double expected = 0;
        int level = games.Count > 0 ? games[0].Levels[player] : 0;
        foreach (var game in games)
        {
            won += game.Winner == player ? 1 : 0;
            foreach (var s in game.Shots.Where(s => s.Before.Shooter == player))
            {
                shots++;
                times.Add(s.DecisionMs);
                fouls += s.Ruling.Legal ? 0 : 1;
                if (s.Before.Shot == 0)
                {
                    breaks++;
                    pottingBreaks += s.Ruling.Continue || (s.Ruling.GameOver && s.Ruling.Winner == player) ? 1 : 0;
                }
                if (s.AttemptedPot)
                {
                    attempts++;
                    pots += s.Made ? 1 : 0;
                    expected += s.ExpectedPot;
                }
            }
            // Only wins the player pocketed count: a win by the opponent's loss of game is neither.
            if (game.Winner == player && game.Shots.Count > 0 && game.Shots[^1].Before.Shooter == player)
            {
                if (game.Shots.All(s => s.Before.Shooter == player))
                {
                    bnr++;
                }
                else
                {
                    runOuts++;
                }
            }
        }
        times.Sort();
        return new PlayerStats(level, won, shots, attempts, pots, fouls, breaks, pottingBreaks, bnr, runOuts, Percentile(times, 0.5), Percentile(times, 0.95), attempts > 0 ? expected / attempts : 0);
    }

    /// <summary>The <paramref name="q"/> quantile of sorted values (nearest rank), 0 for none.</summary>
    public static double Percentile(IReadOnlyList<double> sorted, double q)
    {
        ArgumentNullException.ThrowIfNull(sorted);
        if (sorted.Count == 0)
        {
            return 0;
        }
        int rank = (int)Math.Ceiling(q * sorted.Count);
        return sorted[Math.Clamp(rank - 1, 0, sorted.Count - 1)];
    }
}
