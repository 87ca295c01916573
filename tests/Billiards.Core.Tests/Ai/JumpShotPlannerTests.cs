using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Xunit.Abstractions;

namespace Billiards.Core.Tests.Ai;

public sealed class JumpShotPlannerTests(ITestOutputHelper output)
{
    private static readonly double R = PlannerKit.Params.R;

    [Theory]
    [InlineData(0.20, 0.0)]
    [InlineData(0.30, 0.01)]
    [InlineData(0.25, -0.02)]
    public void JumpStrokesHopTheBlockerAndMeetTheTargetFirst(double blockerAt, double blockerOffset)
    {
        var cue = new Vec3(-0.8, 0, R);
        var target = new Vec3(0.1, 0.05, R);
        var u = (target - cue).XY.Normalized();
        var blocker = cue + (u * blockerAt) + (new Vec3(-u.Y, u.X, 0) * blockerOffset);
        var position = new TablePosition([(PoolBalls.Cue, cue), (new BallId(1), target), (new BallId(9), blocker), (new BallId(10), new Vec3(0.8, -0.5, R))], PoolBalls.Cue);
        Assert.True(PlannerKit.Planner.Table.Blocked(position, cue, target, new BallId(1)));
        var strokes = PlannerKit.Planner.JumpStrokes(position, new BallId(1), target);
        Assert.NotEmpty(strokes);
        foreach (var (speed, elevation) in strokes)
        {
            double aim = Math.Atan2(u.Y, u.X) * 180 / Math.PI;
            var shot = new ShotSpec(speed, aim, 0, 0, elevation); // through the centre, in the cue's frame
            // Playable as it is: the cue clears the rail and every ball behind the cue ball.
            Assert.Equal(shot, CueClearance.Playable(shot, PlannerKit.Pool, R, cue, position.Positions));
            var record = PlannerKit.Simulate(position, shot);
            var events = record.Events.ToArray();
            var contacts = events.Where(e => e.Kind == EventKind.BallBall).ToList();
            output.WriteLine($"blocker at {blockerAt} m: {speed:0.00} m/s at {elevation} deg, first contact {contacts.FirstOrDefault().B}");
            Assert.NotEmpty(contacts);
            Assert.Equal((PoolBalls.Cue, new BallId(1)), (contacts[0].A, contacts[0].B));
            Assert.DoesNotContain(events, e => e.Kind == EventKind.BallBall && e.B == new BallId(9) && e.Time < contacts[0].Time);
        }
    }

    [Fact]
    public void NoJumpClearsABlockerTouchingTheTarget()
    {
        // The target sits right behind the blocker: no hop comes down between them.
        var cue = new Vec3(-0.8, 0, R);
        var blocker = new Vec3(-0.4, 0, R);
        var target = blocker + new Vec3(2 * R + 0.001, 0, 0);
        var position = new TablePosition([(PoolBalls.Cue, cue), (new BallId(1), target), (new BallId(9), blocker)], PoolBalls.Cue);
        Assert.Empty(PlannerKit.Planner.JumpStrokes(position, new BallId(1), target));
    }

    [Fact]
    public void AJumpStrokesTipScattersAboutTheCentreAndNeverMiscues()
    {
        // The tip is in the cue's frame: a jump stroke is aimed at [0, 0] and keeps its mean there,
        // and the player's scatter stays inside the miscue limit at every elevation.
        var skill = SkillLevel.Of(1);
        var random = new PlannerRandom(3);
        foreach (double elevation in (double[])[0, 55])
        {
            double sum = 0;
            const int N = 4000;
            for (int i = 0; i < N; i++)
            {
                var s = skill.Execute(new ShotSpec(3, 0, 0.2, 0.3, elevation), random);
                sum += s.TipHeight;
                Assert.False(CueStrike.IsMiscue(s, PhysicsParams.Pool), $"a miscue at {elevation} deg: [{s.TipSide}, {s.TipHeight}]");
            }
            Assert.Equal(0.3, sum / N, 0.02);
        }
    }

    [Fact]
    public void FromSnookersTheLevelFourPlayerJumpsSometimesAndPlaysOnlyPlayableShots()
    {
        var positions = Snookers.Positions(PlannerKit.Pool, R, 10, 1);
        Assert.Equal(10, positions.Count);
        foreach (var p in positions)
        {
            var cue = p.Position.Cue!.Value;
            Assert.All(PlannerTable.LegalTargets(p.State, p.Position), t => Assert.True(PlannerKit.Planner.Table.Blocked(p.Position, cue, p.Position.Positions[p.Position.IndexOf(t)], t)));
        }
        var budget = new PlannerBudget(600_000, Threads: 1);
        var with = Snookers.Measure(PlannerKit.Planner, positions, 4, 2, 1, budget);
        var without = Snookers.Measure(new ShotPlanner(PlannerKit.Pool, PlannerKit.Params) { ConsiderJumps = false }, positions, 4, 2, 1, budget);
        output.WriteLine($"with jumps {with}; without {without}");
        Assert.Equal(0, with.Unplayable);
        Assert.Equal(0, without.Jumps);
        Assert.True(with.Jumps > 0, "no jump chosen from ten snookers");
        // Level 3 never jumps.
        Assert.Equal(0, Snookers.Measure(PlannerKit.Planner, positions, 3, 1, 1, budget).Jumps);
    }
}
