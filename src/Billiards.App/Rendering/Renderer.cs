using System.Numerics;
using Billiards.App.Native;
using Billiards.Core.Balls;
using Billiards.Core.Table;

namespace Billiards.App.Rendering;

/// <summary>
/// Draws a <see cref="RenderFrame"/> into the framebuffer bound when <see cref="Draw"/> is called
/// (the window's, or an offscreen one): the table loaded through Assimp, textured balls, the cue,
/// lighting from the seed's four lights (per vertex on the table, per pixel on balls and cue) with
/// soft ball shadows as decals on the bed, the debug collision
/// view and the HUD. The same code serves `play` and `render`. Needs a current GL 3.3 context.
/// </summary>
internal sealed class Renderer : IDisposable
{
    private static readonly string[] s_meshAttributes = ["aPosition", "aNormal", "aUv", "aColor"];

    private readonly Gl _gl;
    private readonly Func<TableSpec, string> _modelPath;
    private readonly LitProgram _lit;
    private readonly LitProgram _gouraud;
    private readonly GpuMesh _sphere;
    private readonly GpuMesh _cue;
    private readonly Dictionary<int, uint> _ballTextures = [];
    private readonly DebugLines _lines;
    private readonly ShadowDecals _shadows;
    private readonly HudRenderer _hud;
    private TableModel? _table;
    private TableSpec? _tableSpec;

    /// <summary>Creates the GPU resources. <paramref name="modelPath"/> picks the table model file (default: <see cref="TableModels.PathFor"/>).</summary>
    public Renderer(Gl gl, Func<TableSpec, string>? modelPath = null)
    {
        _gl = gl;
        _modelPath = modelPath ?? TableModels.PathFor;
        _lit = new LitProgram(gl, gl.LinkProgram(
            gl.CompileShader(Gl.VertexShader, Shaders.LitVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.LitFragment), s_meshAttributes));
        _gouraud = new LitProgram(gl, gl.LinkProgram(
            gl.CompileShader(Gl.VertexShader, Shaders.GouraudVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.GouraudFragment), s_meshAttributes));
        // 32 x 24 is smooth at the size a ball is ever drawn; llvmpipe sets up every triangle on one thread.
        _sphere = GpuMesh.From(gl, Primitives.Sphere(32, 24));
        _cue = GpuMesh.From(gl, Primitives.Cue());
        _lines = new DebugLines(gl);
        _shadows = new ShadowDecals(gl);
        _hud = new HudRenderer(gl);
    }

    /// <summary>The model file of the table last drawn.</summary>
    public string? TableSource => _table?.Source;

    /// <summary>Height of the three lamps above the bed (m): the seed's 90 cm.</summary>
    public const float LampHeight = 0.9f;

    /// <summary>Height of the fill light over the centre of the bed (m): the seed's 1 cm.</summary>
    public const float FillHeight = 0.01f;

    /// <summary>Draws the frame into the bound framebuffer, viewport (0, 0, Width, Height).</summary>
    public void Draw(RenderFrame frame)
    {
        EnsureTable(frame.Table);
        var gl = _gl;
        gl.Viewport(0, 0, frame.Width, frame.Height);
        gl.ClearColor(0.018f, 0.016f, 0.014f, 1);
        gl.Clear(Gl.ColorBufferBit | Gl.DepthBufferBit);
        gl.Enable(Gl.DepthTest);
        gl.DepthFunc(Gl.LessEqual);
        gl.Disable(Gl.CullFace);
        gl.Disable(Gl.Blend);
        gl.Enable(Gl.Multisample);

        var viewProjection = RenderMath.ViewProjection(frame);
        float radius = frame.BallRadius;
        Span<float> lamps = stackalloc float[12];
        Lamps(frame.Table, lamps);
        _gouraud.Begin(viewProjection, frame.Eye, lamps);
        foreach (var part in _table!.Parts)
        {
            _gouraud.Material(part.Diffuse, part.Specular, part.Shininess, reflect: 0);
            _gouraud.Draw(Matrix4x4.Identity, texture: 0, part.Mesh);
        }

        _shadows.Draw(viewProjection, frame.Balls, radius, lamps, LampRadius, Ambient);

        _lit.Begin(viewProjection, frame.Eye, lamps);
        foreach (var ball in frame.Balls)
        {
            if (!ball.Visible)
            {
                continue;
            }
            var model = Matrix4x4.CreateScale(radius) * Matrix4x4.CreateFromQuaternion(Normalized(ball.Orientation)) * Matrix4x4.CreateTranslation(ball.Position);
            _lit.Material(Vector4.One, new Vector3(0.55f), 160, reflect: 0.045f);
            _lit.Draw(model, BallTexture(ball.Id), _sphere);
        }

        if (frame.Cue.Visible)
        {
            _lit.Material(Vector4.One, new Vector3(0.25f), 40, reflect: 0.02f);
            _lit.Draw(Primitives.CuePlacement(frame.Cue, radius), texture: 0, _cue);
        }

        if (frame.ShowCollisionGeometry && frame.CollisionTriangles.Count > 0)
        {
            _lines.Draw(viewProjection, frame.CollisionTriangles, frame.Width, frame.Height);
        }

        if (frame.Hud is { } hud)
        {
            _hud.Draw(hud, frame.Width, frame.Height);
        }
        gl.BindVertexArray(0);
    }

