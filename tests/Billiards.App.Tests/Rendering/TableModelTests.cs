using System.Numerics;
using System.Runtime.CompilerServices;
using Billiards.App.Native;
using Billiards.App.Rendering;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Rendering;

public class TableModelTests
{
    /// <summary>The presets with a committed model in assets/models.</summary>
    public static TheoryData<string> Presets => new(TableSpec.PresetNames);

    /// <summary>
    /// The committed model matches the generator. To regenerate after changing the generator:
    /// BILLIARDS_WRITE_MODELS=1 dotnet test --filter CommittedModelMatchesTheGenerator
    /// </summary>
    [Theory]
    [MemberData(nameof(Presets))]
    public void CommittedModelMatchesTheGenerator(string preset)
    {
        var spec = TableSpec.FromPreset(preset);
        if (Environment.GetEnvironmentVariable("BILLIARDS_WRITE_MODELS") == "1")
        {
            // Into the repository's assets/models (the build copies them beside the executable), then here.
            string committed = Path.GetFullPath(Path.Combine(SourceFolder(), "..", "..", "..", "assets", "models"));
            TableModels.Export(spec, committed, preset);
            TableModels.Export(spec, TableModels.ModelsDirectory, preset);
        }
        var (obj, mtl) = TableModels.Text(spec, preset);
        string objPath = Path.Combine(TableModels.ModelsDirectory, preset + ".obj");
        Assert.True(File.Exists(objPath), $"{objPath} is missing");
        Assert.True(SameModel(obj, File.ReadAllText(objPath)), $"{objPath} differs from the generator; regenerate it with BILLIARDS_WRITE_MODELS=1");
        Assert.True(SameModel(mtl, File.ReadAllText(Path.ChangeExtension(objPath, ".mtl"))), $"{preset}.mtl differs from the generator");
        Assert.Equal(objPath, TableModels.PathFor(spec));
    }

    private static string SourceFolder([CallerFilePath] string file = "") => Path.GetDirectoryName(file)!;

    /// <summary>Same tokens, numbers equal to the last written digit or so (libm's sines may differ by an ulp between machines).</summary>
    private static bool SameModel(string expected, string actual)
    {
        string[] a = expected.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
        string[] b = actual.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
        if (a.Length != b.Length)
        {
            return false;
        }
        var ci = System.Globalization.CultureInfo.InvariantCulture;
        for (int i = 0; i < a.Length; i++)
        {
            if (a[i] == b[i])
            {
                continue;
            }
            if (!double.TryParse(a[i], ci, out double x) || !double.TryParse(b[i], ci, out double y) || Math.Abs(x - y) > 2e-4)
            {
                return false;
            }
        }
        return true;
    }

    [Fact]
    public void PathForGeneratesAModelForAChangedTable()
    {
        var spec = TableSpec.FromPreset("pool-9ft") with { Length = 2.0, Width = 1.0 };
        string path = TableModels.PathFor(spec);
        Assert.StartsWith(Path.GetTempPath(), path);
        Assert.True(File.Exists(path));
        Assert.True(File.Exists(Path.ChangeExtension(path, ".mtl")));
    }

    [Fact]
    public void AssimpImportsTheGeneratedModelWithItsMaterials()
    {
        var spec = TableSpec.FromPreset("pool-9ft");
        var generated = TableModelGenerator.Generate(spec);
        var imported = Assimp.Import(TableModels.PathFor(spec));
        var names = imported.Select(m => m.MaterialName).ToHashSet();
        Assert.Superset(new HashSet<string> { "cloth", "cushion", "rail", "sight", "pocket" }, names);
        Assert.Equal(generated.Sum(m => m.Indices.Count), imported.Sum(m => m.Indices.Length));
        var cloth = imported.Single(m => m.MaterialName == "cloth");
        var expected = TableModelGenerator.Materials.Cloth.Diffuse;
        Assert.Equal(expected.Y, cloth.Diffuse.Y, 3);
        Assert.All(cloth.Normals, n => Assert.Equal(1, n.Z, 3));
        // The bed reaches the cushions' noses and lies at z = 0.
        Assert.All(cloth.Positions, p => Assert.Equal(0, p.Z, 5));
        Assert.True(cloth.Positions.Max(p => p.X) > spec.HalfLength);
    }

