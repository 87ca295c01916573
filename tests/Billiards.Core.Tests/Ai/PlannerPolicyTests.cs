using Billiards.Core.Ai;
using Billiards.Core.Rules;

namespace Billiards.Core.Tests.Ai;

/// <summary>The planner takes its policy from the ruleset's planner role, never from which game it is.</summary>
public class PlannerPolicyTests
{
    [Fact]
    public void SnookerPlaysTheSnookerPolicyAndEveryOtherShippedGamePools()
    {
        Assert.Same(PlannerPolicy.Snooker, Ruleset.For(GameRules.Snooker).Policy);
        foreach (var game in new[] { GameRules.EightBall, GameRules.NineBall, GameRules.TenBall, GameRules.StraightPool, ThreeCushionRuleset.ThreeCushion })
        {
            Assert.Same(PlannerPolicy.Pool, Ruleset.For(game).Policy);
        }
    }

    [Fact]
    public void ThePoliciesKeepThePlannersWeights()
    {
        Assert.Equal(new PlannerPolicy(ShotPlanner.OpponentWeight, 0, 0, false, false), PlannerPolicy.Pool);
        Assert.Equal(new PlannerPolicy(ShotPlanner.SnookerOpponentWeight, 2, 24, true, true), PlannerPolicy.Snooker);
    }
}
