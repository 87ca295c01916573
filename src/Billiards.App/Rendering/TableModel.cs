using System.Numerics;
using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>One drawable part of a loaded model: its triangles and material (linear colours).</summary>
internal sealed record ModelPart(GpuMesh Mesh, Vector4 Diffuse, Vector3 Specular, float Shininess, string Name);

/// <summary>A table model on the GPU, loaded from a file through Assimp.</summary>
internal sealed class TableModel : IDisposable
{
    private TableModel(string source, List<ModelPart> parts)
    {
        Source = source;
        Parts = parts;
    }

    /// <summary>The file it came from.</summary>
    public string Source { get; }

    /// <summary>Its parts, one per mesh of the file.</summary>
    public IReadOnlyList<ModelPart> Parts { get; }

    /// <summary>Loads a model file (any format Assimp reads; MTL colours are taken as sRGB).</summary>
    public static TableModel Load(Gl gl, string path)
    {
        var parts = new List<ModelPart>();
        foreach (var mesh in Assimp.Import(path))
        {
            var gpu = GpuMesh.From(gl, mesh.Positions, mesh.Normals, mesh.Indices);
            var d = RenderMath.ToLinear(new Vector3(mesh.Diffuse.X, mesh.Diffuse.Y, mesh.Diffuse.Z));
            var s = RenderMath.ToLinear(mesh.Specular);
            parts.Add(new ModelPart(gpu, new Vector4(d, mesh.Diffuse.W), s, Math.Max(1, mesh.Shininess), mesh.MaterialName));
        }
        if (parts.Count == 0)
        {
            throw new InvalidDataException($"{path}: the model has no triangles");
        }
        return new TableModel(path, parts);
    }

    public void Dispose()
    {
        foreach (var part in Parts)
        {
            part.Mesh.Dispose();
        }
    }
}
