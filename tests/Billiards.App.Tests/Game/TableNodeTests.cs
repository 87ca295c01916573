using System.Numerics;
using Billiards.App.Game;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

public class TableNodeTests
{
    private static Scene Scene(string model, string preset) => SceneLoader.Parse(
        $$"""{ "format": "billiards-scene/1", "table": { "preset": "{{preset}}" }, "physics": { "model": "{{model}}" } }""", "t.json");

    [Fact]
    public void TheThesisDebugViewShowsTheSeedsSeventyTwoTrianglesFacingTheBed()
    {
        var triangles = TableNode.CollisionGeometryOf(Scene("thesis", "thesis"));
        Assert.Equal(72, triangles.Count); // the seed's count (seed 4.3.4)
        Assert.All(triangles, t => Assert.Equal(1, t.Normal.Length(), 5));
    }

    [Fact]
    public void TheStandardDebugViewShowsEveryCushionSegmentAndJawNose()
    {
        var triangles = TableNode.CollisionGeometryOf(Scene("standard", "pool-9ft"));
        var geometry = Billiards.Core.Table.TableGeometry.Build(Billiards.Core.Table.TableSpec.FromPreset("pool-9ft"), 0.028575);
        // Two triangles per segment face, and 8 faces of 2 triangles per nose.
        Assert.Equal(2 * geometry.Segments.Length + 16 * geometry.Noses.Length, triangles.Count);
        // The six rail faces come first; their normals point back towards the middle of the table.
        foreach (var t in triangles.Take(12))
        {
            var centre = (t.A + t.B + t.C) / 3;
            Assert.True(Vector3.Dot(t.Normal, -centre with { Z = 0 }) > 0, $"normal {t.Normal} at {centre}");
            Assert.Equal(1, t.Normal.Length(), 5);
        }
    }

    [Fact]
    public void APocketlessTableHasItsSixRailFacesAndNoNoses()
    {
        // head, foot, and the two long rails each in a head and a foot half: 6 faces, 2 triangles each.
        Assert.Equal(12, TableNode.CollisionGeometryOf(Scene("standard", "pocketless")).Count);
    }
}
