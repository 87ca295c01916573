using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;

namespace Billiards.Core.Tests.Scenes;

public class SceneLoaderTests
{
    private const string Head = "\"format\": \"billiards-scene/1\"";

    private static Scene Parse(string json, SceneOverrides? overrides = null) => SceneLoader.Parse(json, "test.json", overrides);

    private static SceneException Refused(string json, SceneOverrides? overrides = null) =>
        Assert.Throws<SceneException>(() => Parse(json, overrides));

    [Fact]
    public void ASceneWithoutPhysicsRunsTheStandardModelWithTheExactIntegratorAt250Hz()
    {
        var scene = Parse($$"""{ {{Head}}, "balls": [ { "id": "cue", "position": [0, 0] } ] }""");
        Assert.Equal("standard", scene.Physics.Model.Name);
        Assert.Equal("exact", scene.Physics.Integrator.Name);
        Assert.Equal(1.0 / 250, scene.Physics.Dt);
        // The pool table's own cloth and balls (physics-standard-model.md, "Against the real table").
        Assert.Equal(PhysicsParams.Pool, scene.Physics.Params);
        Assert.Equal("pool-9ft", scene.Table.Preset);
        Assert.Equal(PhysicsParams.DefaultRadius, scene.Balls[0].Position.Z);
    }

    [Fact]
    public void TheSnookerTableHasItsMeasuredClothAndACushionRestitutionThatFallsWithSpeed()
    {
        var scene = Parse($$"""{ "format": "billiards-scene/1", "table": { "preset": "snooker-12ft" }, "balls": [ { "id": "cue", "position": [0, 0] } ] }""");
        var p = scene.Physics.Params;
        Assert.Equal(0.0127 * 9.81, p.MuR * p.G, 12); // 0.124-0.126 m/s^2 measured
        Assert.Equal(22, p.SpinDeceleration, 12);
        Assert.Equal(CushionRestitution.Measured, p.ECModel);
        Assert.True(p.CushionE(1) > p.CushionE(3));
        var constant = Parse($$"""{ "format": "billiards-scene/1", "table": { "preset": "snooker-12ft" }, "physics": { "params": { "e_c": 0.85, "mu_b": "alciatore-2014" } }, "balls": [ { "id": "cue", "position": [0, 0] } ] }""").Physics.Params;
        Assert.Equal((CushionRestitution.Constant, 0.85, 0.85), (constant.ECModel, constant.CushionE(1), constant.CushionE(3)));
        Assert.Equal(BallBallFriction.Measured, constant.MuBModel);
    }

    [Fact]
    public void ExplicitBallsReplaceRackedBallsWithTheSameId()
    {
        var scene = Parse($$"""
            { {{Head}}, "rack": { "game": "nine-ball", "seed": 3 },
              "balls": [ { "id": "cue", "position": [-0.5, 0.1], "velocity": [1, 0], "spin": [0, 0, 2] },
                         { "id": "9", "position": [-1.0, -0.4] } ] }
            """);
        Assert.Equal(10, scene.Balls.Count); // 9 racked balls and the cue ball
        Assert.Equal(Enumerable.Range(0, 10), scene.Balls.Select(b => b.Id.Value));
        var cue = scene.Balls[0];
        Assert.Equal((-0.5, 0.1, 1.0, 2.0), (cue.Position.X, cue.Position.Y, cue.Velocity.X, cue.Spin.Z));
        Assert.Equal((-1.0, -0.4), (scene.Balls[9].Position.X, scene.Balls[9].Position.Y));
        Assert.Equal(new RackSpec(RackGame.NineBall, 3), scene.Rack);
    }

    [Fact]
    public void ARackWithoutAnExplicitCueBallPutsItOnTheHeadSpot()
    {
        var scene = Parse($$"""{ {{Head}}, "rack": { "game": "eight-ball", "seed": 1 } }""");
        Assert.Equal(16, scene.Balls.Count);
        Assert.Equal(PoolBalls.Cue, scene.Balls[0].Id);
        Assert.Equal(-2.54 / 4, scene.Balls[0].Position.X, 12);
    }

