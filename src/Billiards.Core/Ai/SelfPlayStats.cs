using Billiards.Core.Mathematics;
using Billiards.Core.Rules;

namespace Billiards.Core.Ai;

/// <summary>
/// One player's figures over a series of self-play games. Every field is a count (or a histogram of
/// counts), so the figures of disjoint series add up to the figures of their union exactly
/// (<see cref="Plus"/>): the summaries of a run's shards merge into the run's summary.
/// </summary>
/// <param name="Level">The player's level.</param>
/// <param name="GamesWon">Games won.</param>
/// <param name="Shots">Shots taken (breaks included).</param>
/// <param name="PotAttempts">Shots meant to pot a ball (not breaks, safeties or push-outs).</param>
/// <param name="Pots">Of those, the shots after which the player stayed at the table or won.</param>
/// <param name="Fouls">Shots with a foul.</param>
/// <param name="Breaks">Break-offs taken: the first shots of a rack (the JSON's "breaks"; a break in the sense of <paramref name="BreakSum"/> is a visit's score).</param>
/// <param name="PottingBreaks">Break-offs that kept the breaker at the table.</param>
/// <param name="BreakAndRuns">Games won by the breaker's own shots without the opponent taking one.</param>
/// <param name="RunOuts">Games won by the player's own last shot in a visit that started after the opponent had been at the table (the visit cleared what was left).</param>
/// <param name="Visits">
/// Visits to the table: the player's shots from coming to the table until a shot that does not
/// keep them there (a foul, a miss, a safety, the end of the game; a visit cut off by the shot
/// limit counts too). A put-back after a foul starts a new visit.
/// </param>
/// <param name="ScoringVisits">Of those, the visits with a break above 0.</param>
/// <param name="BreakSum">
/// The breaks of every visit summed, in <see cref="Ruleset.BreakUnit"/>: the points a visit
/// scored in snooker, the object balls it pocketed on legal shots that stayed down in pool (<see cref="Ruleset.BreakValue"/>).
/// </param>
/// <param name="HighestBreak">The highest break of one visit (same unit), 0 without a visit.</param>
/// <param name="ExpectedPotSumE9">
/// The planner's expected pot probabilities summed over the attempted pots, in units of 1e-9, each
/// rounded to a whole unit before it is added: a sum of integers, the same in any order.
/// </param>
/// <param name="Decisions">The decision times (wall clock, ms), binned.</param>
public sealed record PlayerStats(int Level, int GamesWon, int Shots, int PotAttempts, int Pots, int Fouls, int Breaks, int PottingBreaks, int BreakAndRuns, int RunOuts, int Visits, int ScoringVisits, int BreakSum, int HighestBreak, long ExpectedPotSumE9, DecisionHistogram Decisions)
{
    /// <summary>Units of <see cref="ExpectedPotSumE9"/> in a probability of 1.</summary>
    public const double ExpectedPotUnit = 1e9;

    /// <summary>Median decision time (ms), from <see cref="Decisions"/>.</summary>
    public double DecisionMedianMs => Decisions.Quantile(0.5);

    /// <summary>95th percentile of the decision time (ms), from <see cref="Decisions"/>.</summary>
    public double DecisionP95Ms => Decisions.Quantile(0.95);

    /// <summary>The planner's mean expected pot probability over the attempted pots (against <see cref="Pots"/> / <see cref="PotAttempts"/> it shows how far the search's estimate is from what happened).</summary>
    public double ExpectedPotRate => PotAttempts > 0 ? ExpectedPotSumE9 / ExpectedPotUnit / PotAttempts : 0;

    /// <summary>The fraction of attempted pots made, 0 without an attempt.</summary>
    public double PotRate => PotAttempts > 0 ? (double)Pots / PotAttempts : 0;

    /// <summary>
    /// The mean break over the scoring visits (<see cref="BreakSum"/> / <see cref="ScoringVisits"/>),
    /// 0 without one: snooker's "mean break" leaves out the visits that scored nothing, and so does
    /// this in every game.
    /// </summary>
    public double MeanBreak => ScoringVisits > 0 ? (double)BreakSum / ScoringVisits : 0;

    /// <summary>The figures of this series and <paramref name="other"/> (the same player at the same level) together.</summary>
    /// <exception cref="ArgumentException">When the levels differ.</exception>
    public PlayerStats Plus(PlayerStats other)
    {
        ArgumentNullException.ThrowIfNull(other);
        if (other.Level != Level)
        {
            throw new ArgumentException($"level {other.Level} cannot be added to level {Level}", nameof(other));
        }
        return new PlayerStats(Level, GamesWon + other.GamesWon, Shots + other.Shots, PotAttempts + other.PotAttempts, Pots + other.Pots,
            Fouls + other.Fouls, Breaks + other.Breaks, PottingBreaks + other.PottingBreaks, BreakAndRuns + other.BreakAndRuns,
            RunOuts + other.RunOuts, Visits + other.Visits, ScoringVisits + other.ScoringVisits, BreakSum + other.BreakSum,
            Math.Max(HighestBreak, other.HighestBreak), ExpectedPotSumE9 + other.ExpectedPotSumE9, Decisions.Plus(other.Decisions));
    }
}

