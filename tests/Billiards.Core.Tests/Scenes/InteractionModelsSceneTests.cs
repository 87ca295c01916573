using System.Text.Json;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Physics.Collisions.BallBall;
using Billiards.Core.Physics.Collisions.BallCushion;
using Billiards.Core.Scenes;
using Billiards.Core.Tests.Physics;

namespace Billiards.Core.Tests.Scenes;

/// <summary>physics.models of scene-format.md: names, refusals, the echo in the result, and that a model is honoured.</summary>
public class InteractionModelsSceneTests
{
    private static string SceneWith(string physics) =>
        $$"""{ "format": "billiards-scene/1", "physics": {{physics}}, "balls": [ { "id": "cue", "position": [0, 0] } ] }""";

    [Fact]
    public void ASceneWithoutModelsGetsTheDefaults()
    {
        var scene = SceneLoader.Parse(SceneWith("{}"), "s.json");
        Assert.Same(Han2005.Instance, scene.Physics.Models.BallCushion);
        Assert.Same(FrictionalInelastic.Instance, scene.Physics.Models.BallBall);
        Assert.Equal(["han-2005", "mathavan-2010", "stronge-compliant"], ModelRegistry.BallCushionNames);
        Assert.Equal(["frictional-inelastic", "frictional-mathavan"], ModelRegistry.BallBallNames);
    }

    [Theory]
    [InlineData("mathavan-2010", "frictional-inelastic")]
    [InlineData("stronge-compliant", "frictional-mathavan")]
    [InlineData("han-2005", "frictional-mathavan")]
    public void ASceneNamesEachInteractionsModel(string cushion, string ballBall)
    {
        var scene = SceneLoader.Parse(SceneWith($$"""{ "models": { "ball_cushion": "{{cushion}}", "ball_ball": "{{ballBall}}" } }"""), "s.json");
        Assert.Equal(cushion, scene.Physics.Models.BallCushion.Name);
        Assert.Equal(ballBall, scene.Physics.Models.BallBall.Name);
    }

    [Theory]
    [InlineData("""{ "models": { "ball_cushion": "han-2006" } }""", "$.physics.models.ball_cushion", "unknown value \"han-2006\" (expected one of \"han-2005\", \"mathavan-2010\", \"stronge-compliant\")")]
    [InlineData("""{ "models": { "ball_ball": "elastic" } }""", "$.physics.models.ball_ball", "unknown value \"elastic\" (expected one of \"frictional-inelastic\", \"frictional-mathavan\")")]
    [InlineData("""{ "models": { "ball_table": "x" } }""", "$.physics.models.ball_table", "unknown field (expected one of \"ball_cushion\", \"ball_ball\")")]
    [InlineData("""{ "models": "mathavan-2010" }""", "$.physics.models", "expected an object")]
    [InlineData("""{ "model": "thesis", "models": { "ball_cushion": "han-2005" } }""", "$.physics.models", "model \"thesis\" keeps its own collisions")]
    public void UnknownModelsAreRefusedWithTheKnownOnes(string physics, string path, string problem)
    {
        var e = Assert.Throws<SceneException>(() => SceneLoader.Parse(SceneWith(physics), "s.json"));
        Assert.Contains($"s.json: {path}: {problem}", e.Message);
    }