    [Fact]
    public void ParametersOverrideDefaultsAndMuSpAndEndMassFollowRAndM()
    {
        var scene = Parse($$"""
            { {{Head}}, "physics": { "dt": 0.001, "params": { "mu_s": 0.3, "R": 0.03, "m": 0.3, "mu_b": "alciatore" } } }
            """);
        var p = scene.Physics.Params;
        Assert.Equal((0.3, 0.03, 0.3), (p.MuS, p.R, p.M));
        // They keep the preset's spin-down rate and its m / m_e.
        Assert.Equal(PhysicsParams.Pool.SpinDeceleration, p.SpinDeceleration, 12);
        Assert.Equal(PhysicsParams.Pool.M / PhysicsParams.Pool.CueEndMass, p.M / p.CueEndMass, 12);
        Assert.Equal(BallBallFriction.Alciatore, p.MuBModel);
        // Alciatore's fit at zero slip: 0.009951 + 0.108.
        Assert.Equal(0.117951, p.BallBallMu(0), 12);
        Assert.Equal(0.001, scene.Physics.Dt);
    }

    [Fact]
    public void TheThesisModelDefaultsToTheThesisTableAndItsFixedStep()
    {
        var scene = Parse($$"""{ {{Head}}, "physics": { "model": "thesis" }, "balls": [ { "id": "cue", "position": [0, 0] } ] }""");
        Assert.Equal(("thesis", "fixed", "thesis"), (scene.Physics.Model.Name, scene.Physics.Integrator.Name, scene.Table.Preset));
        Assert.Equal(0.0286, scene.Balls[0].Position.Z);
    }

    [Fact]
    public void CommandLineOverridesApplyAndAreValidated()
    {
        var json = $$"""{ {{Head}} }""";
        var scene = Parse(json, new SceneOverrides(Integrator: "event", Dt: 0.01));
        Assert.Equal(("event", 0.01), (scene.Physics.Integrator.Name, scene.Physics.Dt));
        Assert.Equal("fixed", Parse(json, new SceneOverrides(Model: "thesis")).Physics.Integrator.Name);
        Assert.StartsWith("--integrator: $: integrator \"exact\" is not available for model \"thesis\"",
            Refused(json, new SceneOverrides(Model: "thesis", Integrator: "exact")).Message);
        Assert.Contains("unknown model \"snooker\"", Refused(json, new SceneOverrides(Model: "snooker")).Message);
        Assert.Contains("out of range", Refused(json, new SceneOverrides(Dt: 0)).Message);
    }

