using System.Numerics;
using Billiards.App.Native;
using Billiards.Core.Scenes;

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

    /// <summary>
    /// Longest edge after refinement on the bed and above (m). The table is lit at its vertices.
    /// Halving it to 25 cm changes the default view's picture by a PSNR of 50 dB (the tone curve
    /// flattens the lamps' peaks), while every triangle costs a software rasteriser in every frame
    /// the camera moves.
    /// </summary>
    public const float MaxEdge = 0.5f;

    /// <summary>
    /// Longest edge after refinement at a point (m): <see cref="MaxEdge"/> down to the bed, growing
    /// below it (the frame and the floor are farther from the lamps, their light smoother).
    /// </summary>
    public static float MaxEdgeAt(Vector3 point) => MaxEdge * (1 + (MathF.Max(0, -point.Z) / 0.25f));

    /// <summary>Loads a model file (any format Assimp reads; MTL colours are taken as sRGB).</summary>
    public static TableModel Load(Gl gl, string path)
    {
        var parts = new List<ModelPart>();
        List<Assimp.ImportedMesh> imported;
        try
        {
            imported = Assimp.Import(path);
        }
        catch (InvalidDataException e) when (AssetFolder.Holds(path))
        {
            // A shipped model is the installation's problem; a user's --model stays bad input.
            string why = e.Message.StartsWith(path + ": ", StringComparison.Ordinal) ? e.Message[(path.Length + 2)..] : e.Message;
            throw AssetException.Unreadable(path, why.TrimEnd('.'));
        }
        var refined = MeshRefinement.Refine([.. imported.Select(m => new RefinedMesh(m.Positions, m.Normals, m.Indices))], MaxEdgeAt);
        for (int i = 0; i < imported.Count; i++)
        {
            var mesh = imported[i];
            var gpu = GpuMesh.From(gl, refined[i].Positions, refined[i].Normals, refined[i].Indices);
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

    /// <summary>
    /// Longest edge of the room's walls and ceiling after refinement (m): two metres and more from
    /// the lamps their light is smooth, and every triangle costs a software rasteriser.
    /// </summary>
    public const float RoomMaxEdge = 1.0f;

    /// <summary>
    /// Uploads meshes built in code as one model (<paramref name="refine"/>: which of them to
    /// refine to <see cref="RoomMaxEdge"/> for their light, lit at the vertices, to vary smoothly).
    /// </summary>
    public static TableModel FromBuilders(Gl gl, string source, IReadOnlyList<MeshBuilder> builders, IReadOnlyList<bool> refine)
    {
        var parts = new List<ModelPart>();
        for (int i = 0; i < builders.Count; i++)
        {
            var b = builders[i];
            var mesh = new RefinedMesh([.. b.Positions], [.. b.Normals], [.. b.Indices]);
            if (refine[i])
            {
                mesh = MeshRefinement.Refine([mesh], MeshRefinement.Uniform(RoomMaxEdge))[0];
            }
            var material = b.Material;
            parts.Add(new ModelPart(GpuMesh.From(gl, mesh.Positions, mesh.Normals, mesh.Indices), new Vector4(RenderMath.ToLinear(material.Diffuse), 1),
                RenderMath.ToLinear(material.Specular), Math.Max(1, material.Shininess), material.Name));
        }
        return new TableModel(source, parts);
    }

    public void Dispose()
    {
        foreach (var part in Parts)
        {
            part.Mesh.Dispose();
        }
    }
}