    [Theory]
    [InlineData("models/bank-mathavan-2010.json", "mathavan-2010", "frictional-inelastic")]
    [InlineData("models/bank-stronge-compliant.json", "stronge-compliant", "frictional-inelastic")]
    [InlineData("models/cut-frictional-mathavan.json", "han-2005", "frictional-mathavan")]
    [InlineData("eight-ball-break.json", "han-2005", "frictional-inelastic")]
    public void TheResultEchoesTheModelsUsed(string file, string cushion, string ballBall)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file));
        var outcome = SimulationRunner.Run(scene, new RunOptions());
        using var doc = JsonDocument.Parse(ResultWriter.ToUtf8(outcome));
        var models = doc.RootElement.GetProperty("models");
        Assert.Equal(cushion, models.GetProperty("ball_cushion").GetString());
        Assert.Equal(ballBall, models.GetProperty("ball_ball").GetString());
    }

    [Theory]
    [InlineData("models/bank-mathavan-2010.json", "models/bank-stronge-compliant.json")]
    [InlineData("models/eight-ball-break-mathavan-2010.json", "models/eight-ball-break-stronge-compliant.json")]
    public void EachCushionModelIsHonoured(string first, string second)
    {
        // The same shot with another cushion model ends elsewhere, and the default model's copy of
        // the break ends exactly where the plain break scene does.
        double[] Final(string file)
        {
            var scene = SceneLoader.Load(AssetFolder.Scene(file));
            var sim = SimulationFactory.Create(scene);
            sim.Strike(scene.Shot!);
            sim.AdvanceTo(600);
            Assert.True(sim.IsAtRest);
            return [.. sim.Balls.ToArray().SelectMany(b => new[] { b.Position.X, b.Position.Y })];
        }
        var a = Final(first);
        var b = Final(second);
        Assert.True(a.Zip(b).Max(p => Math.Abs(p.First - p.Second)) > 1e-3, "the cushion model changed nothing");
    }

    [Fact]
    public void TheDefaultModelsNamedExplicitlyGiveThePlainBreakBitForBit()
    {
        ulong Hash(Scene scene)
        {
            var sim = SimulationFactory.Create(scene);
            sim.Strike(scene.Shot!);
            sim.AdvanceTo(600);
            return SimulationKit.Hash(sim);
        }
        // The cross-check names pooltool's parameters too: the plain break with those, and its shot.
        var named = SceneLoader.Load(AssetFolder.Scene("models/eight-ball-break-han-2005.json"));
        var plain = SceneLoader.Load(AssetFolder.Scene("eight-ball-break.json"));
        Assert.NotEqual(named.Physics.Params, plain.Physics.Params);
        Assert.Equal(Hash(plain with { Physics = plain.Physics with { Params = named.Physics.Params }, Shot = named.Shot }), Hash(named));
    }

    [Fact]
    public void TheBallBallModelIsHonoured()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("models/cut-frictional-mathavan.json"));
        var plain = scene with { Physics = scene.Physics with { Models = InteractionModels.Default } };
        var a = SimulationRunner.Run(scene, new RunOptions()).Simulation.Balls.ToArray();
        var b = SimulationRunner.Run(plain, new RunOptions()).Simulation.Balls.ToArray();
        Assert.True((a[1].Position - b[1].Position).Length > 1e-4, "the ball-ball model changed nothing");
    }

    [Fact]
    public void TheComputerPlansWithTheGamesModels()
    {
        var models = new InteractionModels(StrongeCompliant.Instance, FrictionalMathavan.Instance);
        var table = Billiards.Core.Table.TableSpec.FromPreset("pool-9ft");
        Assert.Same(models, new Billiards.Core.Ai.ShotPlanner(table, PhysicsParams.Default, models).PhysicsConfig.Models);
        Assert.Same(InteractionModels.Default, new Billiards.Core.Ai.ShotPlanner(table, PhysicsParams.Default).PhysicsConfig.Models);
    }

    [Theory]
    [InlineData("models/bank-mathavan-2010.json")]
    [InlineData("models/bank-stronge-compliant.json")]
    [InlineData("models/cut-frictional-mathavan.json")]
    [InlineData("models/eight-ball-break-stronge-compliant.json")]
    public void AModelChangesWhatHappensAtAContactNeverWhen(string file)
    {
        // The event engine stays exact with every model: the fixed-step integrator at any step
        // meets every contact at the reference solver's time and ends where it ends.
        (double[] Times, double[] Final) Run(string integrator, double? dt)
        {
            var scene = SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(null, integrator, dt));
            var sim = SimulationFactory.Create(scene);
            sim.Strike(scene.Shot!);
            sim.AdvanceTo(600);
            Assert.True(sim.IsAtRest);
            return ([.. sim.Events.AsSpan().ToArray().Select(e => e.Time)], [.. sim.Balls.ToArray().SelectMany(b => new[] { b.Position.X, b.Position.Y })]);
        }
        var reference = Run("event", null);
        foreach (double dt in new[] { 1.0 / 30, 1.0 / 250, 1.0 / 4000 })
        {
            var (times, final) = Run("exact", dt);
            Assert.Equal(reference.Times.Length, times.Length);
            Assert.All(times.Zip(reference.Times), t => Assert.Equal(t.Second, t.First, 1e-9));
            Assert.All(final.Zip(reference.Final), x => Assert.Equal(x.Second, x.First, 1e-9));
        }
    }
}