    [Theory]
    [InlineData("{", "$", "not valid JSON")]
    [InlineData("[]", "$", "expected an object, found an array of 0")]
    [InlineData("{}", "$", "missing \"format\"")]
    [InlineData("""{ "format": "billiards-scene/2" }""", "$.format", "unknown format \"billiards-scene/2\"")]
    [InlineData("""{ "format": 1 }""", "$.format", "expected a string, found the number 1")]
    [InlineData("""{ §, "colour": "red" }""", "$.colour", "unknown field")]
    [InlineData("""{ §, "table": { "preset": "snooker" } }""", "$.table.preset", "unknown value \"snooker\"")]
    [InlineData("""{ §, "table": { } }""", "$.table", "missing \"preset\"")]
    [InlineData("""{ §, "table": { "preset": "pool-9ft", "length": -2 } }""", "$.table.length", "out of range")]
    [InlineData("""{ §, "physics": { "model": "newton" } }""", "$.physics.model", "unknown value \"newton\"")]
    [InlineData("""{ §, "physics": { "integrator": "rk4" } }""", "$.physics.integrator", "unknown value \"rk4\"")]
    [InlineData("""{ §, "physics": { "model": "thesis", "integrator": "exact" } }""", "$.physics.integrator", "unknown value \"exact\"")]
    [InlineData("""{ §, "physics": { "dt": 0 } }""", "$.physics.dt", "out of range")]
    [InlineData("""{ §, "physics": { "dt": "fast" } }""", "$.physics.dt", "expected a number, found the string \"fast\"")]
    [InlineData("""{ §, "physics": { "params": { "mu_k": 0.1 } } }""", "$.physics.params.mu_k", "unknown field")]
    [InlineData("""{ §, "physics": { "params": { "e_b": 1.5 } } }""", "$.physics.params.e_b", "out of range")]
    [InlineData("""{ §, "physics": { "params": { "mu_b": "pooltool" } } }""", "$.physics.params.mu_b", "unknown value \"pooltool\"")]
    [InlineData("""{ §, "physics": { "params": { "mu_s": "NaN" } } }""", "$.physics.params.mu_s", "expected a number, found the string \"NaN\"")]
    [InlineData("""{ §, "physics": { "params": { "mu_s": 1e999 } } }""", "$.physics.params.mu_s", "not finite")]
    [InlineData("""{ §, "rack": { "game": "carom" } }""", "$.rack.game", "unknown value \"carom\"")]
    [InlineData("""{ §, "rack": { "game": "nine-ball", "seed": 1.5 } }""", "$.rack.seed", "whole number")]
    [InlineData("""{ §, "balls": { } }""", "$.balls", "expected an array")]
    [InlineData("""{ §, "balls": [ { "id": "16", "position": [0, 0] } ] }""", "$.balls[0].id", "unknown ball id \"16\"")]
    [InlineData("""{ §, "balls": [ { "id": "3" } ] }""", "$.balls[0]", "missing \"position\"")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [0] } ] }""", "$.balls[0].position", "expected an array of 2 or 3 numbers, found an array of 1")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [0, null] } ] }""", "$.balls[0].position[1]", "expected a number, found null")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [0, 0], "spin": [0, 0] } ] }""", "$.balls[0].spin", "expected an array of 3 numbers")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [0, 0] }, { "id": "3", "position": [1, 0] } ] }""", "$.balls[1].id", "ball \"3\" appears twice")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [0, 0] }, { "id": "4", "position": [0.05, 0] } ] }""", "$.balls[1]", "ball \"4\" overlaps ball \"3\"")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [1.26, 0] } ] }""", "$.balls[0]", "ball \"3\" at [1.26, 0] is off the table")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [0, -0.62] } ] }""", "$.balls[0]", "is off the table")]
    [InlineData("""{ §, "rack": { "game": "nine-ball" }, "balls": [ { "id": "5", "position": [0.64, 0] } ] }""", "$.balls[0]", "overlaps")]
    [InlineData("""{ §, "balls": [ { "id": "3", "position": [0, 0] } ], "shot": { "speed": 2, "aim_deg": 0 } }""", "$.shot", "a shot needs a cue ball")]
    [InlineData("""{ §, "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "aim_deg": 0 } }""", "$.shot", "missing \"speed\"")]
    [InlineData("""{ §, "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "speed": 99, "aim_deg": 0 } }""", "$.shot.speed", "out of range")]
    [InlineData("""{ §, "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "speed": 2, "aim_deg": 0, "tip": [0.8, 0.8] } }""", "$.shot.tip", "inside the ball")]
    [InlineData("""{ §, "balls": [ { "id": "cue", "position": [0, 0] } ], "shot": { "speed": 2, "aim_deg": 0, "elevation_deg": 95 } }""", "$.shot.elevation_deg", "out of range")]
    [InlineData("""{ §, "rules": "carom" }""", "$.rules", "unknown value \"carom\"")]
    [InlineData("""{ §, "name": "a", "name": "b" }""", "$.name", "field appears twice")]
    public void MalformedScenesAreRefusedWithTheFileThePathAndTheProblem(string json, string path, string problem)
    {
        var e = Refused(json.Replace("§", Head));
        Assert.Equal("test.json", e.File);
        Assert.Equal(path, e.JsonPath);
        Assert.Contains(problem, e.Problem);
        Assert.StartsWith($"test.json: {path}: ", e.Message);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void AMissingFileIsRefusedWithItsName()
    {
        var e = Assert.Throws<SceneException>(() => SceneLoader.Load("/nonexistent/scene.json"));
        Assert.StartsWith("/nonexistent/scene.json: $: cannot read the file", e.Message);
    }

    [Fact]
    public void EveryShippedSceneLoads()
    {
        var files = Directory.GetFiles(AssetFolder.Scene(""), "*.json", SearchOption.AllDirectories);
        Assert.NotEmpty(files);
        Assert.All(files, f => SceneLoader.Load(f));
    }
}
