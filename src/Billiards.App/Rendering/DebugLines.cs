using System.Numerics;
using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>The debug view of the collision geometry: triangle edges and their normals as red lines.</summary>
internal sealed class DebugLines : IDisposable
{
    /// <summary>Length of a drawn normal (m).</summary>
    public const float NormalLength = 0.03f;

    private readonly Gl _gl;
    private readonly uint _program, _vao, _vbo;
    private readonly int _viewProj;

    public DebugLines(Gl gl)
    {
        _gl = gl;
        _program = gl.LinkProgram(gl.CompileShader(Gl.VertexShader, Shaders.LineVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.LineFragment), ["aPosition", "aColor"]);
        _viewProj = gl.GetUniformLocation(_program, "uViewProj");
        _vao = gl.GenVertexArray();
        _vbo = gl.GenBuffer();
        gl.BindVertexArray(_vao);
        gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        gl.VertexAttribPointer(0, 3, Gl.Float, false, 6 * sizeof(float), 0);
        gl.VertexAttribPointer(1, 3, Gl.Float, false, 6 * sizeof(float), 3 * sizeof(float));
        gl.EnableVertexAttribArray(0);
        gl.EnableVertexAttribArray(1);
        gl.BindVertexArray(0);
    }

    /// <summary>Line vertices (position, colour) for the triangles: three edges in red, the normal from the centroid in bright red.</summary>
    public static float[] Vertices(IReadOnlyList<DebugTriangle> triangles)
    {
        var v = new List<float>(triangles.Count * 8 * 6);
        var edge = new Vector3(0.9f, 0.1f, 0.1f);
        var normal = new Vector3(1f, 0.35f, 0.35f);
        void Add(Vector3 p, Vector3 c)
        {
            v.Add(p.X); v.Add(p.Y); v.Add(p.Z);
            v.Add(c.X); v.Add(c.Y); v.Add(c.Z);
        }
        foreach (var t in triangles)
        {
            Add(t.A, edge); Add(t.B, edge);
            Add(t.B, edge); Add(t.C, edge);
            Add(t.C, edge); Add(t.A, edge);
            var centroid = (t.A + t.B + t.C) / 3;
            var n = t.Normal.LengthSquared() > 0 ? Vector3.Normalize(t.Normal) : Vector3.UnitZ;
            Add(centroid, normal);
            Add(centroid + (NormalLength * n), normal);
        }
        return [.. v];
    }

    public void Draw(Matrix4x4 viewProjection, IReadOnlyList<DebugTriangle> triangles)
    {
        float[] vertices = Vertices(triangles);
        _gl.UseProgram(_program);
        _gl.UniformMatrix4(_viewProj, viewProjection);
        _gl.BindVertexArray(_vao);
        _gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        _gl.BufferData<float>(Gl.ArrayBuffer, vertices, Gl.DynamicDraw);
        // Lines sit on surfaces: draw them in front of what they outline.
        _gl.DepthFunc(Gl.LessEqual);
        _gl.DrawArrays(Gl.Lines, 0, vertices.Length / 6);
    }

    public void Dispose()
    {
        _gl.DeleteBuffer(_vbo);
        _gl.DeleteVertexArray(_vao);
        _gl.DeleteProgram(_program);
    }
}
