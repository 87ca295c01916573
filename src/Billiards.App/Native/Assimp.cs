using System.Numerics;
using System.Runtime.InteropServices;

namespace Billiards.App.Native;

/// <summary>
/// Assimp 5 through its C API: import a file, walk the flattened meshes, release. Only the
/// struct fields the App reads are addressed, at the offsets of Assimp 5.2's headers on 64-bit
/// targets (checked with offsetof against libassimp-dev 5.2.5): see the constants below.
/// </summary>
internal static unsafe class Assimp
{
    // Post-processing flags (postprocess.h).
    public const uint JoinIdenticalVertices = 0x2, Triangulate = 0x8, GenSmoothNormals = 0x40, PreTransformVertices = 0x10000;

    // aiScene: unsigned mFlags @0; aiNode* mRootNode @8; unsigned mNumMeshes @16; aiMesh** mMeshes @24;
    // unsigned mNumMaterials @32; aiMaterial** mMaterials @40.
    private const int SceneNumMeshes = 16, SceneMeshes = 24, SceneNumMaterials = 32, SceneMaterials = 40;

    // aiMesh: unsigned mPrimitiveTypes @0, mNumVertices @4, mNumFaces @8; aiVector3D* mVertices @16,
    // mNormals @24; aiFace* mFaces @208; unsigned mMaterialIndex @232. aiFace: unsigned mNumIndices @0,
    // unsigned* mIndices @8, 16 bytes.
    private const int MeshNumVertices = 4, MeshNumFaces = 8, MeshVertices = 16, MeshNormals = 24, MeshFaces = 208, MeshMaterialIndex = 232;
    private const int FaceSize = 16, FaceIndices = 8;

    private static readonly Lazy<nint> s_library = new(() => NativeLoader.Load("Assimp 5",
        OperatingSystem.IsWindows() ? ["assimp-vc143-mt.dll", "assimp-vc142-mt.dll", "assimp.dll"] :
        OperatingSystem.IsMacOS() ? ["libassimp.5.dylib", "libassimp.dylib"] :
        ["libassimp.so.5", "libassimp.so"]));

    private static nint F(string name) => NativeLoader.Export(s_library.Value, name);

    /// <summary>One imported mesh: triangles with per-vertex normals, and its material's colours.</summary>
    public sealed record ImportedMesh(Vector3[] Positions, Vector3[] Normals, uint[] Indices, Vector4 Diffuse, Vector3 Specular, float Shininess, string MaterialName);

