using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Table;
using Vec3 = Billiards.Core.Mathematics.Vec3;
using static Billiards.Core.Tests.Ai.PlannerKit;

namespace Billiards.Core.Tests.Ai;

/// <summary>The candidates the planner's search starts from.</summary>
public class CandidateGeneratorTests
{
    // Seven stripes spread over the table and the cue ball in the middle: every one is in view.
    private static TablePosition OpenTable()
    {
        var balls = new List<(BallId, Vec3)> { (PoolBalls.Cue, new Vec3(0, 0, Params.R)) };
        for (int i = 0; i < 7; i++)
        {
            double a = 2 * Math.PI * i / 7;
            balls.Add((new BallId(9 + i), new Vec3(0.5 * Math.Cos(a), 0.35 * Math.Sin(a), Params.R)));
        }
        return new TablePosition(balls, PoolBalls.Cue);
    }

    [Fact]
    public void SafetiesTakeEveryLegalTargetInTurnSoThatTheFirstFewCoverEveryBall()
    {
        var position = OpenTable();
        var state = new GameState(GameRules.EightBall) { Shot = 5, Shooter = 1, Part = new EightBallPart { Groups = new PerPlayer<BallGroup>(BallGroup.Solids, BallGroup.Stripes) } };

        var safeties = CandidateGenerator.Safeties(Planner.Table, state, position, position.Cue!.Value);

        // Level 5 searches the first candidates / 2 + 2 = 10: the first seven are one per stripe.
        Assert.Equal(Enumerable.Range(9, 7).Select(i => new BallId(i)), safeties.Take(7).Select(c => c.Target));
        // Each stripe gets five contacts at each of three speeds.
        Assert.All(safeties.GroupBy(c => c.Target), g => Assert.Equal(15, g.Count()));
        Assert.Equal(3, safeties.Where(c => c.Target == new BallId(9)).Select(c => c.BaseSpeed).Distinct().Count());
    }
}

/// <summary>How the planner declares the shot it chose.</summary>
public class DeclarationTests
{
    private static readonly Candidate Pot = new(ShotKind.Direct, new BallId(3), new BallId(3), PoolPockets.FootLeft, Vec3.Zero, new Vec3(1, 0, 0), Vec3.Zero, 2, 0.9);
    private static readonly Call Called = new(new BallId(3), PoolPockets.FootLeft);

    [Fact]
    public void APotThatNoneOfItsSimulationsMadeIsPlayedAndCalledAsASafety()
    {
        Assert.Equal((ShotKind.Safety, PocketId.None, (Call?)Call.Safety), ShotPlanner.Declared(Pot, Called, pots: 0, simulations: 73));
        // Where the game calls nothing, nothing is called.
        Assert.Equal((ShotKind.Safety, PocketId.None, (Call?)null), ShotPlanner.Declared(Pot, null, 0, 73));
        // A kick with a pocket is a pot; a bank too.
        Assert.Equal(ShotKind.Safety, ShotPlanner.Declared(Pot with { Kind = ShotKind.Kick }, Called, 0, 73).Kind);
        Assert.Equal(ShotKind.Safety, ShotPlanner.Declared(Pot with { Kind = ShotKind.Bank }, Called, 0, 73).Kind);
    }

    [Fact]
    public void APotThatSomeSimulationMadeOrThatHadTooFewSimulationsStaysAPot()
    {
        Assert.Equal((ShotKind.Direct, PoolPockets.FootLeft, (Call?)Called), ShotPlanner.Declared(Pot, Called, pots: 1, simulations: 73));
        Assert.Equal((ShotKind.Direct, PoolPockets.FootLeft, (Call?)Called), ShotPlanner.Declared(Pot, Called, 0, ShotPlanner.SafetyEvidence - 1));
        // A kick without a pocket is a safety already and stays what it is.
        var kick = Pot with { Kind = ShotKind.Kick, Pocket = PocketId.None };
        Assert.Equal((ShotKind.Kick, PocketId.None, (Call?)Call.Safety), ShotPlanner.Declared(kick, Call.Safety, 0, 73));
    }
}

/// <summary>How a level judges the opponent's reply.</summary>
public class OpponentJudgementTests
{
    [Fact]
    public void APlayerJudgesTheOpponentAtLeastAsGoodAsItselfAndAsTheReferencePlayer()
    {
        for (int level = SkillLevel.Min; level <= SkillLevel.Max; level++)
        {
            var s = SkillLevel.Of(level);
            Assert.Equal(Math.Min(s.PositionAimStdDeg, PlannerTable.ReferenceAimStdDeg), s.OpponentAimStdDeg);
        }
        Assert.Equal(0.2, SkillLevel.Of(5).OpponentAimStdDeg, 12);
        Assert.Equal(PlannerTable.ReferenceAimStdDeg, SkillLevel.Of(3).OpponentAimStdDeg);
    }

    [Fact]
    public void LeavingAnOpenShotCostsAStrongPlayerMoreThanAWeakOne()
    {
        // A legal miss that leaves the opponent a long cut: level 5 fears it more than level 3.
        var position = StraightIn(PoolPockets.FootLeft, 1.2, 0.8);
        var state = new GameState(GameRules.NineBall) { Shot = 4 };
        var miss = new Ruling(true, [], [], false, BallInHand.None, [], [], false, null, "", state with { Shooter = 1, Shot = 5 });
        double strong = Planner.Score(state, miss, position, SkillLevel.Of(5));
        double weak = Planner.Score(state, miss, position, SkillLevel.Of(3));
        Assert.True(strong < weak, $"level 5 {strong}, level 3 {weak}");
    }
}