    [Fact]
    public void EachPocketCupsRimLiesOnTheHolesOutlineSoNoWallStandsOverTheClothOrLeavesAGap()
    {
        var spec = TableSpec.FromPreset("pool-9ft");
        var parts = TableModelGenerator.Generate(spec);
        var cloth = parts.Single(m => m.Material.Name == "cloth");
        var cup = parts.Single(m => m.Material.Name == "pocket");
        var trim = parts.Single(m => m.Material.Name == "trim");
        static (int, int) Key(Vector3 p) => ((int)MathF.Round(p.X * 1e5f), (int)MathF.Round(p.Y * 1e5f));
        var bed = cloth.Positions.Select(Key).ToHashSet();
        // The cup's wall reaches the bed's height only on the cloth's own outline points.
        var atBed = cup.Positions.Where(p => MathF.Abs(p.Z) < 1e-6f).ToList();
        Assert.NotEmpty(atBed);
        Assert.All(atBed, p => Assert.Contains(Key(p), bed));
        // Above the bed it is at the trim's top exactly: nothing of the cup lies inside the trim's faces.
        float top = trim.Positions.Max(p => p.Z);
        Assert.All(cup.Positions.Where(p => p.Z > 1e-6f), p => Assert.Equal(top, p.Z, 6));
        // And the bottom is its own, darker part.
        var floor = parts.Single(m => m.Material.Name == "pocket_floor");
        Assert.True(floor.Material.Diffuse.Length() < cup.Material.Diffuse.Length() / 2);
    }

    [Fact]
    public void AssimpReportsAnUnreadableFile()
    {
        string path = Path.Combine(Path.GetTempPath(), $"not-a-model-{Environment.ProcessId}.obj");
        File.WriteAllText(path, "this is not a model\n");
        try
        {
            Assert.ThrowsAny<InvalidDataException>(() => Assimp.Import(path));
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Theory]
    [MemberData(nameof(Presets))]
    public void GenerateCutsSixPocketsIntoTheBed(string preset)
    {
        var spec = TableSpec.FromPreset(preset);
        var cloth = TableModelGenerator.Generate(spec).Single(m => m.Material.Name == "cloth");
        float hx = (float)spec.HalfLength + TableModelGenerator.CushionDepth, hy = (float)spec.HalfWidth + TableModelGenerator.CushionDepth;
        float area = 0;
        for (int i = 0; i < cloth.Indices.Count; i += 3)
        {
            var a = cloth.Positions[(int)cloth.Indices[i]];
            var b = cloth.Positions[(int)cloth.Indices[i + 1]];
            var c = cloth.Positions[(int)cloth.Indices[i + 2]];
            var cross = Vector3.Cross(b - a, c - a);
            Assert.True(cross.Z > 0, "bed triangles face up");
            area += cross.Z / 2;
        }
        float rectangle = 4 * hx * hy;
        if (spec.HasPockets)
        {
            // Less than the rectangle by the pockets' near halves, but not by much more.
            Assert.InRange(area, rectangle - 0.05f, rectangle - 0.01f);
            Assert.False(CoveredBy(cloth, new Vector2(hx, hy) - new Vector2(0.03f)), "the corner pocket is open");
            Assert.False(CoveredBy(cloth, new Vector2(0, hy - 0.02f)), "the side pocket is open");
        }
        else
        {
            Assert.Equal(rectangle, area, 3);
        }
        Assert.True(CoveredBy(cloth, Vector2.Zero));
    }

    private static bool CoveredBy(MeshBuilder mesh, Vector2 point)
    {
        static float Cross(Vector2 u, Vector2 v) => (u.X * v.Y) - (u.Y * v.X);
        for (int i = 0; i < mesh.Indices.Count; i += 3)
        {
            var a = new Vector2(mesh.Positions[(int)mesh.Indices[i]].X, mesh.Positions[(int)mesh.Indices[i]].Y);
            var b = new Vector2(mesh.Positions[(int)mesh.Indices[i + 1]].X, mesh.Positions[(int)mesh.Indices[i + 1]].Y);
            var c = new Vector2(mesh.Positions[(int)mesh.Indices[i + 2]].X, mesh.Positions[(int)mesh.Indices[i + 2]].Y);
            if (Cross(b - a, point - a) >= 0 && Cross(c - b, point - b) >= 0 && Cross(a - c, point - c) >= 0)
            {
                return true;
            }
        }
        return false;
    }
}
