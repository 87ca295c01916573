using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Ai.PlannerKit;

namespace Billiards.Core.Tests.Ai;

/// <summary>The planner on positions whose right answer is known.</summary>
public class ShotPlannerTests
{
    private static readonly GameState NineBall = new(GameRules.NineBall) { Shot = 3 };

    [Fact]
    public void AStraightInPotIsChosenAndItsShotPotsTheBall()
    {
        // The 9 alone, straight in: any pot wins, so nothing but the pot itself counts.
        var line = StraightIn(PoolPockets.FootLeft, 0.5, 0.6);
        var nine = new BallId(9);
        var position = new TablePosition([(PoolBalls.Cue, line.Cue!.Value), (nine, line.Positions[line.IndexOf(new BallId(1))])], PoolBalls.Cue);
        var decision = Planner.Decide(NineBall, position, SkillLevel.Of(5), new PlannerBudget(60_000, 2), 11);

        Assert.Equal(nine, decision.Target);
        Assert.Equal(ShotKind.Direct, decision.Kind);
        Assert.Equal(PoolPockets.FootLeft, decision.Pocket);
        Assert.Null(decision.Place);
        var record = Simulate(position, decision.Shot);
        Assert.Equal(PoolPockets.FootLeft, record.PocketedOnShot(nine));
        Assert.False(record.IsPocketedAfter(PoolBalls.Cue));
        Assert.True(decision.ExpectedPot > 0.9, $"expected pot {decision.ExpectedPot}");
    }

    [Fact]
    public void EightBallCallsTheBallAndPocketItPlays()
    {
        var position = StraightIn(PoolPockets.SideLeft, 0.4, 0.5);
        var state = new GameState(GameRules.EightBall) { Shot = 2 };
        var decision = Planner.Decide(state, position, SkillLevel.Of(4), new PlannerBudget(60_000, 2), 3);

        Assert.Equal(new Call(new BallId(decision.Kind == ShotKind.Combination ? 2 : 1), decision.Pocket), decision.Call);
        var record = Simulate(position, decision.Shot);
        Assert.Equal(decision.Call!.Pocket, record.PocketedOnShot(decision.Call.Ball));
    }

    [Fact]
    public void TheSameSeedGivesTheSameDecisionOnOneThreadAndOnTwo()
    {
        var state = new GameState(GameRules.EightBall) { Shot = 0 };
        var position = TablePosition.Rack(new Billiards.Core.Setup.RackSpec(Billiards.Core.Setup.RackGame.EightBall, 5), Pool, Params.R, PoolBalls.Cue);
        var broken = Simulate(position, new Billiards.Core.Cue.ShotSpec(7, 0.3, 0, -0.2));
        var after = TablePosition.After(broken);
        var open = new GameState(GameRules.EightBall) { Shot = 1, BallInHand = after.Cue is null ? BallInHand.Table : BallInHand.None };

        var one = Planner.Decide(open, after, SkillLevel.Of(3), new PlannerBudget(600_000, 1), 42);
        var two = Planner.Decide(open, after, SkillLevel.Of(3), new PlannerBudget(600_000, 2), 42);
        var again = Planner.Decide(open, after, SkillLevel.Of(3), new PlannerBudget(600_000, 2), 42);

        Assert.Equal(one.Shot, two.Shot);
        Assert.Equal(one.Place, two.Place);
        Assert.Equal(one.Call, two.Call);
        Assert.Equal(one.ExpectedScore, two.ExpectedScore);
        Assert.Equal(one.Simulations, two.Simulations);
        Assert.Equal(two.Shot, again.Shot);
        Assert.Equal(two.ExpectedPot, again.ExpectedPot);
    }

    [Fact]
    public async Task TheSearchRunsOnTheCallersSchedulerAndDecidesAsItDoesOnThePool()
    {
        var line = StraightIn(PoolPockets.FootLeft, 0.5, 0.6);
        var state = NineBall;
        var plain = Planner.Decide(state, line, SkillLevel.Of(3), new PlannerBudget(600_000, 2), 5);

        var scheduler = new CountingScheduler();
        var scheduled = await Task.Factory.StartNew(
            () => Planner.Decide(state, line, SkillLevel.Of(3), new PlannerBudget(600_000, 2), 5),
            CancellationToken.None, TaskCreationOptions.None, scheduler);

        // The outer task and at least one worker of the parallel search were queued to it.
        Assert.True(scheduler.Queued >= 2, $"queued {scheduler.Queued}");
        Assert.Equal(plain.Shot, scheduled.Shot);
        Assert.Equal(plain.ExpectedScore, scheduled.ExpectedScore);
    }

