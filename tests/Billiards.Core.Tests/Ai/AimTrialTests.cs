using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Ai.PlannerKit;

namespace Billiards.Core.Tests.Ai;

/// <summary>Aim by trial: the middle of the range of aims that pot.</summary>
public class AimTrialTests
{
    private const double Step = ShotPlanner.AimTrialStepDeg;

    [Theory]
    // A range inside the tried span: both ends found to a quarter step, so the middle to an eighth.
    [InlineData(0.37, 1.05)]
    [InlineData(-0.95, -0.12)]
    [InlineData(-0.5, 0.61)]
    public void TheMiddleOfAPottingRangeInsideTheTriedSpanIsFoundToAnEighthOfAStep(double lo, double hi)
    {
        var (aim, trials) = ShotPlanner.CentredAim(a => a >= lo && a <= hi, 0, 4);

        Assert.InRange(aim, (lo + hi) / 2 - Step / 8, (lo + hi) / 2 + Step / 8);
        Assert.Equal(9 + 4, trials);
    }

    [Fact]
    public void OfTwoPottingRangesTheOneNearerTheGeometricAimIsTaken()
    {
        // A kiss spoils the middle: the aims that pot are [-1.1, -0.55] and [0.2, 0.7].
        var (aim, _) = ShotPlanner.CentredAim(a => (a >= -1.1 && a <= -0.55) || (a >= 0.2 && a <= 0.7), 0, 4);

        Assert.InRange(aim, 0.45 - Step / 8, 0.45 + Step / 8);
    }

    [Fact]
    public void ARangeWiderThanTheTriedSpanKeepsItsMiddleWithinTheSpan()
    {
        var (aim, trials) = ShotPlanner.CentredAim(a => a >= -0.7 && a <= 5, 10, 4);

        // Everything tried pots: the middle of the tried span is the aim itself.
        Assert.Equal(10, aim, 12);
        Assert.Equal(9, trials);
    }

    [Fact]
    public void WithoutAPottingAimTheGeometricAimStays()
    {
        var (aim, trials) = ShotPlanner.CentredAim(_ => false, 12.5, 4);

        Assert.Equal(12.5, aim);
        Assert.Equal(9, trials);
    }

    [Fact]
    public void AimingByTrialStopsAtTheTimeCap()
    {
        // A cap of 0 ms is passed before the first trial: no thread takes a variation, and the one
        // simulation left is the chosen shot's without error. Without the cap the trials alone
        // would be 13 for each of the hundreds of pot variations of level 5.
        var position = StraightIn(PoolPockets.FootLeft, 0.5, 0.6);
        var state = new GameState(GameRules.NineBall) { Shot = 3 };

        var capped = Planner.Decide(state, position, SkillLevel.Of(5), new PlannerBudget(0, 2), 1);
        var free = Planner.Decide(state, position, SkillLevel.Of(5), new PlannerBudget(60_000, 2), 1);

        Assert.InRange(capped.Simulations, 1, 1 + 2 * 13);
        Assert.True(free.Simulations > 1000, $"{free.Simulations} simulations without the cap");
    }

    [Fact]
    public void LevelsThreeToFiveAimByTrialAndLevelsOneAndTwoByTheGeometry()
    {
        Assert.Equal([0, 0, 4, 4, 4], Enumerable.Range(1, 5).Select(l => SkillLevel.Of(l).AimTrials));
    }

    [Theory]
    // The 9 1.5 cm off the long cushion, about 0.37 m from the foot-left corner, cut along the cushion from
    // the middle of the table: the pocket's jaw takes the ball off centre, and the geometric aim lies
    // 0.19 deg from the middle of a 1.05 deg range (level 5 errs by 0.08 deg).
    [InlineData(0.9, 0.015, 0.1, 0.0)]
    // Near the cushion, played from its side of the table with draw.
    [InlineData(0.6, 0.02, -0.2, -0.3)]
    public void TheChosenAimOfACutAlongTheCushionLiesInTheMiddleOfItsPottingRange(double ox, double gap, double cx, double cy)
    {
        var o = new Vec3(ox, Pool.HalfWidth - Params.R - gap, Params.R);
        var cue = new Vec3(cx, cy, Params.R);
        var position = new TablePosition([(PoolBalls.Cue, cue), (new BallId(9), o)], PoolBalls.Cue);
        var state = new GameState(GameRules.NineBall) { Shot = 3 };

        var decision = Planner.Decide(state, position, SkillLevel.Of(5), new PlannerBudget(60_000, 2), 5);
        Assert.Equal(ShotKind.Direct, decision.Kind);
        Assert.Equal(PoolPockets.FootLeft, decision.Pocket);

        // The potting range around the chosen aim, to 0.01 deg, by simulating without error.
        bool Pots(double deg)
        {
            var record = Simulate(position, decision.Shot with { AimDeg = deg });
            return record.PocketedOnShot(new BallId(9)) == PoolPockets.FootLeft && !record.IsPocketedAfter(PoolBalls.Cue);
        }
        Assert.True(Pots(decision.Shot.AimDeg));
        double lo = decision.Shot.AimDeg, hi = decision.Shot.AimDeg;
        while (Pots(lo - 0.01))
        {
            lo -= 0.01;
        }
        while (Pots(hi + 0.01))
        {
            hi += 0.01;
        }
        double half = (hi - lo) / 2;
        // Found to an eighth of a step by the search (plus the 0.01 deg of this scan): the aim is
        // nowhere near an edge, so the player's error is spent on both sides of the pocket alike.
        Assert.True(half > 0.1, $"range {lo:F2} to {hi:F2} deg");
        Assert.InRange(decision.Shot.AimDeg, (lo + hi) / 2 - Step / 8 - 0.01, (lo + hi) / 2 + Step / 8 + 0.01);
    }
}
