using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Scenes;

/// <summary><c>--sample DT</c>: positions at t = k DT exactly (scene-format.md), never a repeated time, with every integrator.</summary>
public class SampleTimesTests
{
    private static Scene Break(string model, string integrator, double dt) => SceneLoader.Load(AssetFolder.Scene("eight-ball-break.json"),
        new SceneOverrides(model, integrator, dt));

    [Theory]
    [InlineData("standard", Integrators.Exact, 0.004, 0.01)]
    [InlineData("standard", Integrators.Exact, 0.004, 0.002)]
    [InlineData("standard", Integrators.Event, 0.004, 0.01)]
    [InlineData("standard", Integrators.Euler, 0.004, 0.01)]
    [InlineData("standard", Integrators.Euler, 0.001, 0.0025)]
    [InlineData("thesis", Integrators.Fixed, 0.004, 0.01)]
    public void SamplesFallOnMultiplesOfTheirInterval(string model, string integrator, double dt, double sample)
    {
        var outcome = SimulationRunner.Run(Break(model, integrator, dt), new RunOptions(Until: 0.5, SampleDt: sample));
        Assert.Equal((int)Math.Round(0.5 / sample) + 1, outcome.Samples.Count);
        for (int k = 0; k < outcome.Samples.Count; k++)
        {
            Assert.Equal(k * sample, outcome.Samples[k].Time);
        }
    }

    [Theory]
    [InlineData(Integrators.Exact)]
    [InlineData(Integrators.Euler)]
    public void ASampleBetweenStepsIsTheStateAtItsTime(string integrator)
    {
        // A split step: the sample at 0.01 s with 4 ms steps is where the event solver has the balls
        // at 0.01 s (the exact integrator is the event solver on a grid), and for Euler near it.
        var scene = Break("standard", integrator, 0.004);
        var reference = SimulationRunner.Run(Break("standard", Integrators.Event, 0.004), new RunOptions(Until: 0.03, SampleDt: 0.01));
        var stepped = SimulationRunner.Run(scene, new RunOptions(Until: 0.03, SampleDt: 0.01));
        double tolerance = integrator == Integrators.Exact ? 1e-9 : 2e-3;
        for (int k = 0; k < reference.Samples.Count; k++)
        {
            for (int i = 0; i < reference.Samples[k].Positions.Length; i++)
            {
                Assert.True((reference.Samples[k].Positions[i] - stepped.Samples[k].Positions[i]).Length < tolerance,
                    $"sample {k}, ball {i}: {stepped.Samples[k].Positions[i]} against {reference.Samples[k].Positions[i]}");
            }
        }
    }
}