    /// <summary>
    /// Imports a model file, triangulated, with smooth normals where the file has none and node
    /// transforms applied. Throws <see cref="InvalidDataException"/> with Assimp's message when
    /// the file cannot be read.
    /// </summary>
    public static List<ImportedMesh> Import(string path)
    {
        byte* p = (byte*)Marshal.StringToCoTaskMemUTF8(path);
        byte* scene;
        try
        {
            scene = ((delegate* unmanaged<byte*, uint, byte*>)F("aiImportFile"))(p, Triangulate | JoinIdenticalVertices | GenSmoothNormals | PreTransformVertices);
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)p);
        }
        if (scene == null)
        {
            string error = Marshal.PtrToStringUTF8(((delegate* unmanaged<nint>)F("aiGetErrorString"))()) ?? "unknown error";
            throw new InvalidDataException($"{path}: {error}");
        }
        try
        {
            uint numMeshes = *(uint*)(scene + SceneNumMeshes);
            byte** meshes = *(byte***)(scene + SceneMeshes);
            uint numMaterials = *(uint*)(scene + SceneNumMaterials);
            byte** materials = *(byte***)(scene + SceneMaterials);
            var result = new List<ImportedMesh>((int)numMeshes);
            for (int m = 0; m < numMeshes; m++)
            {
                byte* mesh = meshes[m];
                int nv = (int)*(uint*)(mesh + MeshNumVertices);
                int nf = (int)*(uint*)(mesh + MeshNumFaces);
                var vertices = *(Vector3**)(mesh + MeshVertices);
                var normals = *(Vector3**)(mesh + MeshNormals);
                byte* faces = *(byte**)(mesh + MeshFaces);
                uint materialIndex = *(uint*)(mesh + MeshMaterialIndex);

                var positions = new Vector3[nv];
                var norms = new Vector3[nv];
                new ReadOnlySpan<Vector3>(vertices, nv).CopyTo(positions);
                if (normals != null)
                {
                    new ReadOnlySpan<Vector3>(normals, nv).CopyTo(norms);
                }
                var indices = new List<uint>(nf * 3);
                for (int f = 0; f < nf; f++)
                {
                    byte* face = faces + (f * FaceSize);
                    uint count = *(uint*)face;
                    uint* idx = *(uint**)(face + FaceIndices);
                    if (count == 3)
                    {
                        indices.Add(idx[0]);
                        indices.Add(idx[1]);
                        indices.Add(idx[2]);
                    }
                }
                Vector4 diffuse = new(0.8f, 0.8f, 0.8f, 1);
                Vector3 specular = Vector3.Zero;
                float shininess = 0;
                string name = "";
                if (materialIndex < numMaterials)
                {
                    byte* material = materials[materialIndex];
                    if (GetColor(material, "$clr.diffuse", out var d))
                    {
                        diffuse = d;
                    }
                    if (GetFloat(material, "$mat.opacity", out float opacity))
                    {
                        diffuse.W = opacity;
                    }
                    if (GetColor(material, "$clr.specular", out var s))
                    {
                        specular = new Vector3(s.X, s.Y, s.Z);
                    }
                    GetFloat(material, "$mat.shininess", out shininess);
                    name = GetName(material);
                }
                if (indices.Count > 0)
                {
                    result.Add(new ImportedMesh(positions, norms, [.. indices], diffuse, specular, shininess, name));
                }
            }
            return result.Count > 0 ? result : throw new InvalidDataException($"{path}: no triangle meshes in the file");
        }
        finally
        {
            ((delegate* unmanaged<byte*, void>)F("aiReleaseImport"))(scene);
        }
    }

    private static bool GetColor(byte* material, string key, out Vector4 color)
    {
        byte* k = (byte*)Marshal.StringToCoTaskMemUTF8(key);
        try
        {
            Vector4 c;
            // aiReturn aiGetMaterialColor(const aiMaterial*, const char* key, unsigned type, unsigned index, aiColor4D*)
            int r = ((delegate* unmanaged<byte*, byte*, uint, uint, Vector4*, int>)F("aiGetMaterialColor"))(material, k, 0, 0, &c);
            color = c;
            return r == 0;
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)k);
        }
    }

    private static bool GetFloat(byte* material, string key, out float value)
    {
        byte* k = (byte*)Marshal.StringToCoTaskMemUTF8(key);
        try
        {
            float v;
            uint max = 1;
            int r = ((delegate* unmanaged<byte*, byte*, uint, uint, float*, uint*, int>)F("aiGetMaterialFloatArray"))(material, k, 0, 0, &v, &max);
            value = r == 0 ? v : 0;
            return r == 0;
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)k);
        }
    }

    private static string GetName(byte* material)
    {
        // aiString: ai_uint32 length; char data[1024].
        byte* k = (byte*)Marshal.StringToCoTaskMemUTF8("?mat.name");
        byte* buffer = stackalloc byte[4 + 1024];
        try
        {
            int r = ((delegate* unmanaged<byte*, byte*, uint, uint, byte*, int>)F("aiGetMaterialString"))(material, k, 0, 0, buffer);
            if (r != 0)
            {
                return "";
            }
            int length = (int)Math.Min(*(uint*)buffer, 1023u);
            return System.Text.Encoding.UTF8.GetString(buffer + 4, length);
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)k);
        }
    }
}