    /// <summary>Runs each task on a new thread and counts them.</summary>
    private sealed class CountingScheduler : TaskScheduler
    {
        private int _queued;

        public int Queued => _queued;

        protected override void QueueTask(Task task)
        {
            Interlocked.Increment(ref _queued);
            new Thread(() => TryExecuteTask(task)) { IsBackground = true }.Start();
        }

        protected override bool TryExecuteTaskInline(Task task, bool taskWasPreviouslyQueued) => false;

        protected override IEnumerable<Task> GetScheduledTasks() => [];
    }

    [Fact]
    public void BallInHandPlacesTheCueBallLegallyAndPots()
    {
        var position = StraightIn(PoolPockets.HeadRight, 0.4, 0.5).Without(PoolBalls.Cue);
        var state = NineBall with { BallInHand = BallInHand.Table };
        var decision = Planner.Decide(state, position, SkillLevel.Of(5), new PlannerBudget(60_000, 2), 9);

        var place = Assert.NotNull(decision.Place);
        Assert.True(position.CanPlace(place, BallInHand.Table, Pool, Params.R, PoolBalls.Cue));
        var record = Simulate(position, decision.Shot, place);
        var ruling = Referee.For(GameRules.NineBall, Pool, Params.R).Judge(state with { Placement = place }, record);
        Assert.True(ruling.Legal);
        Assert.True(ruling.Continue);
    }

    [Fact]
    public void TheBreakIsPlacedBehindTheHeadString()
    {
        var position = TablePosition.Rack(new Billiards.Core.Setup.RackSpec(Billiards.Core.Setup.RackGame.NineBall, 1), Pool, Params.R, PoolBalls.Cue);
        var decision = Planner.Decide(new GameState(GameRules.NineBall), position, SkillLevel.Of(2), new PlannerBudget(60_000, 2), 1);

        Assert.Equal(ShotKind.Break, decision.Kind);
        var place = Assert.NotNull(decision.Place);
        Assert.True(place.X < -Pool.HalfLength / 2);
        Assert.Null(decision.Call);
    }

    [Fact]
    public void LevelFiveMakesEasyStraightInShotsWithItsOwnError()
    {
        // Twelve straight-in shots of 0.3 to 0.9 m to the pocket with the cue ball 0.3 to 0.6 m
        // behind, into corners and sides; level 5 strikes each with its error. A strong
        // professional misses almost none of these.
        var level = SkillLevel.Of(5);
        int made = 0, total = 0;
        PocketId[] pockets = [PoolPockets.FootLeft, PoolPockets.FootRight, PoolPockets.HeadLeft, PoolPockets.SideLeft, PoolPockets.SideRight, PoolPockets.HeadRight];
        for (int i = 0; i < 12; i++)
        {
            var position = StraightIn(pockets[i % 6], 0.3 + 0.1 * (i % 7), 0.3 + 0.05 * (i % 5));
            var decision = Planner.Decide(NineBall, position, level, new PlannerBudget(60_000, 2), (ulong)i);
            var executed = level.Execute(decision.Shot, new PlannerRandom(PlannerRandom.Derive(1234, i)));
            var record = Simulate(position, executed);
            var ruling = Referee.For(GameRules.NineBall, Pool, Params.R).Judge(NineBall, record);
            made += ruling.Continue ? 1 : 0;
            total++;
        }
        Assert.True(made >= 11, $"level 5 made {made} of {total} easy straight-in shots");
    }

