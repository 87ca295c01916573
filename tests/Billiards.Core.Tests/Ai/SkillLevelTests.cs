using Billiards.Core.Ai;
using Billiards.Core.Cue;

namespace Billiards.Core.Tests.Ai;

/// <summary>The error model of each level against its documented standard deviations.</summary>
public class SkillLevelTests
{
    // The table of SkillLevel's remarks and the README: aim (deg), speed (fraction), tip (fraction of R).
    public static TheoryData<int, double, double, double> Documented => new()
    {
        { 1, 1.00, 0.12, 0.10 },
        { 2, 0.55, 0.08, 0.07 },
        { 3, 0.30, 0.05, 0.05 },
        { 4, 0.16, 0.035, 0.03 },
        { 5, 0.08, 0.02, 0.015 },
    };

    [Theory]
    [MemberData(nameof(Documented))]
    public void ExecutedShotsScatterWithTheDocumentedStandardDeviations(int level, double aim, double speed, double tip)
    {
        var skill = SkillLevel.Of(level);
        var planned = new ShotSpec(3, 10, 0, 0, 0);
        var random = new PlannerRandom(77);
        const int N = 40_000;
        double sa = 0, saa = 0, ss = 0, sss = 0, st = 0, stt = 0, sh = 0, shh = 0;
        for (int i = 0; i < N; i++)
        {
            var s = skill.Execute(planned, random);
            double da = s.AimDeg - planned.AimDeg, ds = s.Speed / planned.Speed - 1;
            sa += da; saa += da * da; ss += ds; sss += ds * ds;
            st += s.TipSide; stt += s.TipSide * s.TipSide; sh += s.TipHeight; shh += s.TipHeight * s.TipHeight;
            Assert.Equal(planned.ElevationDeg, s.ElevationDeg);
        }
        // With 40 000 samples the sample standard deviation is within 1.5 % of the true one
        // (its relative standard error is 1/sqrt(2N) = 0.35 %); the 4-sigma clamp removes 0.1 %.
        AssertStd(aim, sa, saa, N);
        AssertStd(speed, ss, sss, N);
        AssertStd(tip, st, stt, N);
        AssertStd(tip, sh, shh, N);
    }

    [Fact]
    public void TheSameStreamGivesTheSameShotAndDerivedStreamsDiffer()
    {
        var skill = SkillLevel.Of(3);
        var planned = new ShotSpec(2, 45, 0.1, 0.2, 0);
        Assert.Equal(skill.Execute(planned, new PlannerRandom(5)), skill.Execute(planned, new PlannerRandom(5)));
        Assert.NotEqual(PlannerRandom.Derive(1, 0, 0), PlannerRandom.Derive(1, 0, 1));
        Assert.NotEqual(PlannerRandom.Derive(1, 0, 0), PlannerRandom.Derive(1, 1, 0));
        Assert.NotEqual(PlannerRandom.Derive(1, 0, 0), PlannerRandom.Derive(2, 0, 0));
    }

    [Fact]
    public void LowerLevelsSearchLessAndLookAheadLess()
    {
        for (int level = 2; level <= 5; level++)
        {
            var lower = SkillLevel.Of(level - 1);
            var upper = SkillLevel.Of(level);
            Assert.True(lower.AimStdDeg > upper.AimStdDeg);
            Assert.True(lower.Candidates * lower.Speeds * lower.Spins * lower.Samples < upper.Candidates * upper.Speeds * upper.Spins * upper.Samples);
            Assert.True(lower.LookAhead <= upper.LookAhead);
        }
        Assert.Equal(0, SkillLevel.Of(1).LookAhead);
        Assert.Equal(1, SkillLevel.Of(5).LookAhead);
        Assert.Throws<ArgumentOutOfRangeException>(() => SkillLevel.Of(0));
        Assert.Throws<ArgumentOutOfRangeException>(() => SkillLevel.Of(6));
    }

    private static void AssertStd(double expected, double sum, double sumSquares, int n)
    {
        double mean = sum / n;
        double std = Math.Sqrt(sumSquares / n - mean * mean);
        Assert.InRange(std, expected * 0.985, expected * 1.015);
        Assert.InRange(mean, -4 * expected / Math.Sqrt(n), 4 * expected / Math.Sqrt(n));
    }
}
