using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Physics;

/// <summary>The one registry of models: name to factory, integrators, ball radius and debug geometry.</summary>
public class ModelRegistryTests
{
    [Fact]
    public void EveryModelIsFoundByItsNameAndTheDefaultComesFirst()
    {
        Assert.Equal(["standard", "thesis"], ModelRegistry.Names);
        Assert.Same(ModelRegistry.Default, ModelRegistry.All[0]);
        foreach (var model in ModelRegistry.All)
        {
            Assert.Same(model, ModelRegistry.Find(model.Name));
            Assert.Same(model, ModelRegistry.Get(model.Name));
            Assert.NotEmpty(model.Integrators);
        }
        Assert.Null(ModelRegistry.Find("newton"));
        Assert.Contains("unknown model \"newton\"", Assert.Throws<ArgumentException>(() => ModelRegistry.Get("newton")).Message);
    }

    [Theory]
    [InlineData("standard", typeof(StandardSimulation), "exact,euler,event", "pool-9ft")]
    [InlineData("thesis", typeof(ThesisSimulation), "fixed", "thesis")]
    public void AModelMakesItsSimulationWithItsIntegratorsOnItsTable(string name, Type simulation, string integrators, string preset)
    {
        var model = ModelRegistry.Get(name);
        Assert.Equal(integrators.Split(','), ModelRegistry.IntegratorNames(model));
        Assert.Equal(preset, model.DefaultTablePreset);
        var scene = SceneLoader.Parse($$"""{ "format": "billiards-scene/1", "physics": { "model": "{{name}}" }, "balls": [ { "id": "cue", "position": [0, 0] } ] }""", "m.json");
        Assert.Same(model, scene.Physics.Model);
        Assert.Equal(preset, scene.Table.Preset);
        Assert.Equal(model.Integrators[0], scene.Physics.Integrator);
        var sim = SimulationFactory.Create(scene);
        Assert.IsType(simulation, sim);
        Assert.Equal(name, sim.Model);
        Assert.Equal(model.BallRadius(scene.Physics.Params), sim.BallRadius);
        Assert.Equal(sim.BallRadius, scene.Balls[0].Position.Z, 1e-12);
    }

    [Fact]
    public void TheStandardRadiusFollowsTheScenesRAndTheThesisKeepsTheSeeds()
    {
        var p = PhysicsParams.Default with { R = 0.03 };
        Assert.Equal(0.03, ModelRegistry.Standard.BallRadius(p));
        Assert.Equal(0.0286, ModelRegistry.Thesis.BallRadius(p));
    }

    [Theory]
    [InlineData("standard", "pool-9ft")]
    [InlineData("thesis", "thesis")]
    public void CollisionFacesAreTrianglesWithUnitNormals(string name, string preset)
    {
        var table = TableSpec.FromPreset(preset);
        var faces = ModelRegistry.Get(name).CollisionFaces(table, PhysicsParams.Default);
        Assert.NotEmpty(faces);
        foreach (var f in faces)
        {
            Assert.Equal(1, f.Normal.Length, 1e-6);
            // Perpendicular to the face's edges (the thesis triangles are single precision).
            Assert.Equal(0, Billiards.Core.Mathematics.Vec3.Dot(f.Normal, (f.B - f.A).Normalized()), 1e-5);
            Assert.Equal(0, Billiards.Core.Mathematics.Vec3.Dot(f.Normal, (f.C - f.A).Normalized()), 1e-5);
        }
    }
}
