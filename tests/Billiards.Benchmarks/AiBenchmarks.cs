using BenchmarkDotNet.Attributes;
using Billiards.Core.Ai;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Benchmarks;

/// <summary>
/// The computer player: one whole decision at levels 1, 3 and 5 on fixed 8-ball positions (an
/// open table after a seeded break, and ball in hand on it), and the planner's simulation rate
/// (one shot from a restored snapshot to rest with the event integrator, what the search repeats).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class AiBenchmarks
{
    private static readonly TableSpec Table = TableSpec.FromPreset("pool-9ft");
    private ShotPlanner _planner = null!;
    private TablePosition _open = null!;
    private GameState _state = null!;
    private StandardSimulation _sim = null!;
    private SimulationSnapshot _snapshot = null!;
    private ShotSpec _shot = null!;

    /// <summary>The player's level.</summary>
    [Params(1, 3, 5)]
    public int Level { get; set; } = 1;

    [GlobalSetup]
    public void Setup()
    {
        var physics = PhysicsParams.Default;
        _planner = new ShotPlanner(Table, physics);
        var rack = TablePosition.Rack(new RackSpec(RackGame.EightBall, 5), Table, physics.R, Billiards.Core.Balls.BallSet.Pool.CueBalls[0]);
        var sim = rack.CreateSimulation(Table, physics);
        sim.Strike(new ShotSpec(7, 0.3, 0, -0.2));
        sim.AdvanceTo(120);
        _open = TablePosition.Of(sim, Billiards.Core.Balls.BallSet.Pool.CueBalls[0]);
        _state = new GameState(GameRules.EightBall) { Shot = 1, BallInHand = _open.Cue is null ? BallInHand.Table : BallInHand.None };
        _sim = _open.CreateSimulation(Table, physics);
        _snapshot = _sim.CreateSnapshot();
        _shot = _planner.Decide(_state, _open, SkillLevel.Of(3), new PlannerBudget(60_000, 1), 1).Shot;
    }

    /// <summary>One decision on the open table after the break (both cores).</summary>
    [Benchmark]
    public double Decide() => _planner.Decide(_state, _open, SkillLevel.Of(Level), new PlannerBudget(60_000), 1).ExpectedScore;

    /// <summary>One decision with ball in hand on the same table.</summary>
    [Benchmark]
    public double DecideBallInHand() =>
        _planner.Decide(_state with { BallInHand = BallInHand.Table }, _open.Without(Billiards.Core.Balls.BallSet.Pool.CueBalls[0]), SkillLevel.Of(Level), new PlannerBudget(60_000), 1).ExpectedScore;

    /// <summary>One simulated shot of the search (restore the position's snapshot, strike, run to rest), on one core; the inverse is simulations per second.</summary>
    [Benchmark]
    public double SimulateShot()
    {
        _sim.Restore(_snapshot);
        _sim.Strike(_shot);
        _sim.AdvanceTo(120);
        return _sim.Time;
    }
}
