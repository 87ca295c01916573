using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Table;
using Billiards.Core.Tests.Rules;

namespace Billiards.Core.Tests.Ai;

/// <summary>The three-cushion computer player: strokes whose simulated outcome is a point, within the cue's clearance.</summary>
public class ThreeCushionPlannerTests
{
    private static readonly GameRules Game = ThreeCushionRuleset.ThreeCushion;
    private static readonly TableSpec Table = TableSpec.FromPreset(CaromTable.Preset);
    private static readonly PhysicsParams Physics = BallSet.Carom.DefaultParams;
    private static readonly ShotPlanner Planner = new(Table, Physics);
    private static readonly PlannerBudget Budget = new(Threads: 1);

    private static TablePosition Break(GameState state)
    {
        var balls = Ruleset.For(Game).Rack(state, Table, Physics.R, 0);
        return new TablePosition(balls, Ruleset.For(Game).CueBall(state));
    }

    [Fact]
    public void TheBreakIsPlayedOnTheRedAndScoresWithoutError()
    {
        var state = new GameState(Game);
        var decision = Planner.Decide(state, Break(state), SkillLevel.Of(5), Budget, 7);
        Assert.NotNull(decision.ExpectedRuling);
        Assert.True(decision.ExpectedRuling!.Point, decision.ExpectedRuling.Message);
        Assert.Empty(decision.ExpectedRuling.Fouls);
        Assert.InRange(decision.ExpectedRuling.Cushions, 3, int.MaxValue);
        // The decision names the ball its stroke meets first: on the break, the red.
        Assert.Equal(BallSet.Red, decision.Target);
    }

    [Fact]
    public void TheSameDecisionForTheSameSeed()
    {
        var state = new GameState(Game);
        var a = Planner.Decide(state, Break(state), SkillLevel.Of(2), Budget, 3);
        var b = Planner.Decide(state, Break(state), SkillLevel.Of(2), new PlannerBudget(Threads: 2), 3);
        Assert.Equal(a.Shot, b.Shot);
    }

    [Fact]
    public void EveryStrokeOfAPositionBehindACushionPassesTheCueClearance()
    {
        // The white frozen nearly to the head cushion, the cue must be raised to play towards the foot.
        double r = Physics.R;
        var balls = new List<(BallId, Vec3)>
        {
            (BallSet.White, new Vec3(-Table.HalfLength + r + 0.002, 0.1, r)),
            (BallSet.Yellow, new Vec3(0.4, -0.3, r)),
            (BallSet.Red, new Vec3(0.9, 0.4, r)),
        };
        var state = new GameState(Game) { Shot = 3, Part = new ThreeCushionPart { Innings = new(2, 1) } };
        var position = new TablePosition(balls, BallSet.White);
        var decision = Planner.Decide(state, position, SkillLevel.Of(1), Budget, 11);
        var playable = CueClearance.Playable(decision.Shot, Table, r, position.Cue!.Value, position.Positions);
        Assert.Equal(playable.ElevationDeg, decision.Shot.ElevationDeg, 9);
    }
}
