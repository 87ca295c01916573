using System.Globalization;
using System.Text;

namespace Billiards.App.Rendering;

/// <summary>Writes meshes as Wavefront OBJ with its MTL library: one group and material per mesh, normals per vertex.</summary>
public static class ObjWriter
{
    /// <summary>The OBJ and MTL texts; the OBJ refers to the MTL by <paramref name="mtlFileName"/>.</summary>
    public static (string Obj, string Mtl) Write(IReadOnlyList<MeshBuilder> meshes, string mtlFileName, string comment)
    {
        var ci = CultureInfo.InvariantCulture;
        var obj = new StringBuilder();
        var mtl = new StringBuilder();
        obj.Append("# ").AppendLine(comment);
        obj.AppendLine("# Units: metres; z up; origin at the centre of the bed.");
        obj.Append("mtllib ").AppendLine(mtlFileName);
        mtl.Append("# ").AppendLine(comment);
        mtl.AppendLine("# Colours are sRGB.");
        int offset = 1;
        foreach (var mesh in meshes)
        {
            if (mesh.Indices.Count == 0)
            {
                continue;
            }
            var m = mesh.Material;
            mtl.AppendLine();
            mtl.Append("newmtl ").AppendLine(m.Name);
            mtl.AppendLine(ci, $"Kd {m.Diffuse.X:0.####} {m.Diffuse.Y:0.####} {m.Diffuse.Z:0.####}");
            mtl.AppendLine(ci, $"Ks {m.Specular.X:0.####} {m.Specular.Y:0.####} {m.Specular.Z:0.####}");
            mtl.AppendLine(ci, $"Ns {m.Shininess:0.##}");
            mtl.AppendLine("d 1");
            mtl.AppendLine("illum 2");

            obj.AppendLine();
            obj.Append("o ").AppendLine(m.Name);
            obj.Append("usemtl ").AppendLine(m.Name);
            foreach (var p in mesh.Positions)
            {
                obj.AppendLine(ci, $"v {p.X:0.#####} {p.Y:0.#####} {p.Z:0.#####}");
            }
            foreach (var n in mesh.Normals)
            {
                obj.AppendLine(ci, $"vn {n.X:0.####} {n.Y:0.####} {n.Z:0.####}");
            }
            for (int i = 0; i < mesh.Indices.Count; i += 3)
            {
                long a = mesh.Indices[i] + offset, b = mesh.Indices[i + 1] + offset, c = mesh.Indices[i + 2] + offset;
                obj.AppendLine(ci, $"f {a}//{a} {b}//{b} {c}//{c}");
            }
            offset += mesh.Positions.Count;
        }
        return (obj.ToString(), mtl.ToString());
    }
}
