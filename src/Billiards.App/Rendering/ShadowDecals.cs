using System.Numerics;
using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>
/// The balls' soft shadows and contact darkening on the bed, drawn as one small quad per ball
/// (<see cref="Shaders.ShadowFragment"/>) multiplied into the frame after the table. Only the
/// pixels near a ball pay for its shadow, where a per-pixel loop over every ball made the whole
/// bed pay for all of them.
/// </summary>
internal sealed class ShadowDecals : IDisposable
{
    /// <summary>Lift of the quads above the bed (m): above the cloth, below anything a ball's shadow should not darken.</summary>
    public const float Lift = 0.0005f;

    private readonly Gl _gl;
    private readonly uint _program, _vao, _vbo;
    private readonly int _viewProj, _ball, _lamps, _lampRadius, _ambient;
    private readonly List<float> _vertices = [];
    private readonly List<Vector4> _balls = [];

    public ShadowDecals(Gl gl)
    {
        _gl = gl;
        _program = gl.LinkProgram(gl.CompileShader(Gl.VertexShader, Shaders.ShadowVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.ShadowFragment), ["aPosition"]);
        _viewProj = gl.GetUniformLocation(_program, "uViewProj");
        _ball = gl.GetUniformLocation(_program, "uBall");
        _lamps = gl.GetUniformLocation(_program, "uLamps");
        _lampRadius = gl.GetUniformLocation(_program, "uLampRadius");
        _ambient = gl.GetUniformLocation(_program, "uAmbient");
        _vao = gl.GenVertexArray();
        _vbo = gl.GenBuffer();
        gl.BindVertexArray(_vao);
        gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        gl.VertexAttribPointer(0, 3, Gl.Float, false, 3 * sizeof(float), 0);
        gl.EnableVertexAttribArray(0);
        gl.BindVertexArray(0);
    }

    /// <summary>
    /// Half the side of a ball's quad (m): the ball's radius, the farthest lamp's offset of the
    /// shadow's centre and its penumbra, with a margin.
    /// </summary>
    public static float HalfSize(Vector3 ball, float radius, ReadOnlySpan<float> lamps, float lampRadius)
    {
        float reach = 0;
        for (int k = 0; k + 3 < lamps.Length; k += 4)
        {
            var lamp = new Vector3(lamps[k], lamps[k + 1], lamps[k + 2]);
            float above = MathF.Max(lamp.Z - ball.Z, 1e-3f);
            float offset = (new Vector2(ball.X, ball.Y) - new Vector2(lamp.X, lamp.Y)).Length() * ball.Z / above;
            float umbra = radius * lamp.Z / above;
            float penumbra = lampRadius * ball.Z / above;
            reach = MathF.Max(reach, offset + umbra + penumbra);
        }
        return MathF.Max(reach, 2 * radius) + (0.5f * radius);
    }

    /// <summary>Multiplies the shadows of the balls resting on the bed (centre at about one radius) into the bound framebuffer.</summary>
    public void Draw(Matrix4x4 viewProjection, IReadOnlyList<BallVisual> balls, float radius, ReadOnlySpan<float> lamps, float lampRadius, float ambient)
    {
        _vertices.Clear();
        _balls.Clear();
        foreach (var ball in balls)
        {
            // A ball dropping into a pocket is no longer over the bed.
            if (!ball.Visible || ball.Position.Z < 0.5f * radius)
            {
                continue;
            }
            float h = HalfSize(ball.Position, radius, lamps, lampRadius);
            float x0 = ball.Position.X - h, x1 = ball.Position.X + h, y0 = ball.Position.Y - h, y1 = ball.Position.Y + h;
            ReadOnlySpan<float> quad = [x0, y0, Lift, x1, y0, Lift, x1, y1, Lift, x0, y0, Lift, x1, y1, Lift, x0, y1, Lift];
            foreach (float f in quad)
            {
                _vertices.Add(f);
            }
            _balls.Add(new Vector4(ball.Position, radius));
        }
        if (_balls.Count == 0)
        {
            return;
        }
        var gl = _gl;
        gl.UseProgram(_program);
        gl.UniformMatrix4(_viewProj, viewProjection);
        gl.Uniform4Array(_lamps, lamps);
        gl.Uniform1(_lampRadius, lampRadius);
        gl.Uniform1(_ambient, ambient);
        gl.BindVertexArray(_vao);
        gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        gl.BufferData<float>(Gl.ArrayBuffer, System.Runtime.InteropServices.CollectionsMarshal.AsSpan(_vertices), Gl.DynamicDraw);
        gl.Enable(Gl.Blend);
        gl.BlendFunc(Gl.Zero, Gl.SrcColor);
        gl.DepthMask(false);
        for (int i = 0; i < _balls.Count; i++)
        {
            var b = _balls[i];
            gl.Uniform4(_ball, b.X, b.Y, b.Z, b.W);
            gl.DrawArrays(Gl.Triangles, 6 * i, 6);
        }
        gl.DepthMask(true);
        gl.Disable(Gl.Blend);
    }

    public void Dispose()
    {
        _gl.DeleteBuffer(_vbo);
        _gl.DeleteVertexArray(_vao);
        _gl.DeleteProgram(_program);
    }
}
