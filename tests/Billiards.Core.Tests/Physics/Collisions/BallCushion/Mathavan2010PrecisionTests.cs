using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Physics.Collisions.BallBall;
using Billiards.Core.Physics.Collisions.BallCushion;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics.Collisions.BallCushion;

/// <summary>Mathavan 2010 at its default setting against its converged solution over whole shots, and an impact cut short at the step limit is reported.</summary>
public class Mathavan2010PrecisionTests
{
    // The same equations with 16 times finer extrapolated steps: converged to 1e-8 of the speed.
    private sealed class Converged : IBallCushionModel
    {
        public string Name => "mathavan-2010";

        public void Resolve(ref BallState ball, Vec3 normal, double height, PhysicsParams p) =>
            Mathavan2010.ResolveExtrapolated(ref ball, normal, height, p, 16 * Mathavan2010.CompressionSteps);
    }

    // One run at more steps than a phase may take: the impact is cut short.
    private sealed class TooFine : IBallCushionModel
    {
        public string Name => "mathavan-2010";

        public void Resolve(ref BallState ball, Vec3 normal, double height, PhysicsParams p) =>
            Mathavan2010.Resolve(ref ball, normal, height, p, 2 * ImpulseIntegration.MaxStepsPerPhase);
    }

    private static Vec3[] Run(Scene scene, IBallCushionModel model)
    {
        var s = scene with { Physics = scene.Physics with { Models = new InteractionModels(model, FrictionalInelastic.Instance) } };
        var outcome = SimulationRunner.Run(s, new RunOptions());
        Assert.Equal(0, outcome.Simulation.TruncatedImpacts);
        return [.. outcome.Simulation.Balls.ToArray().Select(b => b.Position)];
    }

    private static string Shot(double speed, double aim, double side, double height) =>
        FormattableString.Invariant($$"""
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "models": { "ball_cushion": "mathavan-2010" } },
          "balls": [ { "id": "cue", "position": [-0.6, -0.2] }, { "id": "1", "position": [0.9, 0.45] } ],
          "shot": { "speed": {{speed}}, "aim_deg": {{aim}}, "tip": [{{side}}, {{height}}], "elevation_deg": 0 } }
        """);

    public static TheoryData<string> Shots() =>
    [
        "models/bank-mathavan-2010.json",
        Shot(2.5, 20, 0, 0.3),
        Shot(3.5, 75, 0.4, 0),
        Shot(2, 140, -0.4, -0.3),
        Shot(4, -30, 0.2, 0.4),
    ];

    [Theory]
    [MemberData(nameof(Shots))]
    public void AShotEndsWithinAFifthOfAMillimetreOfTheConvergedSolution(string shot)
    {
        var scene = shot.EndsWith(".json", StringComparison.Ordinal) ? SceneLoader.Load(AssetFolder.Scene(shot)) : SceneLoader.Parse(shot, "shot.json");
        var plain = Run(scene, Mathavan2010.Instance);
        var converged = Run(scene, new Converged());
        double worst = plain.Zip(converged, (a, b) => (a - b).Length).Max();
        Assert.True(worst < 2e-4, $"{worst * 1000:0.000} mm from the converged solution");
    }

    [Fact]
    public void AnImpactCutShortAtTheStepLimitIsReported()
    {
        var scene = SceneLoader.Parse(Shot(2.5, 20, 0, 0.3), "shot.json");
        var s = scene with { Physics = scene.Physics with { Models = new InteractionModels(new TooFine(), FrictionalInelastic.Instance) } };
        var outcome = SimulationRunner.Run(s, new RunOptions(Until: 3));
        Assert.True(outcome.Simulation.TruncatedImpacts > 0);
        string json = System.Text.Encoding.UTF8.GetString(ResultWriter.ToUtf8(outcome, indented: false));
        Assert.Contains($"\"truncated_impacts\":{outcome.Simulation.TruncatedImpacts}", json, StringComparison.Ordinal);
    }
}
