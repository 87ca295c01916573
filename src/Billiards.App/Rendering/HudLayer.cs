using System.Runtime.InteropServices;
using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>
/// The HUD as last drawn, kept in a texture while it does not change. Its text is hundreds of
/// small blended quads, and the help overlay a panel over most of the screen: a software
/// rasteriser paid several milliseconds a frame for a HUD that changes a few times a second.
/// The HUD is stored (premultiplied alpha) once the same quads have been drawn twice in a row;
/// while they stay the same, one textured quad over their bounding box puts it back. A HUD that
/// changes every frame (the power meter while stroking) is drawn directly and pays no copy.
/// </summary>
internal sealed class HudLayer : IDisposable
{
    private const string CompositeVertex = """
        #version 330 core
        in vec2 aPosition;
        uniform vec2 uScreen;
        out vec2 vUv;
        void main() {
            vUv = vec2(aPosition.x / uScreen.x, 1.0 - aPosition.y / uScreen.y);
            gl_Position = vec4(aPosition.x / uScreen.x * 2.0 - 1.0, 1.0 - aPosition.y / uScreen.y * 2.0, 0.0, 1.0);
        }
        """;

    private const string CompositeFragment = """
        #version 330 core
        in vec2 vUv;
        uniform sampler2D uHud;
        out vec4 fragColor;
        void main() { fragColor = texture(uHud, vUv); }
        """;

    private readonly Gl _gl;
    private readonly uint _program, _vao, _vbo;
    private readonly int _screen, _sampler;
    private readonly List<float> _previous = [];
    private uint _framebuffer, _texture;
    private int _width, _height;
    private bool _stored;
    private const byte Touched = 1, Opaque = 2;
    private readonly List<float> _blended = [];
    private readonly List<(int X0, int Y0, int X1, int Y1)> _copied = [];
    private byte[] _tiles = [];
    private int _columns, _rows;

    public HudLayer(Gl gl)
    {
        _gl = gl;
        _program = gl.LinkProgram(gl.CompileShader(Gl.VertexShader, CompositeVertex),
            gl.CompileShader(Gl.FragmentShader, CompositeFragment), ["aPosition"]);
        _screen = gl.GetUniformLocation(_program, "uScreen");
        _sampler = gl.GetUniformLocation(_program, "uHud");
        _vao = gl.GenVertexArray();
        _vbo = gl.GenBuffer();
        gl.BindVertexArray(_vao);
        gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        gl.VertexAttribPointer(0, 2, Gl.Float, false, 2 * sizeof(float), 0);
        gl.EnableVertexAttribArray(0);
        gl.BindVertexArray(0);
    }

    /// <summary>Frames whose HUD came from the stored texture.</summary>
    public long Reused { get; private set; }

    /// <summary>
    /// Puts the HUD described by <paramref name="vertices"/> (<paramref name="floatsPerVertex"/>
    /// floats a vertex, pixel position first) over the bound framebuffer: from the stored texture
    /// when the quads are the stored ones, else by <paramref name="draw"/>, whose argument says
    /// whether to blend for a premultiplied layer (true) or straight onto the frame (false).
    /// </summary>
    public void Draw(List<float> vertices, int floatsPerVertex, int width, int height, Action<bool> draw)
    {
        var quads = CollectionsMarshal.AsSpan(vertices);
        bool same = quads.SequenceEqual(CollectionsMarshal.AsSpan(_previous));
        if (same && _stored && width == _width && height == _height)
        {
            Composite((uint)_gl.GetInteger(Gl.DrawFramebufferBinding));
            Reused++;
            return;
        }
        if (!same)
        {
            _previous.Clear();
            _previous.AddRange(quads);
            _stored = false;
            draw(false);
            return;
        }
        uint target = (uint)_gl.GetInteger(Gl.DrawFramebufferBinding);
        Ensure(width, height);
        _gl.BindFramebuffer(Gl.Framebuffer, _framebuffer);
        _gl.Viewport(0, 0, width, height);
        _gl.ClearColor(0, 0, 0, 0);
        _gl.Clear(Gl.ColorBufferBit);
        draw(true);
        _gl.BindFramebuffer(Gl.Framebuffer, target);
        Bounds(quads, floatsPerVertex, width, height);
        _stored = true;
        Composite(target);
    }

    /// <summary>Side of the squares the screen is divided into for putting the layer back (px).</summary>
    public const int Tile = 32;

