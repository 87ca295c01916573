using Billiards.Core.Balls;
using Billiards.Core.Rules;

namespace Billiards.Benchmarks;

/// <summary>
/// The computer player: one whole decision at levels 1, 3 and 5 on fixed 8-ball positions (an
/// open table after a seeded break, and ball in hand on it), and the planner's simulation rate
/// (one shot from a restored snapshot to rest with the event integrator, what the search repeats).
/// </summary>
public class AiBenchmarks
{
    private PlannerPosition _eight = null!;

    /// <summary>The player's level.</summary>
    [Params(1, 3, 5)]
    public int Level { get; set; } = 1;

    [GlobalSetup]
    public void Setup() => _eight = PlannerPosition.EightBall();

    /// <summary>One decision on the open table after the break (both cores).</summary>
    [Benchmark]
    public double Decide() => _eight.Decide(Level);

    /// <summary>One decision with ball in hand on the same table.</summary>
    [Benchmark]
    public double DecideBallInHand() =>
        _eight.Decide(_eight.State with { BallInHand = BallInHand.Table }, _eight.Table.Without(BallSet.Pool.CueBalls[0]), Level);

    /// <summary>One simulated shot of the search (restore the position's snapshot, strike, run to rest), on one core; the inverse is simulations per second.</summary>
    [Benchmark]
    public double SimulateShot() => _eight.SimulateShot();
}
