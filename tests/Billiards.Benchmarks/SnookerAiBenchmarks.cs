using BenchmarkDotNet.Attributes;
using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Benchmarks;

/// <summary>
/// The computer player at snooker, level 5: one whole decision on a fixed position of the 12 ft
/// table (the rack after a seeded break-off, a red on), one with a colour to nominate after a red
/// (the same table with a red taken off), and one simulated shot of the search on it (22 balls,
/// restored from a snapshot and run to rest with the event integrator).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class SnookerAiBenchmarks
{
    private static readonly TableSpec Table = SnookerTable.Spec;
    private ShotPlanner _planner = null!;
    private TablePosition _open = null!;
    private GameState _redOn = null!;
    private GameState _colourOn = null!;
    private TablePosition _colourTable = null!;
    private StandardSimulation _sim = null!;
    private SimulationSnapshot _snapshot = null!;
    private ShotSpec _shot = null!;

    [GlobalSetup]
    public void Setup()
    {
        var physics = BallSet.Snooker.DefaultParams;
        _planner = new ShotPlanner(Table, physics);
        var rack = TablePosition.Rack(new RackSpec(RackGame.Snooker, 5), Table, physics.R, BallSet.Snooker.CueBalls[0]);
        var sim = rack.CreateSimulation(Table, physics);
        // A firm break-off into the side of the pack, so that reds lie open for the decision.
        sim.Strike(new ShotSpec(5, 2.6, 0, 0));
        sim.AdvanceTo(120);
        _open = TablePosition.Of(sim, BallSet.Snooker.CueBalls[0]);
        _redOn = new GameState(GameRules.Snooker) { Shot = 1, BallOn = SnookerRuleset.Red, BallInHand = _open.Cue is null ? BallInHand.D : BallInHand.None };
        var red = _open.Ids.First(SnookerRuleset.IsRed);
        _colourTable = _open.Without(red);
        _colourOn = _redOn with { Shot = 2, BallOn = SnookerRuleset.Colour, Score = new PerPlayer<int>(1, 0) };
        _sim = _open.CreateSimulation(Table, physics);
        _snapshot = _sim.CreateSnapshot();
        _shot = _planner.Decide(_redOn, _open, SkillLevel.Of(3), new PlannerBudget(60_000, 1), 1).Shot;
    }

    /// <summary>One level-5 decision with a red on (both cores).</summary>
    [Benchmark]
    public double DecideRedOn() => _planner.Decide(_redOn, _open, SkillLevel.Of(5), new PlannerBudget(60_000), 1).ExpectedScore;

    /// <summary>One level-5 decision with a colour to nominate and pot after a red (both cores).</summary>
    [Benchmark]
    public double DecideColourOn() => _planner.Decide(_colourOn, _colourTable, SkillLevel.Of(5), new PlannerBudget(60_000), 1).ExpectedScore;

    /// <summary>One simulated shot of the search on the snooker table, on one core.</summary>
    [Benchmark]
    public double SimulateShot()
    {
        _sim.Restore(_snapshot);
        _sim.Strike(_shot);
        _sim.AdvanceTo(120);
        return _sim.Time;
    }
}
