using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>
/// A framebuffer of reduced size whose colour is a texture, and the pass that draws it over the
/// whole bound framebuffer, filtered (one triangle that covers the screen, one bilinear fetch a
/// pixel). On llvmpipe a scaling glBlitFramebuffer of a 1280x720 frame cost more processor time
/// than drawing the table at a third of the resolution.
/// </summary>
internal sealed class Upscaler : IDisposable
{
    private const string Vertex = """
        #version 330 core
        out vec2 vUv;
        void main() {
            // Three vertices from their index: a triangle covering the screen, (0, 0) to (1, 1) in uv.
            vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
            vUv = 0.5 * p + 0.5;
            gl_Position = vec4(p, 0.0, 1.0);
        }
        """;

    private const string Fragment = """
        #version 330 core
        in vec2 vUv;
        uniform sampler2D uScene;
        out vec4 fragColor;
        void main() { fragColor = vec4(texture(uScene, vUv).rgb, 1.0); }
        """;

    private readonly Gl _gl;
    private readonly uint _program, _vao;
    private readonly int _sampler;
    private uint _framebuffer, _color, _depth;

    public Upscaler(Gl gl)
    {
        _gl = gl;
        _program = gl.LinkProgram(gl.CompileShader(Gl.VertexShader, Vertex), gl.CompileShader(Gl.FragmentShader, Fragment), []);
        _sampler = gl.GetUniformLocation(_program, "uScene");
        _vao = gl.GenVertexArray();
    }

    /// <summary>The size of the reduced framebuffer (0 x 0 before the first <see cref="Bind"/>).</summary>
    public (int Width, int Height) Size { get; private set; }

    /// <summary>Binds the reduced framebuffer, made or remade at <paramref name="width"/> x <paramref name="height"/>.</summary>
    public void Bind(int width, int height)
    {
        if (_framebuffer == 0 || Size != (width, height))
        {
            Release();
            Size = (width, height);
            (_framebuffer, _color) = TextureFramebuffer.Create(_gl, width, height, Gl.Linear);
            _depth = _gl.GenRenderbuffer();
            _gl.BindRenderbuffer(Gl.Renderbuffer, _depth);
            _gl.RenderbufferStorage(Gl.Renderbuffer, Gl.Depth24Stencil8, width, height);
            _gl.FramebufferRenderbuffer(Gl.Framebuffer, Gl.DepthStencilAttachment, Gl.Renderbuffer, _depth);
        }
        _gl.BindFramebuffer(Gl.Framebuffer, _framebuffer);
    }

    /// <summary>The reduced framebuffer (0 before the first <see cref="Bind"/>).</summary>
    public uint Framebuffer => _framebuffer;

    /// <summary>Draws the reduced colour over framebuffer <paramref name="target"/>, <paramref name="width"/> x <paramref name="height"/>, and leaves it bound.</summary>
    public void DrawTo(uint target, int width, int height)
    {
        _gl.BindFramebuffer(Gl.Framebuffer, target);
        _gl.Viewport(0, 0, width, height);
        _gl.Disable(Gl.DepthTest);
        _gl.Disable(Gl.Blend);
        _gl.Disable(Gl.CullFace);
        _gl.UseProgram(_program);
        _gl.Uniform1(_sampler, 0);
        _gl.ActiveTexture(Gl.Texture0);
        _gl.BindTexture(Gl.Texture2D, _color);
        _gl.BindVertexArray(_vao);
        _gl.DrawArrays(Gl.Triangles, 0, 3);
        _gl.Enable(Gl.DepthTest);
    }

    private void Release()
    {
        if (_framebuffer == 0)
        {
            return;
        }
        _gl.DeleteFramebuffer(_framebuffer);
        _gl.DeleteTexture(_color);
        _gl.DeleteRenderbuffer(_depth);
        _framebuffer = 0;
    }

    public void Dispose()
    {
        Release();
        _gl.DeleteVertexArray(_vao);
        _gl.DeleteProgram(_program);
    }
}
