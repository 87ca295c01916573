using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Rules;

namespace Billiards.Benchmarks;

/// <summary>
/// The level-5 decision under execution noise, on one core: on <see cref="AiBenchmarks"/>' open
/// 8-ball table after the break and with ball in hand on it, the noise-free decision (the level's
/// own error, the baseline of the ratio column) beside the planner that plays for the tournaments'
/// noise at 1x (<c>fastfiz</c>) and the noise-blind planner (one exact outcome per candidate).
/// </summary>
public class NoiseAiBenchmarks
{
    private static readonly PlannerBudget OneCore = new(60_000, 1);
    private PlannerPosition _eight = null!;
    private SkillLevel _own = null!, _noise = null!, _blind = null!;

    [GlobalSetup]
    public void Setup()
    {
        _eight = PlannerPosition.EightBall();
        _own = SkillLevel.Of(5);
        _noise = _own.PlayingFor(new ExecutionNoise(ExecutionNoise.FastFiz, 1));
        _blind = _own.NoiseBlind();
    }

    /// <summary>The level-5 decision with the level's own error (no noise), one core.</summary>
    [Benchmark(Baseline = true)]
    public double NoiseFree() => Decide(_own, ballInHand: false);

    /// <summary>The level-5 decision playing for the noise at 1x, one core.</summary>
    [Benchmark]
    public double Noise1x() => Decide(_noise, ballInHand: false);

    /// <summary>The level-5 noise-blind decision, one core.</summary>
    [Benchmark]
    public double Blind() => Decide(_blind, ballInHand: false);

    /// <summary>The noise-free decision with ball in hand, one core.</summary>
    [Benchmark]
    public double NoiseFreeBallInHand() => Decide(_own, ballInHand: true);

    /// <summary>The decision for the noise at 1x with ball in hand, one core.</summary>
    [Benchmark]
    public double Noise1xBallInHand() => Decide(_noise, ballInHand: true);

    private double Decide(SkillLevel skill, bool ballInHand) => ballInHand
        ? _eight.Planner.Decide(_eight.State with { BallInHand = BallInHand.Table }, _eight.Table.Without(BallSet.Pool.CueBalls[0]), skill, OneCore, 1).ExpectedScore
        : _eight.Planner.Decide(_eight.State, _eight.Table, skill, OneCore, 1).ExpectedScore;
}