/// <summary>Sums up self-play games per player.</summary>
public static class SelfPlayStats
{
    /// <summary>The figures of player <paramref name="player"/> (0 or 1) at <paramref name="level"/> over <paramref name="games"/>.</summary>
    public static PlayerStats Of(IReadOnlyList<PlayedGame> games, int player, int level)
    {
        ArgumentNullException.ThrowIfNull(games);
        int won = 0, shots = 0, attempts = 0, pots = 0, fouls = 0, breaks = 0, pottingBreaks = 0, bnr = 0, runOuts = 0;
        int visits = 0, scoringVisits = 0, breakSum = 0, highestBreak = 0;
        long expected = 0;
        var times = new long[DecisionHistogram.BinCount];
        foreach (var game in games)
        {
            won += game.Winner == player ? 1 : 0;
            foreach (int visitBreak in Visits(game, player))
            {
                visits++;
                scoringVisits += visitBreak > 0 ? 1 : 0;
                breakSum += visitBreak;
                highestBreak = Math.Max(highestBreak, visitBreak);
            }
            foreach (var s in game.Shots.Where(s => s.Before.Shooter == player))
            {
                shots++;
                times[DecisionHistogram.Bin(s.DecisionMs)]++;
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
                    expected += (long)Math.Round(s.ExpectedPot * PlayerStats.ExpectedPotUnit);
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
        return new PlayerStats(level, won, shots, attempts, pots, fouls, breaks, pottingBreaks, bnr, runOuts,
            visits, scoringVisits, breakSum, highestBreak, expected, new DecisionHistogram(times));
    }

    /// <summary>
    /// The break of each of <paramref name="player"/>'s visits in <paramref name="game"/>, in order
    /// (<see cref="PlayerStats.Visits"/>; a break of 0 for a visit that scored nothing). A visit
    /// ends with a shot that does not keep the shooter at the table, whoever plays next: the
    /// offender put back in after a foul starts a new one.
    /// </summary>
    public static IEnumerable<int> Visits(PlayedGame game, int player)
    {
        ArgumentNullException.ThrowIfNull(game);
        return Ruleset.For(game.Rules).Visits(game.Shots.Select(s => (s.Before.Shooter, s.Ruling))).Where(v => v.Player == player).Select(v => v.Break);
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

/// <summary>
/// Decision times in fixed logarithmic bins: <see cref="BinsPerDecade"/> bins a decade from
/// <see cref="FirstEdgeMs"/> over <see cref="Decades"/> decades (0.01 ms to 1,000 s), each about 12 %
/// wide. Histograms of any series add bin by bin, so quantiles of a merged run come out of the
/// merged counts exactly as the unsharded run's do; a quantile is the geometric middle of the bin
/// that holds its nearest rank, within 6 % of the true value.
/// </summary>
public sealed class DecisionHistogram
{
    /// <summary>Bins a decade.</summary>
    public const int BinsPerDecade = 20;

    /// <summary>Decades covered.</summary>
    public const int Decades = 8;

    /// <summary>The lower edge of the first bin (ms); shorter times fall into the first bin.</summary>
    public const double FirstEdgeMs = 0.01;

    /// <summary>The number of bins; times beyond the last edge fall into the last bin.</summary>
    public const int BinCount = BinsPerDecade * Decades;

    private readonly long[] _counts;

    /// <summary>A histogram of <see cref="BinCount"/> counts (copied).</summary>
    /// <exception cref="ArgumentException">When the length is not <see cref="BinCount"/> or a count is negative.</exception>
    public DecisionHistogram(IReadOnlyList<long> counts)
    {
        ArgumentNullException.ThrowIfNull(counts);
        if (counts.Count != BinCount || counts.Any(c => c < 0))
        {
            throw new ArgumentException($"expected {BinCount} counts, none negative", nameof(counts));
        }
        _counts = [.. counts];
    }

    /// <summary>The count of each bin.</summary>
    public IReadOnlyList<long> Counts => _counts;

    /// <summary>The number of times binned.</summary>
    public long Total => _counts.Sum();

    /// <summary>The bin of a time (ms).</summary>
    public static int Bin(double ms)
    {
        if (!(ms > FirstEdgeMs))
        {
            return 0;
        }
        return (int)Math.Min(BinCount - 1, Math.Floor(BinsPerDecade * DeterministicMath.Log10(ms / FirstEdgeMs)));
    }

    /// <summary>The lower edge of bin <paramref name="bin"/> (ms).</summary>
    public static double Edge(int bin) => FirstEdgeMs * DeterministicMath.Pow(10, (double)bin / BinsPerDecade);

    /// <summary>The <paramref name="q"/> quantile (nearest rank) as the geometric middle of its bin (ms); 0 for no times.</summary>
    public double Quantile(double q)
    {
        long total = Total;
        if (total == 0)
        {
            return 0;
        }
        long rank = Math.Clamp((long)Math.Ceiling(q * total), 1, total);
        long seen = 0;
        int bin = 0;
        for (; bin < BinCount - 1; bin++)
        {
            seen += _counts[bin];
            if (seen >= rank)
            {
                break;
            }
        }
        return FirstEdgeMs * DeterministicMath.Pow(10, (bin + 0.5) / BinsPerDecade);
    }

    /// <summary>The bin-by-bin sum of this histogram and <paramref name="other"/>.</summary>
    public DecisionHistogram Plus(DecisionHistogram other)
    {
        ArgumentNullException.ThrowIfNull(other);
        var sum = new long[BinCount];
        for (int i = 0; i < BinCount; i++)
        {
            sum[i] = _counts[i] + other._counts[i];
        }
        return new DecisionHistogram(sum);
    }
}
