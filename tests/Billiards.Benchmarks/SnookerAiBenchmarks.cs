using BenchmarkDotNet.Configs;
using Billiards.Core.Ai;
using Billiards.Core.Rules;

namespace Billiards.Benchmarks;

/// <summary>
/// The computer player at snooker, level 5, against the same at 8-ball (<see cref="AiBenchmarks"/>'
/// position) as the baseline of each group, so that the ratio column compares the two games in one
/// run. Decisions: a red on, on the 12 ft table after a firm seeded break-off that opened the reds
/// (<see cref="PlannerPosition.Snooker"/>); a colour to nominate and pot after a red (the same table
/// with a red taken off, 1-0 up); the 8-ball level-5 decision on the open table after the break.
/// Shots: one simulated shot of the search on each table (22 and 16 balls, restored from a snapshot
/// and run to rest with the event integrator, one core).
/// </summary>
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
[CategoriesColumn]
public class SnookerAiBenchmarks
{
    private const int Level = 5;
    private PlannerPosition _eight = null!;
    private PlannerPosition _snooker = null!;
    private GameState _colourOn = null!;
    private TablePosition _colourTable = null!;

    [GlobalSetup]
    public void Setup()
    {
        _eight = PlannerPosition.EightBall();
        _snooker = PlannerPosition.Snooker();
        _colourTable = _snooker.Table.Without(_snooker.Table.Ids.First(SnookerRuleset.IsRed));
        _colourOn = _snooker.State with { Shot = 2, Score = new PerPlayer<int>(1, 0), Part = SnookerPart.Of(_snooker.State) with { BallOn = SnookerRuleset.Colour } };
    }

    /// <summary>The 8-ball level-5 decision on the open table after the break: the decisions' baseline.</summary>
    [Benchmark(Baseline = true), BenchmarkCategory("decision")]
    public double EightBallDecide() => _eight.Decide(Level);

    /// <summary>One level-5 decision with a red on (both cores).</summary>
    [Benchmark, BenchmarkCategory("decision")]
    public double DecideRedOn() => _snooker.Decide(Level);

    /// <summary>One level-5 decision with a colour to nominate and pot after a red (both cores).</summary>
    [Benchmark, BenchmarkCategory("decision")]
    public double DecideColourOn() => _snooker.Decide(_colourOn, _colourTable, Level);

    /// <summary>One simulated shot of the search on the 8-ball table: the shots' baseline.</summary>
    [Benchmark(Baseline = true), BenchmarkCategory("shot")]
    public double EightBallSimulateShot() => _eight.SimulateShot();

    /// <summary>One simulated shot of the search on the snooker table, on one core.</summary>
    [Benchmark, BenchmarkCategory("shot")]
    public double SimulateShot() => _snooker.SimulateShot();
}
