using Billiards.Core.Ai;
using Billiards.Core.Cue;
using Billiards.Core.Rules;
using static Billiards.Core.Tests.Ai.PlannerKit;

namespace Billiards.Core.Tests.Ai;

/// <summary>Execution noise (<c>--noise fastfiz[:K]</c>): its parsing, its errors, and games played under it.</summary>
public class ExecutionNoiseTests
{
    private static readonly double R = Params.R;

    [Theory]
    [InlineData("fastfiz", 1.0)]
    [InlineData("fastfiz:5", 5.0)]
    [InlineData("fastfiz:0.5", 0.5)]
    [InlineData("fastfiz:0", 0.0)]
    public void ANameAndScaleParse(string text, double scale)
    {
        var noise = ExecutionNoise.TryParse(text, out string problem);
        Assert.NotNull(noise);
        Assert.Equal("", problem);
        Assert.Equal(scale, noise.Scale);
        Assert.Equal(0.125 * scale, noise.AimStdDeg, 12);
        Assert.Equal(0.1 * scale, noise.ElevationStdDeg, 12);
        Assert.Equal(0.075 * scale, noise.SpeedStd, 12);
        Assert.Equal(0.0005 * scale, noise.TipStd, 12);
        Assert.Equal(noise, ExecutionNoise.TryParse(noise.ToString(), out _));
    }

    [Theory]
    [InlineData("foo")]
    [InlineData("fastfiz:-1")]
    [InlineData("fastfiz:NaN")]
    [InlineData("fastfiz:")]
    [InlineData("fastfiz:1e400")]
    [InlineData("fastfiz:101")]
    [InlineData("FastFiz")]
    public void ABadNoiseIsRefusedWithAReason(string text)
    {
        Assert.Null(ExecutionNoise.TryParse(text, out string problem));
        Assert.NotEqual("", problem);
    }

    // Each of the five errors has mean 0 and the model's standard deviation: 20000 draws put the
    // sample mean within 4 standard errors of 0 and the sample deviation within 3 % of sigma
    // (its standard error is 0.5 %; the clamp at 4 sigma takes less than 0.2 %).
    [Theory]
    [InlineData(1.0)]
    [InlineData(5.0)]
    public void EachErrorIsAZeroMeanGaussianOfTheModelsSigma(double scale)
    {
        var noise = new ExecutionNoise(ExecutionNoise.FastFiz, scale);
        var planned = new ShotSpec(3, 30, 0.1, -0.2, 20);
        var random = new PlannerRandom(99);
        const int n = 20000;
        var errors = new double[5][];
        for (int k = 0; k < 5; k++)
        {
            errors[k] = new double[n];
        }
        for (int i = 0; i < n; i++)
        {
            var s = noise.Apply(planned, random, R);
            errors[0][i] = s.AimDeg - planned.AimDeg;
            errors[1][i] = s.ElevationDeg - planned.ElevationDeg;
            errors[2][i] = s.Speed - planned.Speed;
            errors[3][i] = (s.TipSide - planned.TipSide) * R;
            errors[4][i] = (s.TipHeight - planned.TipHeight) * R;
        }
        double[] sigma = [noise.AimStdDeg, noise.ElevationStdDeg, noise.SpeedStd, noise.TipStd, noise.TipStd];
        for (int k = 0; k < 5; k++)
        {
            double mean = errors[k].Average();
            double sd = Math.Sqrt(errors[k].Sum(e => (e - mean) * (e - mean)) / (n - 1));
            Assert.InRange(mean, -4 * sigma[k] / Math.Sqrt(n), 4 * sigma[k] / Math.Sqrt(n));
            Assert.InRange(sd / sigma[k], 0.97, 1.03);
        }
        // Independent: aim and speed errors are uncorrelated (|r| < 4 / sqrt(n)).
        double r = errors[0].Zip(errors[2], (a, b) => a * b).Sum() / (n * sigma[0] * sigma[2]);
        Assert.InRange(r, -4 / Math.Sqrt(n), 4 / Math.Sqrt(n));
    }

