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
    // The table's program for each detail mapping (DetailOf): none, across the bed, along the rails.
    private readonly LitProgram[] _gouraud;
    private readonly (int Slices, GpuMesh Mesh)[] _spheres;
    private readonly GpuMesh _cue;
    private readonly Dictionary<(string Set, int Ball), uint> _ballTextures = [];
    private readonly DebugLines _lines;
    private readonly ShadowDecals _shadows;
    private readonly HudRenderer _hud;
    private readonly StaticLayer _tableLayer;
    private readonly StaticLayer _sceneLayer;
    private readonly Action<Pass> _drawTable;
    private readonly Action<Pass> _drawScene;
    private readonly List<BallVisual> _lastBalls = [];
    private float _lastRadius;
    private long _ballsVersion;
    private Vector3? _lastEye;
    private Matrix4x4 _lastViewProjection;
    private readonly Upscaler _reduced;
    private readonly float[] _lamps = new float[12];
    private TableModel? _table;
    private TableModel? _room;
    private readonly DetailTextures _details;
    private TableSpec? _tableSpec;

    /// <summary>Creates the GPU resources. <paramref name="modelPath"/> picks the table model file (default: <see cref="TableModels.PathFor"/>).</summary>
    public Renderer(Gl gl, Func<TableSpec, string>? modelPath = null)
    {
        _gl = gl;
        _modelPath = modelPath ?? TableModels.PathFor;
        _lit = new LitProgram(gl, gl.LinkProgram(
            gl.CompileShader(Gl.VertexShader, Shaders.LitVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.LitFragment), s_meshAttributes));
        _gouraud = [.. Enumerable.Range(0, 3).Select(mapping => new LitProgram(gl, gl.LinkProgram(
            gl.CompileShader(Gl.VertexShader, Shaders.GouraudVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.GouraudFragment(mapping)), s_meshAttributes)))];
        // Levels of detail: a software rasteriser pays for every triangle in every tile it touches,
        // and a ball 15 px across needs no 1,536 triangles (the overhead view shows 16 of them).
        _details = new DetailTextures(gl);
        _spheres = [.. SphereSlices.Select(n => (n, GpuMesh.From(gl, Primitives.Sphere(n, (3 * n) / 4))))];
        _cue = GpuMesh.From(gl, Primitives.Cue());
        _lines = new DebugLines(gl);
        _shadows = new ShadowDecals(gl);
        _hud = new HudRenderer(gl);
        _tableLayer = new StaticLayer(gl);
        _sceneLayer = new StaticLayer(gl);
        _reduced = new Upscaler(gl);
        _drawTable = DrawTable;
        _drawScene = DrawScene;
    }

    /// <summary>Frames whose table (alone, or with the balls at rest) was put back from a stored layer.</summary>
    public long LayersReused => _tableLayer.Reused + _sceneLayer.Reused;

    /// <summary>Frames whose HUD was put back from its stored layer.</summary>
    public long HudReused => _hud.Reused;

    /// <summary>Frames whose help overlay was put back from its stored layer.</summary>
    public long HelpReused => _hud.HelpReused;

    /// <summary>The model file of the table last drawn.</summary>
    public string? TableSource => _table?.Source;

    /// <summary>Height of the three lamps above the bed (m): the seed's 90 cm.</summary>
    public const float LampHeight = 0.9f;

    /// <summary>Height of the fill light over the centre of the bed (m): the seed's 1 cm.</summary>
    public const float FillHeight = 0.01f;

    /// <summary>
    /// Draw the 3D scene at <see cref="MovingScale"/> of the resolution while the camera moves,
    /// then scale it up; full resolution again as soon as the view stands still. For a window on a
    /// software rasteriser, where a moving view cannot be kept in the stored layers and a full
    /// frame costs more than a 60 Hz frame's time.
    /// </summary>
    public bool DynamicResolution { get; set; }

    /// <summary>The scale of the 3D scene's resolution while the camera moves (with <see cref="DynamicResolution"/>): the governor's.</summary>
    public float MovingScale => _governor.Scale;

    private readonly ResolutionGovernor _governor = new();
    private int _stillFrames = int.MaxValue / 2;

    /// <summary>
    /// Frames the view must stand still before it is drawn at full resolution again. A camera
    /// dragged by a mouse that reports at 30 Hz, or turned by a key that repeats, stands still in
    /// every other 60 Hz frame: drawn sharp, each of those cost several reduced frames.
    /// </summary>
    public const int StillFramesToSharpen = 12;

    /// <summary>Where a frame's time goes, pass by pass, or null (the default: no pass is finished on its own).</summary>
    public PassProfile? Profile { get; set; }
    private bool _lastReduced;

    /// <summary>
    /// Tells the renderer how long the last frame's work took (s, the swap and the wait for the
    /// GPU included, any frame cap's wait left out) against the frame's budget (s): after a frame
    /// drawn at reduced resolution, the governor moves the scale so that such frames fit.
    /// </summary>
    public void ReportFrameTime(double seconds, double budget)
    {
        if (_lastReduced)
        {
            _governor.Report(seconds, budget);
        }
    }

    /// <summary>Frames drawn at the reduced resolution because the camera moved.</summary>
    public long ReducedFrames { get; private set; }

    /// <summary>Draws the frame into the bound framebuffer, viewport (0, 0, Width, Height).</summary>
    public void Draw(RenderFrame frame)
    {
        Profile?.Frame();
        Profile?.Mark("game, swap");
        EnsureTable(frame.Table);
        var viewProjection = RenderMath.ViewProjection(frame);
        bool moving = _lastEye is { } eye && (eye != frame.Eye || _lastViewProjection != viewProjection);
        _lastEye = frame.Eye;
        _lastViewProjection = viewProjection;
        _stillFrames = moving ? 0 : _stillFrames + 1;
        _lastReduced = DynamicResolution && _stillFrames < StillFramesToSharpen && MovingScale < 1;
        if (Profile is { } profile)
        {
            profile.Tag = _lastReduced ? "reduced " : "full ";
        }
        if (_lastReduced)
        {
            DrawReduced(frame);
        }
        else
        {
            DrawScene3D(frame, frame.Width, frame.Height);
        }

        if (frame.Hud is { } hud)
        {
            _hud.Draw(hud, frame.Width, frame.Height);
            Profile?.Mark("hud");
        }
        _gl.BindVertexArray(0);
    }

    private void DrawReduced(RenderFrame frame)
    {
        uint target = (uint)_gl.GetInteger(Gl.DrawFramebufferBinding);
        int width = frame.Width, height = frame.Height;
        int w = Math.Max(1, (int)(width * MovingScale)), h = Math.Max(1, (int)(height * MovingScale));
        _reduced.Bind(w, h);
        DrawScene3D(frame, w, h);
        Profile?.Mark("before upscale");
        _reduced.DrawTo(target, width, height);
        Profile?.Mark("upscale");
        ReducedFrames++;
    }

    /// <summary>
    /// What a pass draws: the frame, and the view it is drawn from at the size of the target
    /// (the frame's own size, or less for a reduced frame; the frame itself is never changed).
    /// </summary>
    private readonly record struct Pass(RenderFrame Frame, StaticLayer.ViewKey View)
    {
        public int Width => View.Width;

        public int Height => View.Height;
    }

    /// <summary>The table, the room, the balls, the cue and the debug lines, at <paramref name="width"/> x <paramref name="height"/>.</summary>
    private void DrawScene3D(RenderFrame frame, int width, int height)
    {
        var gl = _gl;
        var viewProjection = RenderMath.ViewProjection(frame, width, height);
        float radius = frame.BallRadius;
        Lamps(frame.Table, _lamps);
        var pass = new Pass(frame, new StaticLayer.ViewKey(viewProjection, frame.Eye, frame.Table, width, height));
        _sceneLayer.Draw(pass.View, BallsVersion(frame), _drawScene, pass);
        Profile?.Mark("balls, or the stored layer");
        gl.Viewport(0, 0, width, height);
        gl.Enable(Gl.DepthTest);
        gl.DepthFunc(Gl.LessEqual);
        gl.Disable(Gl.Blend);
        gl.Enable(Gl.CullFace);
        gl.CullFaceMode(Gl.Back);
        _lit.Begin(viewProjection, frame.Eye, _lamps);

        if (frame.Cue.Visible)
        {
            _lit.Material(Vector4.One, new Vector3(0.25f), 40, reflect: 0.02f);
            _lit.Draw(Primitives.CuePlacement(frame.Cue, radius), texture: 0, _cue);
        }

        gl.Disable(Gl.CullFace);

        if (frame.ShowCollisionGeometry && frame.CollisionTriangles.Count > 0)
        {
            _lines.Draw(viewProjection, frame.CollisionTriangles, width, height);
        }
        Profile?.Mark("cue, lines");
    }

    /// <summary>
    /// The table, then the balls' shadows and the balls: the part of the frame that stands still
    /// between shots. The table alone is its own layer, kept while the balls roll.
    /// </summary>
    private void DrawScene(Pass pass)
    {
        var gl = _gl;
        var frame = pass.Frame;
        float radius = frame.BallRadius;
        _tableLayer.Draw(pass.View, 0, _drawTable, pass);
        Profile?.Mark("table");
        gl.Viewport(0, 0, pass.Width, pass.Height);
        gl.Enable(Gl.DepthTest);
        gl.DepthFunc(Gl.LessEqual);
        gl.Disable(Gl.Blend);
        _shadows.Draw(pass.View.ViewProjection, frame.Balls, radius, _lamps, LampRadius, Ambient);
        Profile?.Mark("shadows");

        _lit.Begin(pass.View.ViewProjection, frame.Eye, _lamps);
        // Balls and the cue are closed and wound counter-clockwise outwards: their far halves are
        // dropped before rasterising.
        gl.Enable(Gl.CullFace);
        gl.CullFaceMode(Gl.Back);
        foreach (var ball in frame.Balls)
        {
            if (!ball.Visible)
            {
                continue;
            }
            var model = Matrix4x4.CreateScale(radius) * Matrix4x4.CreateFromQuaternion(Normalized(ball.Orientation)) * Matrix4x4.CreateTranslation(ball.Position);
            _lit.Material(Vector4.One, new Vector3(0.55f), 160, reflect: 0.045f);
            _lit.Draw(model, BallTexture(frame.BallSet, ball.Id), SphereFor(ball.Position, frame, pass.Height, radius));
        }
        gl.Disable(Gl.CullFace);
    }

    /// <summary>A number that changes whenever the balls drawn change (position, orientation, visibility, radius).</summary>
    private long BallsVersion(RenderFrame frame)
    {
        var balls = System.Runtime.InteropServices.CollectionsMarshal.AsSpan(frame.Balls);
        if (frame.BallRadius != _lastRadius || !balls.SequenceEqual(System.Runtime.InteropServices.CollectionsMarshal.AsSpan(_lastBalls)))
        {
            _lastBalls.Clear();
            _lastBalls.AddRange(balls);
            _lastRadius = frame.BallRadius;
            _ballsVersion++;
        }
        return _ballsVersion;
    }

    private void DrawTable(Pass pass)
    {
        var gl = _gl;
        var frame = pass.Frame;
        gl.Viewport(0, 0, pass.Width, pass.Height);
        gl.ClearColor(0.018f, 0.016f, 0.014f, 1);
        gl.Clear(Gl.ColorBufferBit | Gl.DepthBufferBit);
        gl.Enable(Gl.DepthTest);
        gl.DepthFunc(Gl.LessEqual);
        gl.Disable(Gl.CullFace);
        gl.Disable(Gl.Blend);
        gl.Enable(Gl.Multisample);
        foreach (var program in _gouraud)
        {
            program.Begin(pass.View.ViewProjection, frame.Eye, _lamps);
            program.Half((float)frame.Table.HalfLength, (float)frame.Table.HalfWidth);
        }
        foreach (var part in _table!.Parts)
        {
            DrawPart(part);
        }
        // From above the lamps the camera would look down past them at the bed, and they would hide
        // the balls: they are drawn only for a view from below them, as a player's eye at the table.
        bool lampsInView = frame.Eye.Z < LampHeight - 0.02f;
        // A camera outside the room (above the ceiling, beyond a wall) looks in through them.
        bool inRoom = Room.Contains(frame.Table, frame.Eye);
        foreach (var part in _room!.Parts)
        {
            bool lamp = part.Name == Room.Shade.Name || part.Name == Room.Bulb.Name;
            if (inRoom && (!lamp || lampsInView))
            {
                DrawPart(part);
            }
        }
    }

    private void DrawPart(ModelPart part)
    {
        var (detail, texture, repeat) = DetailOf(part.Name);
        var program = _gouraud[detail];
        program.Use();
        program.Material(part.Diffuse, part.Specular, part.Shininess, reflect: 0);
        program.Detail(repeat);
        program.Emissive(part.Name == Room.Bulb.Name ? new Vector3(1.0f, 0.97f, 0.88f) : Vector3.Zero);
        program.Draw(Matrix4x4.Identity, texture, part.Mesh);
    }

    /// <summary>How a part's colour is textured: 0 plain, 1 across the bed's plane, 2 along the rail it belongs to.</summary>
    private (int Mapping, uint Texture, float Repeat) DetailOf(string part) => part switch
    {
        "cloth" or "cushion" => (1, _details.Cloth, SurfaceTextures.ClothRepeat),
        "rail" or "frame" => (2, _details.Wood, SurfaceTextures.WoodRepeat),
        "floor" => (1, _details.Planks, SurfaceTextures.PlankRepeat),
        "pocket" => (1, _details.Cloth, SurfaceTextures.ClothRepeat / 4),
        _ => (0, 0u, 1f),
    };

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

    /// <summary>Slices of the sphere's levels of detail, coarse to fine (stacks are three quarters).</summary>
    public static readonly int[] SphereSlices = [12, 20, 32, 48];

    /// <summary>Largest gap between a ball's drawn outline and the true circle (px).</summary>
    public const float OutlineTolerancePixels = 0.5f;

    /// <summary>
    /// The fewest slices whose outline, a polygon of that many sides around a circle of
    /// <paramref name="radiusPixels"/>, stays within <see cref="OutlineTolerancePixels"/> of it:
    /// the sagitta r (1 - cos(pi / n)).
    /// </summary>
    public static int SlicesFor(float radiusPixels)
    {
        foreach (int n in SphereSlices)
        {
            if (radiusPixels * (1 - MathF.Cos(MathF.PI / n)) <= OutlineTolerancePixels)
            {
                return n;
            }
        }
        return SphereSlices[^1];
    }

    /// <summary>The ball's radius on screen (px) at <paramref name="position"/>, seen from the frame's eye.</summary>
    public static float RadiusPixels(Vector3 position, RenderFrame frame, float radius) => RadiusPixels(position, frame, frame.Height, radius);

    /// <summary>The ball's radius (px) on a target <paramref name="height"/> pixels high.</summary>
    public static float RadiusPixels(Vector3 position, RenderFrame frame, int height, float radius)
    {
        ArgumentNullException.ThrowIfNull(frame);
        float distance = MathF.Max(Vector3.Distance(position, frame.Eye), RenderMath.Near);
        float focal = 0.5f * height / MathF.Tan(frame.FovYDegrees * MathF.PI / 360);
        return radius * focal / distance;
    }

    private GpuMesh SphereFor(Vector3 position, RenderFrame frame, int height, float radius)
    {
        int slices = SlicesFor(RadiusPixels(position, frame, height, radius));
        foreach (var (n, mesh) in _spheres)
        {
            if (n == slices)
            {
                return mesh;
            }
        }
        return _spheres[^1].Mesh;
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
        Span<float> lamps = stackalloc float[12];
        Lamps(spec, lamps);
        _room?.Dispose();
        _room = TableModel.FromBuilders(_gl, "room",
            [Room.Walls(spec), Room.CeilingMesh(spec), Room.Shades(lamps), Room.Bulbs(lamps)],
            refine: [true, true, false, false]);
        _tableSpec = spec;
    }

    private uint BallTexture(BallSet set, BallId id)
    {
        if (_ballTextures.TryGetValue((set.Name, id.Value), out uint texture))
        {
            return texture;
        }
        texture = _gl.GenTexture();
        _gl.BindTexture(Gl.Texture2D, texture);
        _gl.PixelStore(Gl.UnpackAlignment, 1);
        _gl.TexImage2D(Gl.Texture2D, 0, Gl.Srgb8Alpha8, BallTextures.Width, BallTextures.Height, Gl.Rgba, Gl.UnsignedByte, BallTextures.Generate(set, id));
        _gl.GenerateMipmap(Gl.Texture2D);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMinFilter, Gl.LinearMipmapLinear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMagFilter, Gl.Linear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapS, Gl.Repeat);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapT, Gl.ClampToEdge);
        DetailTextures.Anisotropic(_gl);
        _ballTextures[(set.Name, id.Value)] = texture;
        return texture;
    }

    public void Dispose()
    {
        _table?.Dispose();
        _room?.Dispose();
        _details.Dispose();
        foreach (var (_, mesh) in _spheres)
        {
            mesh.Dispose();
        }
        _cue.Dispose();
        foreach (uint texture in _ballTextures.Values)
        {
            _gl.DeleteTexture(texture);
        }
        _lines.Dispose();
        _shadows.Dispose();
        _hud.Dispose();
        _tableLayer.Dispose();
        _sceneLayer.Dispose();
        _reduced.Dispose();
        _gl.DeleteProgram(_lit.Program);
        foreach (var program in _gouraud)
        {
            _gl.DeleteProgram(program.Program);
        }
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
        private readonly int _detailRepeat = gl.GetUniformLocation(program, "uDetailRepeat");
        private readonly int _half = gl.GetUniformLocation(program, "uHalf");
        private readonly int _emissive = gl.GetUniformLocation(program, "uEmissive");

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

        /// <summary>The metres one repeat of the detail texture covers.</summary>
        public void Detail(float repeat) => gl.Uniform1(_detailRepeat, 1 / repeat);

        public void Use() => gl.UseProgram(Program);

        /// <summary>Half the bed's length and width (m): where the rails along x give way to those along y.</summary>
        public void Half(float x, float y) => gl.Uniform2(_half, x, y);

        /// <summary>Light the surface gives off itself (tone-mapped colour; zero for none).</summary>
        public void Emissive(Vector3 color) => gl.Uniform3(_emissive, color.X, color.Y, color.Z);

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