    /// <summary>Radius of a lamp's shade as a light source (m).</summary>
    public const float LampRadius = 0.14f;

    /// <summary>Ambient light of the room (linear, relative to the lamps).</summary>
    public const float Ambient = 0.10f;

    /// <summary>Three lamps along the table's length, 90 cm above the bed (seed 3.2): x, y, z and intensity each.</summary>
    public static void Lamps(TableSpec table, Span<float> lamps)
    {
        float spacing = (float)table.Length / 3;
        for (int k = 0; k < 3; k++)
        {
            lamps[(4 * k) + 0] = (k - 1) * spacing;
            lamps[(4 * k) + 1] = 0;
            lamps[(4 * k) + 2] = LampHeight;
            lamps[(4 * k) + 3] = 0.95f;
        }
    }

    private static Quaternion Normalized(Quaternion q) =>
        q.LengthSquared() > 1e-12f ? Quaternion.Normalize(q) : Quaternion.Identity;

    private void EnsureTable(TableSpec spec)
    {
        if (_table is not null && _tableSpec == spec)
        {
            return;
        }
        var loaded = TableModel.Load(_gl, _modelPath(spec));
        _table?.Dispose();
        _table = loaded;
        _tableSpec = spec;
    }

    private uint BallTexture(BallId id)
    {
        if (_ballTextures.TryGetValue(id.Value, out uint texture))
        {
            return texture;
        }
        texture = _gl.GenTexture();
        _gl.BindTexture(Gl.Texture2D, texture);
        _gl.PixelStore(Gl.UnpackAlignment, 1);
        _gl.TexImage2D(Gl.Texture2D, 0, Gl.Srgb8Alpha8, BallTextures.Width, BallTextures.Height, Gl.Rgba, Gl.UnsignedByte, BallTextures.Generate(id));
        _gl.GenerateMipmap(Gl.Texture2D);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMinFilter, Gl.LinearMipmapLinear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMagFilter, Gl.Linear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapS, Gl.Repeat);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapT, Gl.ClampToEdge);
        _ballTextures[id.Value] = texture;
        return texture;
    }

    public void Dispose()
    {
        _table?.Dispose();
        _sphere.Dispose();
        _cue.Dispose();
        foreach (uint texture in _ballTextures.Values)
        {
            _gl.DeleteTexture(texture);
        }
        _lines.Dispose();
        _shadows.Dispose();
        _hud.Dispose();
        _gl.DeleteProgram(_lit.Program);
        _gl.DeleteProgram(_gouraud.Program);
    }

    /// <summary>The lit program's uniforms.</summary>
    private sealed class LitProgram(Gl gl, uint program)
    {
        private readonly int _model = gl.GetUniformLocation(program, "uModel");
        private readonly int _viewProj = gl.GetUniformLocation(program, "uViewProj");
        private readonly int _eye = gl.GetUniformLocation(program, "uEye");
        private readonly int _lamps = gl.GetUniformLocation(program, "uLamps");
        private readonly int _fill = gl.GetUniformLocation(program, "uFill");
        private readonly int _baseColor = gl.GetUniformLocation(program, "uBaseColor");
        private readonly int _specular = gl.GetUniformLocation(program, "uSpecular");
        private readonly int _shininess = gl.GetUniformLocation(program, "uShininess");
        private readonly int _reflect = gl.GetUniformLocation(program, "uReflect");
        private readonly int _useTexture = gl.GetUniformLocation(program, "uUseTexture");
        private readonly int _texture = gl.GetUniformLocation(program, "uTexture");
        private readonly int _ambient = gl.GetUniformLocation(program, "uAmbient");
        private readonly int _exposure = gl.GetUniformLocation(program, "uExposure");

        public uint Program { get; } = program;

        public void Begin(Matrix4x4 viewProjection, Vector3 eye, ReadOnlySpan<float> lamps)
        {
            gl.UseProgram(Program);
            gl.UniformMatrix4(_viewProj, viewProjection);
            gl.Uniform3(_eye, eye.X, eye.Y, eye.Z);
            gl.Uniform4Array(_lamps, lamps);
            gl.Uniform4(_fill, 0, 0, FillHeight, 0.06f);
            gl.Uniform1(_ambient, Ambient);
            gl.Uniform1(_exposure, 1.15f);
            gl.Uniform1(_texture, 0);
        }

        public void Material(Vector4 diffuse, Vector3 specular, float shininess, float reflect)
        {
            gl.Uniform4(_baseColor, diffuse.X, diffuse.Y, diffuse.Z, diffuse.W);
            gl.Uniform3(_specular, specular.X, specular.Y, specular.Z);
            gl.Uniform1(_shininess, shininess);
            gl.Uniform1(_reflect, reflect);
        }

        public void Draw(Matrix4x4 model, uint texture, GpuMesh mesh)
        {
            gl.UniformMatrix4(_model, model);
            gl.Uniform1(_useTexture, texture != 0 ? 1 : 0);
            gl.ActiveTexture(Gl.Texture0);
            gl.BindTexture(Gl.Texture2D, texture);
            mesh.Draw();
        }
    }
}