    [Fact]
    public void NoNoiseStrikesThePlannedShotAndTheStrokeStaysPlayable()
    {
        var planned = new ShotSpec(0.06, 10, 0.59, 0, 0);
        Assert.Equal(planned, new ExecutionNoise(ExecutionNoise.FastFiz, 0).Apply(planned, new PlannerRandom(1), R));
        var random = new PlannerRandom(2);
        var big = new ExecutionNoise(ExecutionNoise.FastFiz, 20);
        for (int i = 0; i < 2000; i++)
        {
            var s = big.Apply(planned, random, R);
            Assert.True(s.Speed >= ExecutionNoise.MinSpeed);
            Assert.InRange(s.ElevationDeg, 0, ExecutionNoise.MaxElevationDeg);
            Assert.True(Math.Sqrt(s.TipSide * s.TipSide + s.TipHeight * s.TipHeight) < SkillLevel.MaxTip);
        }
    }

    [Fact]
    public void TheBlindPlannerSearchesExactStrokesAndTheNoisePlannerSamplesTheNoise()
    {
        var shot = new ShotSpec(2, 45, 0, 0.2, 5);
        var five = SkillLevel.Of(5);
        Assert.Equal(SearchError.Own, five.Error);
        var blind = five.NoiseBlind();
        Assert.Equal(SearchError.Exact, blind.Error);
        Assert.Equal(shot, blind.SearchStroke(shot, new PlannerRandom(3), R));
        Assert.Equal(1, blind.Samples);
        Assert.Equal(0, blind.RefineSamples);
        var noise = new ExecutionNoise(ExecutionNoise.FastFiz, 1);
        var aware = five.PlayingFor(noise);
        Assert.Equal(noise.Apply(shot, new PlannerRandom(3), R), aware.SearchStroke(shot, new PlannerRandom(3), R));
        Assert.Equal(noise.AimStdDeg, aware.AimStdDeg);
        Assert.Equal(five.Execute(shot, new PlannerRandom(3)), five.SearchStroke(shot, new PlannerRandom(3), R));
    }

    // Every stroke of a noisy game (the break too) is the planned one with a draw of the noise
    // from its own stream, the same at one thread or two, and the record holds the struck stroke.
    [Fact]
    public void ANoisyGameStrikesEveryShotWithTheNoiseAndIsTheSameAtAnyThreadCount()
    {
        var selfPlay = new SelfPlay(Pool, Params);
        var noise = new ExecutionNoise(ExecutionNoise.FastFiz, 1);
        var skills = new PerPlayer<SkillLevel>(SkillLevel.Of(2).PlayingFor(noise), SkillLevel.Of(2).NoiseBlind());
        const ulong seed = 21;
        var game = selfPlay.Play(GameRules.EightBall, skills, 0, seed, new PlannerBudget(600_000, 2), GameState.DefaultTarget, noise);
        Assert.NotEmpty(game.Shots);
        Assert.Equal(0, game.Shots[0].Before.Shot);
        for (int k = 0; k < game.Shots.Count; k++)
        {
            var s = game.Shots[k];
            Assert.Equal(noise.Apply(s.Planned, new PlannerRandom(PlannerRandom.Derive(seed, k, 3)), R), s.Executed);
            Assert.NotEqual(s.Planned, s.Executed);
            Assert.Equal(s.Executed, game.Record.Shots[k].Input.Shot);
        }
        var again = selfPlay.Play(GameRules.EightBall, skills, 0, seed, new PlannerBudget(600_000, 1), GameState.DefaultTarget, noise);
        Assert.Equal(game.Shots.Select(s => s.Executed), again.Shots.Select(s => s.Executed));
        Assert.Equal(game.Winner, again.Winner);
    }
}
