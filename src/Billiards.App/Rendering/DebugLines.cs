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

    public DebugLines(Gl gl)
    {
        _gl = gl;
        _program = gl.LinkProgram(gl.CompileShader(Gl.VertexShader, Shaders.LineVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.LineFragment), ["aClip", "aColor"]);
        _vao = gl.GenVertexArray();
        _vbo = gl.GenBuffer();
        gl.BindVertexArray(_vao);
        gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        gl.VertexAttribPointer(0, 4, Gl.Float, false, 7 * sizeof(float), 0);
        gl.VertexAttribPointer(1, 3, Gl.Float, false, 7 * sizeof(float), 4 * sizeof(float));
        gl.EnableVertexAttribArray(0);
        gl.EnableVertexAttribArray(1);
        gl.BindVertexArray(0);
    }

    /// <summary>The segments to draw (world points and colour): three red edges per triangle and its normal from the centroid.</summary>
    public static List<(Vector3 A, Vector3 B, Vector3 Color)> Segments(IReadOnlyList<DebugTriangle> triangles)
    {
        var edge = new Vector3(0.95f, 0.08f, 0.08f);
        var normal = new Vector3(1f, 0.3f, 0.3f);
        var segments = new List<(Vector3, Vector3, Vector3)>(triangles.Count * 4);
        foreach (var t in triangles)
        {
            segments.Add((t.A, t.B, edge));
            segments.Add((t.B, t.C, edge));
            segments.Add((t.C, t.A, edge));
            var centroid = (t.A + t.B + t.C) / 3;
            var n = t.Normal.LengthSquared() > 0 ? Vector3.Normalize(t.Normal) : Vector3.UnitZ;
            segments.Add((centroid, centroid + (NormalLength * n), normal));
        }
        return segments;
    }

    /// <summary>
    /// Draws the triangles' segments as screen-aligned quads <paramref name="widthPixels"/> wide
    /// (core profiles promise no wide lines), depth-tested against the scene.
    /// </summary>
    public void Draw(Matrix4x4 viewProjection, IReadOnlyList<DebugTriangle> triangles, int width, int height, float widthPixels = 2)
    {
        var v = new List<float>();
        void Add(Vector4 clip, Vector3 c)
        {
            v.Add(clip.X); v.Add(clip.Y); v.Add(clip.Z); v.Add(clip.W);
            v.Add(c.X); v.Add(c.Y); v.Add(c.Z);
        }
        foreach (var (a, b, color) in Segments(triangles))
        {
            var ca = Vector4.Transform(new Vector4(a, 1), viewProjection);
            var cb = Vector4.Transform(new Vector4(b, 1), viewProjection);
            if (ca.W < RenderMath.Near || cb.W < RenderMath.Near)
            {
                continue;
            }
            // Direction on screen in pixels, its perpendicular back in NDC units.
            var pa = new Vector2(ca.X / ca.W * width, ca.Y / ca.W * height);
            var pb = new Vector2(cb.X / cb.W * width, cb.Y / cb.W * height);
            var d = pb - pa;
            if (d.LengthSquared() < 1e-8f)
            {
                continue;
            }
            d = Vector2.Normalize(d);
            var offset = new Vector2(-d.Y / width, d.X / height) * widthPixels;
            Vector4 Shift(Vector4 c, float sign) => c + new Vector4(sign * offset.X * c.W, sign * offset.Y * c.W, 0, 0);
            Add(Shift(ca, 1), color); Add(Shift(ca, -1), color); Add(Shift(cb, -1), color);
            Add(Shift(ca, 1), color); Add(Shift(cb, -1), color); Add(Shift(cb, 1), color);
        }
        _gl.UseProgram(_program);
        _gl.BindVertexArray(_vao);
        _gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        var data = System.Runtime.InteropServices.CollectionsMarshal.AsSpan(v);
        _gl.BufferData<float>(Gl.ArrayBuffer, data, Gl.DynamicDraw);
        // Lines lie on the surfaces they outline: pull them a little towards the eye.
        _gl.Enable(Gl.PolygonOffsetFill);
        _gl.PolygonOffset(-1, -4);
        _gl.DrawArrays(Gl.Triangles, 0, v.Count / 7);
        _gl.Disable(Gl.PolygonOffsetFill);
    }

    public void Dispose()
    {
        _gl.DeleteBuffer(_vbo);
        _gl.DeleteVertexArray(_vao);
        _gl.DeleteProgram(_program);
    }
}