    /// <summary>
    /// Which squares of the screen the HUD touches, and which of them lie wholly inside an opaque
    /// solid quad (those are copied, the others blended). The HUD is drawn as quads of six
    /// vertices: x, y, u, v, r, g, b, a, kind (0 = solid).
    /// </summary>
    private void Bounds(ReadOnlySpan<float> quads, int floatsPerVertex, int width, int height)
    {
        _columns = (width + Tile - 1) / Tile;
        _rows = (height + Tile - 1) / Tile;
        Array.Resize(ref _tiles, _columns * _rows);
        Array.Clear(_tiles);
        int quadFloats = 6 * floatsPerVertex;
        for (int q = 0; q + quadFloats <= quads.Length; q += quadFloats)
        {
            float x0 = float.MaxValue, y0 = float.MaxValue, x1 = float.MinValue, y1 = float.MinValue;
            for (int v = q; v < q + quadFloats; v += floatsPerVertex)
            {
                x0 = MathF.Min(x0, quads[v]);
                x1 = MathF.Max(x1, quads[v]);
                y0 = MathF.Min(y0, quads[v + 1]);
                y1 = MathF.Max(y1, quads[v + 1]);
            }
            // Copied whole only where an opaque quad stands square on the screen: a tilted one (a
            // line: the cue in the elevation diagram) does not cover the squares of its bounding box.
            bool square = true;
            for (int v = q; v < q + quadFloats; v += floatsPerVertex)
            {
                square &= (quads[v] == x0 || quads[v] == x1) && (quads[v + 1] == y0 || quads[v + 1] == y1);
            }
            bool opaque = square && quads[q + 8] == 0 && quads[q + 7] >= 1;
            // One pixel more on each side for antialiased edges.
            int c0 = Math.Max(0, (int)MathF.Floor((x0 - 1) / Tile)), c1 = Math.Min(_columns - 1, (int)MathF.Floor((x1 + 1) / Tile));
            int r0 = Math.Max(0, (int)MathF.Floor((y0 - 1) / Tile)), r1 = Math.Min(_rows - 1, (int)MathF.Floor((y1 + 1) / Tile));
            for (int r = r0; r <= r1; r++)
            {
                for (int c = c0; c <= c1; c++)
                {
                    bool inside = opaque && c * Tile >= x0 && (c + 1) * Tile <= x1 && r * Tile >= y0 && (r + 1) * Tile <= y1;
                    ref byte tile = ref _tiles[(r * _columns) + c];
                    tile = inside ? Opaque : Math.Max(tile, Touched);
                }
            }
        }
        _blended.Clear();
        _copied.Clear();
        for (int r = 0; r < _rows; r++)
        {
            for (int c = 0; c < _columns;)
            {
                byte kind = _tiles[(r * _columns) + c];
                int end = c + 1;
                while (end < _columns && _tiles[(r * _columns) + end] == kind)
                {
                    end++;
                }
                if (kind != 0)
                {
                    var run = (X0: c * Tile, Y0: r * Tile, X1: Math.Min(width, end * Tile), Y1: Math.Min(height, (r + 1) * Tile));
                    if (kind == Opaque)
                    {
                        _copied.Add(run);
                    }
                    else
                    {
                        ReadOnlySpan<float> quad = [run.X0, run.Y0, run.X1, run.Y0, run.X1, run.Y1, run.X0, run.Y0, run.X1, run.Y1, run.X0, run.Y1];
                        foreach (float f in quad)
                        {
                            _blended.Add(f);
                        }
                    }
                }
                c = end;
            }
        }
    }

    private void Composite(uint target)
    {
        // Opaque squares are copied (a plain copy is the rasteriser's cheapest path), the rest blended.
        if (_copied.Count > 0)
        {
            _gl.BindFramebuffer(Gl.ReadFramebuffer, _framebuffer);
            _gl.BindFramebuffer(Gl.DrawFramebuffer, target);
            foreach (var (x0, y0, x1, y1) in _copied)
            {
                int gy0 = _height - y1, gy1 = _height - y0;
                _gl.BlitFramebuffer(x0, gy0, x1, gy1, x0, gy0, x1, gy1, Gl.ColorBufferBit, (uint)Gl.Nearest);
            }
        }
        _gl.BindFramebuffer(Gl.Framebuffer, target);
        if (_blended.Count == 0)
        {
            return;
        }
        _gl.Viewport(0, 0, _width, _height);
        _gl.Disable(Gl.DepthTest);
        _gl.Enable(Gl.Blend);
        _gl.BlendFunc(Gl.One, Gl.OneMinusSrcAlpha);
        _gl.UseProgram(_program);
        _gl.Uniform2(_screen, _width, _height);
        _gl.Uniform1(_sampler, 0);
        _gl.ActiveTexture(Gl.Texture0);
        _gl.BindTexture(Gl.Texture2D, _texture);
        _gl.BindVertexArray(_vao);
        _gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        _gl.BufferData<float>(Gl.ArrayBuffer, CollectionsMarshal.AsSpan(_blended), Gl.DynamicDraw);
        _gl.DrawArrays(Gl.Triangles, 0, _blended.Count / 2);
        _gl.Disable(Gl.Blend);
        _gl.Enable(Gl.DepthTest);
    }

    private void Ensure(int width, int height)
    {
        if (_framebuffer != 0 && width == _width && height == _height)
        {
            return;
        }
        Release();
        _width = width;
        _height = height;
        (_framebuffer, _texture) = TextureFramebuffer.Create(_gl, width, height, Gl.Nearest);
    }

    private void Release()
    {
        if (_framebuffer == 0)
        {
            return;
        }
        _gl.DeleteFramebuffer(_framebuffer);
        _gl.DeleteTexture(_texture);
        _framebuffer = 0;
    }

    public void Dispose()
    {
        Release();
        _gl.DeleteBuffer(_vbo);
        _gl.DeleteVertexArray(_vao);
        _gl.DeleteProgram(_program);
    }
}
