using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>A shot's speed is the cue's speed at impact under every model.</summary>
public class ShotSpeedTests
{
    private static Simulation Alone(string model) => SimulationFactory.Create(SceneLoader.Parse($$"""
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "model": "{{model}}" },
          "balls": [ { "id": "cue", "position": [-0.3, 0.1] } ] }
        """, "alone.json"));

    private static double CueBallSpeed(string model, double cueSpeed, double aimDeg)
    {
        var sim = Alone(model);
        sim.Strike(new ShotSpec(cueSpeed, aimDeg));
        return sim.Balls[sim.IndexOf(PoolBalls.Cue)].Velocity.Length;
    }

    [Theory]
    [InlineData(0.5, 0.0)]
    [InlineData(1.0, 37.0)]
    [InlineData(2.0, -120.0)]
    [InlineData(4.0, 90.0)]
    [InlineData(7.5, 200.0)]
    public void BothModelsSendTheCueBallOffByTheCentreBallImpactOfTheCuesSpeed(double cueSpeed, double aimDeg)
    {
        double standard = CueBallSpeed(ModelRegistry.Standard.Name, cueSpeed, aimDeg);
        double thesis = CueBallSpeed(ModelRegistry.Thesis.Name, cueSpeed, aimDeg);
        // Both are the centre-ball impact of TP A-30, v = (1 + e_tip) V / (1 + m / M): the standard
        // model with pool's ball (0.170097 kg), cue (0.567 kg) and leather tip (e_tip 0.73), the
        // thesis model, kept as the seed had it, with an elastic tip and the seed's 0.17 kg ball;
        // its single-precision centimetres keep about seven digits.
        Assert.Equal(0.73, PhysicsParams.Pool.ETip);
        Assert.Equal(1.73 * cueSpeed / (1 + 0.170097 / 0.567), standard, 1e-12);
        Assert.Equal(2 * cueSpeed / (1 + 0.17 / 0.567), thesis, 1e-6 * thesis);
    }

    [Fact]
    public void TheThesisFactorIsTheCentreBallImpactOfTheDefaultCueOnTheSeedsBall()
    {
        // The seed's mass is a float: 0.17f is 0.17 to 2e-9.
        Assert.Equal(2 / (1 + 0.17 / 0.567), ThesisSimulation.CueToBallSpeed, 1e-8);
        Assert.Equal(1.5386, ThesisSimulation.CueToBallSpeed, 1e-4);
    }

    [Fact]
    public void TheThesisStrikeCapsTheCueNotTheBallAtFormel31sFastestStroke()
    {
        // 12 m/s and 8 m/s are both the cap, 800 cm/s, for the cue.
        Assert.Equal(CueBallSpeed(ModelRegistry.Thesis.Name, 8, 0), CueBallSpeed(ModelRegistry.Thesis.Name, 12, 0));
        Assert.Equal(8 * ThesisSimulation.CueToBallSpeed, CueBallSpeed(ModelRegistry.Thesis.Name, 12, 0), 1e-5);
    }
}