    [Fact]
    public void ThrowCorrectionOvercutsAStunnedCut()
    {
        // A 30 deg cut to the left with a stun shot: the object ball is thrown towards the cue
        // ball's path, so the corrected aim sends the ghost further to the right of the object ball.
        var o = new Billiards.Core.Mathematics.Vec3(0.3, 0, Params.R);
        var cue = new Billiards.Core.Mathematics.Vec3(-0.3, 0, Params.R);
        double a = 30 * Math.PI / 180;
        var u = new Billiards.Core.Mathematics.Vec3(Math.Cos(a), Math.Sin(a), 0);
        var ghost = o - u * (2 * Params.R);
        var c = new Candidate(ShotKind.Direct, new BallId(1), new BallId(1), PoolPockets.FootLeft, o, u, ghost, 2, 1);
        var d = ghost - cue;
        double plain = Math.Atan2(d.Y, d.X) * 180 / Math.PI;
        double corrected = Planner.AimFor(c, cue, 0, 0);
        // Stun at 30 deg with mu_b = 0.05: tan(throw) = min(mu sin/slip, 2 sin/(7 (1+e) cos)) = about 0.045
        // rad at the object ball, i.e. the aim turns clockwise (more cut), by less than a degree.
        Assert.True(corrected < plain, $"corrected {corrected} deg, plain {plain} deg");
        Assert.True(plain - corrected < 1.5);
    }
}

/// <summary>Position play: the look-ahead's judgement of a leave, and a shot chosen for its leave.</summary>
public class PositionPlayTests
{
    private static readonly GameState Solids = new(GameRules.EightBall)
    {
        Shot = 5,
        Part = new EightBallPart { Groups = new PerPlayer<BallGroup>(BallGroup.Solids, BallGroup.Stripes) },
    };

    [Fact]
    public void ABallWithEveryWayToAPocketBlockedIsAProblemBall()
    {
        // The 1 in the middle of the table; a stripe on the line to each of the six pockets, 0.15 m out.
        var table = Planner.Table;
        var one = new Vec3(0.2, 0.1, Params.R);
        var balls = new List<(BallId, Vec3)> { (PoolBalls.Cue, new Vec3(-0.9, -0.4, Params.R)), (new BallId(1), one), (new BallId(8), new Vec3(-1.0, 0.45, Params.R)) };
        int id = 9;
        foreach (var pocket in PoolPockets.All)
        {
            var u = (table.AimPoint(pocket) - one).XY.Normalized();
            balls.Add((new BallId(id++), (one + u * 0.15) with { Z = Params.R }));
        }
        var blocked = new TablePosition(balls, PoolBalls.Cue);
        Assert.Equal(1, table.ProblemBalls(blocked, Solids));

        // Take away the stripe towards one pocket: the 1 has a way again.
        var opened = blocked.Without(new BallId(9));
        Assert.Equal(0, table.ProblemBalls(opened, Solids));
    }

    [Fact]
    public void TheLookAheadWeighsTheNextButOneChoice()
    {
        // A long straight-in shot on the 1 and a shorter one on the 2 just behind the cue ball: the
        // 2 is the best next shot, the 1 the next-but-one choice. Without the 2, the 1 is all there is.
        var line = StraightIn(PoolPockets.FootLeft, 1.0, 1.0);
        var cue = line.Cue!.Value;
        var one = line.Positions[line.IndexOf(new BallId(1))];
        var eight = new Vec3(-1.1, 0.5, Params.R);
        var two = new TablePosition([(PoolBalls.Cue, cue), (new BallId(1), one), (new BallId(2), new Vec3(cue.X - 0.3, cue.Y, Params.R)), (new BallId(8), eight)], PoolBalls.Cue);
        var single = new TablePosition([(PoolBalls.Cue, cue), (new BallId(1), one), (new BallId(8), eight)], PoolBalls.Cue);
        double sigma = PlannerTable.ReferenceAimStdDeg;
        var table = Planner.Table;

        // One ball to play: the quality is that shot's ease, neither more nor less.
        double oneAlone = table.BestEase(single, Solids, sigma);
        Assert.InRange(oneAlone, 0.05, 0.95);
        Assert.Equal(oneAlone, table.PositionQuality(single, Solids, sigma), 12);
        // Two: between the harder and the easier shot, nearer the easier (0.85 and 0.15).
        double best = table.BestEase(two, Solids, sigma);
        Assert.True(best > oneAlone + 0.1, $"the 2's shot {best}, the 1's {oneAlone}");
        double quality = table.PositionQuality(two, Solids, sigma);
        Assert.Equal(0.85 * best + 0.15 * oneAlone, quality, 9);
    }
}
