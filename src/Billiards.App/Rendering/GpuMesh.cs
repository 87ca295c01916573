using System.Numerics;
using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>
/// Triangles on the GPU: one interleaved buffer (position, normal, uv, linear colour: 11 floats)
/// and an index buffer, in a vertex array object.
/// </summary>
internal sealed class GpuMesh : IDisposable
{
    /// <summary>Floats per vertex.</summary>
    public const int Stride = 11;

    private readonly Gl _gl;
    private readonly uint _vao, _vbo, _ebo;

    public GpuMesh(Gl gl, ReadOnlySpan<float> vertices, ReadOnlySpan<uint> indices)
    {
        _gl = gl;
        IndexCount = indices.Length;
        _vao = gl.GenVertexArray();
        gl.BindVertexArray(_vao);
        _vbo = gl.GenBuffer();
        gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        gl.BufferData(Gl.ArrayBuffer, vertices, Gl.StaticDraw);
        _ebo = gl.GenBuffer();
        gl.BindBuffer(Gl.ElementArrayBuffer, _ebo);
        gl.BufferData(Gl.ElementArrayBuffer, indices, Gl.StaticDraw);
        const int Bytes = Stride * sizeof(float);
        gl.VertexAttribPointer(0, 3, Gl.Float, false, Bytes, 0);
        gl.VertexAttribPointer(1, 3, Gl.Float, false, Bytes, 3 * sizeof(float));
        gl.VertexAttribPointer(2, 2, Gl.Float, false, Bytes, 6 * sizeof(float));
        gl.VertexAttribPointer(3, 3, Gl.Float, false, Bytes, 8 * sizeof(float));
        for (uint i = 0; i < 4; i++)
        {
            gl.EnableVertexAttribArray(i);
        }
        gl.BindVertexArray(0);
    }

    /// <summary>Number of indices (three per triangle).</summary>
    public int IndexCount { get; }

    /// <summary>Uploads a builder's triangles; its vertex colours are taken as sRGB.</summary>
    public static GpuMesh From(Gl gl, MeshBuilder mesh)
    {
        var vertices = new float[mesh.Positions.Count * Stride];
        for (int i = 0; i < mesh.Positions.Count; i++)
        {
            Write(vertices, i, mesh.Positions[i], mesh.Normals[i], mesh.TexCoords[i], RenderMath.ToLinear(mesh.Colors[i]));
        }
        return new GpuMesh(gl, vertices, [.. mesh.Indices]);
    }

    /// <summary>Uploads positions and normals with white colour and zero uv.</summary>
    public static GpuMesh From(Gl gl, Vector3[] positions, Vector3[] normals, uint[] indices)
    {
        var vertices = new float[positions.Length * Stride];
        for (int i = 0; i < positions.Length; i++)
        {
            Write(vertices, i, positions[i], normals[i], Vector2.Zero, Vector3.One);
        }
        return new GpuMesh(gl, vertices, indices);
    }

    private static void Write(float[] v, int i, Vector3 p, Vector3 n, Vector2 uv, Vector3 c)
    {
        int o = i * Stride;
        v[o] = p.X; v[o + 1] = p.Y; v[o + 2] = p.Z;
        v[o + 3] = n.X; v[o + 4] = n.Y; v[o + 5] = n.Z;
        v[o + 6] = uv.X; v[o + 7] = uv.Y;
        v[o + 8] = c.X; v[o + 9] = c.Y; v[o + 10] = c.Z;
    }

    public void Draw()
    {
        _gl.BindVertexArray(_vao);
        _gl.DrawElements(Gl.Triangles, IndexCount);
    }

    public void Dispose()
    {
        _gl.DeleteBuffer(_vbo);
        _gl.DeleteBuffer(_ebo);
        _gl.DeleteVertexArray(_vao);
    }
}
