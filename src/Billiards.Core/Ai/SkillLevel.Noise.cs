using Billiards.Core.Cue;

namespace Billiards.Core.Ai;

/// <summary>What the planner's search takes the error of its own stroke to be.</summary>
public enum SearchError
{
    /// <summary>The level's own error model (<see cref="SkillLevel"/>): the planner of the game and of a run without noise.</summary>
    Own,

    /// <summary>The execution noise it is told of (<see cref="SkillLevel.Noise"/>), sampled in its search: it plays for the noise.</summary>
    Noise,

    /// <summary>No error: one exact outcome per candidate (the noise-blind planner, kept for comparison).</summary>
    Exact,
}

/// <summary>
/// How the search scores a shot that keeps its player at the table: <paramref name="Stay"/> plus
/// <paramref name="Position"/> times the next position's quality, that quality being
/// <paramref name="BestShot"/> times the best next shot plus <paramref name="SecondShot"/> times the
/// best shot on another ball (<see cref="PlannerTable.PositionQuality(TablePosition, Rules.GameState, double, double, double)"/>).
/// </summary>
/// <param name="Stay">Score of staying at the table before the position counts.</param>
/// <param name="Position">Weight of the next position's quality.</param>
/// <param name="BestShot">Weight of the best next shot in the position's quality.</param>
/// <param name="SecondShot">Weight of the best shot on another ball in the position's quality.</param>
public sealed record LeaveWeights(double Stay, double Position, double BestShot, double SecondShot)
{
    /// <summary>The levels' own weights (<see cref="ShotPlanner.ContinueScore"/>, <see cref="ShotPlanner.PositionWeight"/>, <see cref="PlannerTable.BestShotWeight"/>, <see cref="PlannerTable.SecondShotWeight"/>).</summary>
    public static LeaveWeights Default { get; } = new(ShotPlanner.ContinueScore, ShotPlanner.PositionWeight, PlannerTable.BestShotWeight, PlannerTable.SecondShotWeight);

    /// <summary>
    /// The weights of the planner that plays for the noise: under the noise a run is as long as its
    /// leaves are easy, so the leave weighs more (0.45 against the levels' 0.3, staying 0.55 against 0.7), and a leave with
    /// a second easy ball more (0.3 against 0.15), for when the first way is missed in position.
    /// </summary>
    public static LeaveWeights UnderNoise { get; } = new(0.55, 0.45, 0.7, 0.3);
}

/// <summary>
/// How the planner that plays for the noise searches and scores a break (the first shot of a rack
/// in the games with a power break). Under our WPA rules the breaker stays at the table only when a
/// ball drops and no foul is called, and only then can the rack be run from the break: a break that
/// keeps the table scores <paramref name="Stay"/> plus <paramref name="Position"/> times the next
/// position's quality (weighed as <see cref="LeaveWeights"/> says, less the problem balls' cost), a
/// legal dry break <paramref name="Dry"/> less <paramref name="Opponent"/> times the opponent's best
/// shot (the opponent at the table of an open rack), and a foul (the cue ball pocketed or off the
/// table: ball in hand to the opponent on an open rack) <paramref name="Foul"/>, below any dry break.
/// The break grid's best breaks lie close together, so the search's middle round takes the best
/// <paramref name="ScreenTop"/> of the first round with <paramref name="ScreenSamples"/> draws more
/// each before the last round's, where a lucky few draws would otherwise pick among them.
/// </summary>
/// <param name="Stay">Score of a break that keeps the table before the position counts.</param>
/// <param name="Position">Weight of the next position's quality after a break that keeps the table.</param>
/// <param name="Dry">Score of a legal break that drops nothing before the opponent's chances count.</param>
/// <param name="Opponent">Weight of the opponent's best shot after a dry break.</param>
/// <param name="Foul">Score of a foul break.</param>
/// <param name="ScreenTop">Breaks the middle round takes from the first.</param>
/// <param name="ScreenSamples">Draws of the noise per break in the middle round.</param>
public sealed record BreakSearch(double Stay, double Position, double Dry, double Opponent, double Foul, int ScreenTop, int ScreenSamples)
{
    /// <summary>
    /// The break of the planner that plays for the noise: a dry break scores the opponent's table
    /// (0.3 less 0.4 times the opponent's best shot), a foul break -0.3 (the levels score both as
    /// any shot: the dry break as a safety, the foul 0.08); 200 breaks of the first round get 30
    /// draws more each.
    /// </summary>
    public static BreakSearch UnderNoise { get; } = new(0.55, 0.45, 0.3, 0.4, -0.3, 200, 30);
}

/// <summary>The level's planner under execution noise (<see cref="ExecutionNoise"/>).</summary>
public sealed partial record SkillLevel
{
    /// <summary>The smallest aim error (deg) a position is judged with: a noise of 0x still leaves the look-ahead a width to judge.</summary>
    public const double MinPositionAimStdDeg = 0.01;

    /// <summary>What the search takes the stroke's error to be (<see cref="SearchError.Own"/> for the levels of <see cref="Of"/>).</summary>
    public SearchError Error { get; init; } = SearchError.Own;

    /// <summary>How the search scores a shot that keeps its player at the table (<see cref="LeaveWeights.Default"/>; <see cref="LeaveWeights.UnderNoise"/> when playing for the noise).</summary>
    public LeaveWeights Leave { get; init; } = LeaveWeights.Default;

    /// <summary>How the search takes and scores a break (null: like any shot; <see cref="BreakSearch.UnderNoise"/> when playing for the noise).</summary>
    public BreakSearch? Break { get; init; }

    /// <summary>The execution noise the search samples when <see cref="Error"/> is <see cref="SearchError.Noise"/>, else null.</summary>
    public ExecutionNoise? Noise { get; init; }

    /// <summary>
    /// This level playing for <paramref name="noise"/>: the same search (candidates, variations,
    /// rounds and samples), each sample struck with a draw of the noise instead of the level's own
    /// error, and the next position judged with the noise's aim error (<see cref="ExecutionNoise.AimStdDeg"/>)
    /// in place of the level's: a candidate is scored by its outcomes under the noise, so its pot
    /// chance, the position it leaves and its risk of a foul, and a pot too unlikely loses to a safety.
    /// </summary>
    public SkillLevel PlayingFor(ExecutionNoise noise)
    {
        ArgumentNullException.ThrowIfNull(noise);
        return this with { Error = SearchError.Noise, Noise = noise, AimStdDeg = Math.Max(MinPositionAimStdDeg, noise.AimStdDeg), Leave = LeaveWeights.UnderNoise, Break = BreakSearch.UnderNoise };
    }

    /// <summary>
    /// This level blind to any error: the same search with one exact outcome per candidate (a
    /// single simulation of each variation without error, no later rounds), for comparison with
    /// the planner that plays for the noise.
    /// </summary>
    public SkillLevel NoiseBlind() =>
        this with { Error = SearchError.Exact, Noise = null, Break = null, Samples = 1, ScreenTop = 0, ScreenSamples = 0, RefineSamples = 0, FirstRoundSimulations = int.MaxValue };

    /// <summary>
    /// A stroke of the search aiming for <paramref name="planned"/> on a ball of radius
    /// <paramref name="ballRadius"/> (m), as <see cref="Error"/> says: with the level's own error,
    /// with a draw of the noise, or exact.
    /// </summary>
    public ShotSpec SearchStroke(ShotSpec planned, PlannerRandom random, double ballRadius) => Error switch
    {
        SearchError.Exact => planned,
        SearchError.Noise when Noise is { } noise => noise.Apply(planned, random, ballRadius),
        _ => Execute(planned, random),
    };
}
