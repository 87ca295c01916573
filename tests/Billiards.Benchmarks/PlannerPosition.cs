using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Benchmarks;

/// <summary>
/// A fixed position for the computer player's benchmarks: a seeded rack broken with a fixed shot
/// and run to rest, the game state before the next shot, a planner on the table, and the
/// position's simulation with a snapshot, to rerun one shot of the search (the level-3 choice).
/// </summary>
internal sealed class PlannerPosition
{
    private readonly StandardSimulation _sim;
    private readonly SimulationSnapshot _snapshot;
    private readonly ShotSpec _shot;

    private PlannerPosition(TableSpec table, BallSet balls, PhysicsParams physics, RackSpec rack, ShotSpec breakShot, Func<TablePosition, GameState> state)
    {
        Planner = new ShotPlanner(table, physics);
        var cue = balls.CueBalls[0];
        var sim = TablePosition.Rack(rack, table, physics.R, cue).CreateSimulation(table, physics);
        sim.Strike(breakShot);
        sim.AdvanceTo(120);
        Table = TablePosition.Of(sim, cue);
        State = state(Table);
        _sim = Table.CreateSimulation(table, physics);
        _snapshot = _sim.CreateSnapshot();
        _shot = Planner.Decide(State, Table, SkillLevel.Of(3), new PlannerBudget(60_000, 1), 1).Shot;
    }

    /// <summary>An open 8-ball table after a seeded break (rack seed 5, 7 m/s), the shot after the break.</summary>
    public static PlannerPosition EightBall() => new(TableSpec.FromPreset("pool-9ft"), BallSet.Pool, PhysicsParams.Default,
        new RackSpec(RackGame.EightBall, 5), new ShotSpec(7, 0.3, 0, -0.2),
        open => new GameState(GameRules.EightBall) { Shot = 1, BallInHand = open.Cue is null ? BallInHand.Table : BallInHand.None });

    /// <summary>
    /// Snooker's 12 ft table after a firm break-off into the side of the pack (rack seed 5, 5 m/s),
    /// so that reds lie open: a red on.
    /// </summary>
    public static PlannerPosition Snooker() => new(SnookerTable.Spec, BallSet.Snooker, BallSet.Snooker.DefaultParams,
        new RackSpec(RackGame.Snooker, 5), new ShotSpec(5, 2.6, 0, 0),
        open => new GameState(GameRules.Snooker) { Shot = 1, BallInHand = open.Cue is null ? BallInHand.D : BallInHand.None, Part = new SnookerPart { BallOn = SnookerRuleset.Red } });

    /// <summary>The planner on the position's table.</summary>
    public ShotPlanner Planner { get; }

    /// <summary>The balls at rest after the break.</summary>
    public TablePosition Table { get; }

    /// <summary>The game state before the shot after the break.</summary>
    public GameState State { get; }

    /// <summary>One whole decision at <paramref name="level"/> on the position (the search on every core); returns its expected score.</summary>
    public double Decide(int level) => Decide(State, Table, level);

    /// <summary>One whole decision at <paramref name="level"/> for <paramref name="state"/> on <paramref name="table"/> with the position's planner.</summary>
    public double Decide(GameState state, TablePosition table, int level) =>
        Planner.Decide(state, table, SkillLevel.Of(level), new PlannerBudget(60_000), 1).ExpectedScore;

    /// <summary>One simulated shot of the search: restore the position, strike, run to rest (one core); returns the time at rest (s).</summary>
    public double SimulateShot()
    {
        _sim.Restore(_snapshot);
        _sim.Strike(_shot);
        _sim.AdvanceTo(120);
        return _sim.Time;
    }
}
