using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Ai;

/// <summary>The planner's variation sampler turned on a person's shot (<see cref="ShotPlanner.Sensitivity"/>).</summary>
public class SensitivityTests
{
    private static readonly BallId Cue = BallSet.Pool.CueBalls[0];

    private static readonly ShotPlanner Planner = new(TableSpec.FromPreset("pool-9ft"), PhysicsParams.Default);

    // A straight pot of 30 cm into the foot-left corner's capture circle, and a long thin cut.
    private static (TablePosition Position, ShotSpec Shot) Straight()
    {
        var pocket = new Vec3(1.2492331577200275, 0.6142331577200276, PhysicsParams.DefaultRadius);
        var one = new Vec3(0.95, 0.4, PhysicsParams.DefaultRadius);
        var u = (pocket - one).Normalized();
        var cue = one - (u * 0.3);
        double aim = Math.Atan2(u.Y, u.X) * 180 / Math.PI;
        return (new TablePosition([(Cue, cue), (new BallId(1), one)], Cue), new ShotSpec(2.0, aim, 0, 0, 0));
    }

    [Fact]
    public void TheSameShotSeedAndLevelGiveTheSameEndingsAndTheErrorsAreTheLevelS()
    {
        var (position, shot) = Straight();
        var a = Planner.Sensitivity(position, shot, SkillLevel.Of(3), 24, 7, new BallId(1));
        var b = Planner.Sensitivity(position, shot, SkillLevel.Of(3), 24, 7, new BallId(1));
        Assert.Equal(24, a.Endings.Count);
        Assert.Equal(a.Endings, b.Endings);
        // Every sample is the planned shot with the level's own error: sample i is SkillLevel.Execute with stream i.
        for (int i = 0; i < a.Endings.Count; i++)
        {
            Assert.Equal(SkillLevel.Of(3).Execute(shot, new PlannerRandom(PlannerRandom.Derive(7, i))), a.Endings[i].Shot);
        }
        Assert.True(a.Endings.Select(e => e.Shot.AimDeg).Distinct().Count() > 20, "the aim varies");
        var other = Planner.Sensitivity(position, shot, SkillLevel.Of(3), 24, 8, new BallId(1));
        Assert.NotEqual(a.Endings, other.Endings);
    }

    [Fact]
    public void AShortStraightPotIsSureAtLevel5AndALongThinCutPotsLessOftenAtLevel1()
    {
        var (position, shot) = Straight();
        var sure = Planner.Sensitivity(position, shot, SkillLevel.Of(5), 40, 1, new BallId(1));
        Assert.Equal(40, sure.Pots);
        Assert.Equal(1.0, sure.PotRate);
        // Each potted sample's target is gone; each ending has the cue ball on the table.
        Assert.All(sure.Endings, e => Assert.Null(e.Target));
        Assert.All(sure.Endings, e => Assert.NotNull(e.Cue));

        // The same ball cut thin from 1.5 m: level 1's error misses it often, level 5's much less.
        var pocket = new Vec3(1.2492331577200275, 0.6142331577200276, PhysicsParams.DefaultRadius);
        var one = new Vec3(0.95, 0.4, PhysicsParams.DefaultRadius);
        var u = (pocket - one).Normalized();
        var ghost = one - (u * (2 * PhysicsParams.DefaultRadius));
        double cut = 50 * Math.PI / 180;
        var back = new Vec3(-u.X * Math.Cos(cut) + u.Y * Math.Sin(cut), -u.X * Math.Sin(cut) - u.Y * Math.Cos(cut), 0);
        var cue = ghost + (back * 1.5);
        var thin = new TablePosition([(Cue, cue), (new BallId(1), one)], Cue);
        var d = ghost - cue;
        var cutShot = new ShotSpec(3.0, Math.Atan2(d.Y, d.X) * 180 / Math.PI, 0, 0, 0);
        var beginner = Planner.Sensitivity(thin, cutShot, SkillLevel.Of(1), 40, 1, new BallId(1));
        var pro = Planner.Sensitivity(thin, cutShot, SkillLevel.Of(5), 40, 1, new BallId(1));
        Assert.True(beginner.PotRate < 0.7, $"level 1 pots {beginner.Pots} of 40");
        Assert.True(pro.PotRate > beginner.PotRate + 0.2, $"level 5 pots {pro.Pots}, level 1 {beginner.Pots}");
        // A missed sample leaves the 1 on the table, and says where.
        Assert.All(beginner.Endings.Where(e => !e.Potted && e.Cue is not null), e => Assert.NotNull(e.Target));
    }

    [Fact]
    public void TheSampleCountIsBounded()
    {
        var (position, shot) = Straight();
        Assert.Throws<ArgumentOutOfRangeException>(() => Planner.Sensitivity(position, shot, SkillLevel.Of(3), 0, 1));
        Assert.Throws<ArgumentOutOfRangeException>(() => Planner.Sensitivity(position, shot, SkillLevel.Of(3), ShotPlanner.MaxSensitivitySamples + 1, 1));
    }
}
