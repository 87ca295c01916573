using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Collisions.BallCushion;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Physics.Collisions.CollisionKit;

namespace Billiards.Core.Tests.Physics.Collisions.BallCushion;

/// <summary>Stronge's compliant impact: its regimes' limits and the bounds of omega_ratio.</summary>
public class StrongeCompliantTests
{
    [Theory]
    [InlineData(1.2, 1.0)]
    [InlineData(1.8, 1.0)]
    [InlineData(1.8, 0.85)]
    [InlineData(1.99, 0.6)]
    public void ATinySlipSticksAndIsGivenBackByTheSpringAtItsPhase(double ratio, double e)
    {
        // Stuck from the start, the slip oscillates at omega_t until the normal force is gone at
        // t_f = (1 + e) pi / (2 omega_n): the contact leaves with cos(ratio (1 + e) pi / 2) of it.
        const double q = 1e-7;
        double expected = Math.Cos(ratio * (1 + e) * Math.PI / 2);
        Assert.Equal(expected, StrongeCompliant.FinalSlip(q, 0.2, e, ratio) / q, 4);
    }

    [Fact]
    public void GrossSlipIsCoulombFrictionThroughoutAsHanSliding()
    {
        // Sidespin large enough to slide the whole impact: Stronge and Han give one impulse.
        foreach (double angle in new[] { 0.0, 30, 60 })
        {
            var s = Incoming(2, angle, 0, 6);
            var h = s;
            StrongeCompliant.Instance.Resolve(ref s, Normal, Height, P);
            Han2005.Instance.Resolve(ref h, Normal, Height, P);
            AssertClose(h.Velocity, s.Velocity, 1e-12, $"velocity at {angle} deg");
            AssertClose(h.Spin, s.Spin, 1e-9, $"spin at {angle} deg");
        }
    }

    [Theory]
    [InlineData(1.01)]
    [InlineData(1.5)]
    [InlineData(1.8)]
    [InlineData(1.99)]
    public void TheFinalSlipNeverGrowsAndIsContinuousAcrossTheRegimes(double ratio)
    {
        // |g_f| <= g_0 is the tangential energy; the regimes (stick at once, in compression, in
        // restitution, gross slip) meet without a jump.
        foreach (double e in new[] { 0.5, 0.85, 1.0 })
        {
            double previous = StrongeCompliant.FinalSlip(0, 0.2, e, ratio);
            Assert.Equal(0, previous);
            for (int k = 1; k <= 4000; k++)
            {
                double q = k * 0.0005;
                double g = StrongeCompliant.FinalSlip(q, 0.2, e, ratio);
                Assert.True(Math.Abs(g) <= q * (1 + 1e-12), $"ratio {ratio}, e {e}: slip {q} left at {g}");
                Assert.True(Math.Abs(g - previous) < 0.01, $"ratio {ratio}, e {e}: a jump at slip {q}: {previous} -> {g}");
                previous = g;
            }
        }
    }

    [Theory]
    [InlineData("1", "out of range (1, 2)")]
    [InlineData("2", "out of range (1, 2)")]
    [InlineData("0.9", "out of range [1, 2]")]
    [InlineData("2.5", "out of range [1, 2]")]
    public void AScenesOmegaRatioMustLieStrictlyBetweenOneAndTwo(string value, string problem)
    {
        string json = $$"""{ "format": "billiards-scene/1", "physics": { "models": { "ball_cushion": "stronge-compliant" }, "params": { "omega_ratio": {{value}} } }, "balls": [ { "id": "cue", "position": [0, 0] } ] }""";
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse(json, "s.json"));
        Assert.Contains("$.physics.params.omega_ratio", e.Message);
        Assert.Contains(problem, e.Message);
    }

    [Fact]
    public void TheOmegaRatioChangesTheRebound()
    {
        // A stun ball head-on slips at the raised contact by tan(theta) = 0.29 of its approach, less
        // than f_c beta_t: it sticks during compression and is given back part of its slip, by the
        // tangential spring, at a phase the ratio sets.
        var a = Incoming(1.5, 0);
        var b = a;
        StrongeCompliant.Instance.Resolve(ref a, Normal, Height, P with { OmegaRatio = 1.2 });
        StrongeCompliant.Instance.Resolve(ref b, Normal, Height, P with { OmegaRatio = 1.9 });
        Assert.True((a.Velocity - b.Velocity).Length > 1e-3, $"{a.Velocity} and {b.Velocity}");
    }
}
