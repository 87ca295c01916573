using Billiards.App.Native;
using Billiards.App.Platform;

namespace Billiards.App.Rendering;

/// <summary>
/// Renders frames without a window: an offscreen context (EGL surfaceless or a hidden GLFW
/// window), a 4x multisampled framebuffer object resolved by a blit, read back as RGBA. With one
/// sample it draws straight into the framebuffer that is read back, as a window on a software
/// rasteriser does.
/// </summary>
internal sealed class OffscreenRenderer : IDisposable
{
    private readonly IGlContext _context;
    private readonly Gl _gl;
    private readonly Renderer _renderer;
    private readonly int _samples;
    private Target? _target;

    public OffscreenRenderer(Func<Billiards.Core.Table.TableSpec, string>? modelPath = null, int samples = 4)
    {
        _samples = samples;
        _context = OffscreenContext.Create();
        try
        {
            _gl = new Gl(_context.GetProcAddress);
            _renderer = new Renderer(_gl, modelPath);
            Description = $"{_context.Description}, {_gl.GetString(Gl.RendererName)}";
            _context.ReleaseCurrent();
        }
        catch
        {
            _context.Dispose();
            throw;
        }
    }

    /// <summary>How the context was made and what draws, e.g. "EGL surfaceless, llvmpipe (LLVM 15.0.6, 256 bits)".</summary>
    public string Description { get; }

    /// <summary>The renderer (for its statistics).</summary>
    public Renderer Renderer => _renderer;

    /// <summary>The table model file last drawn.</summary>
    public string? TableSource => _renderer.TableSource;

    /// <summary>Draws a frame and returns its pixels: RGBA, top row first, alpha 255.</summary>
    public byte[] Render(RenderFrame frame)
    {
        if (frame.Width <= 0 || frame.Height <= 0)
        {
            throw new ArgumentException($"frame size {frame.Width} x {frame.Height}");
        }
        _context.MakeCurrent();
        try
        {
            return Draw(frame);
        }
        finally
        {
            _context.ReleaseCurrent();
        }
    }

    private byte[] Draw(RenderFrame frame)
    {
        if (_target is null || _target.Width != frame.Width || _target.Height != frame.Height)
        {
            _target?.Dispose();
            _target = new Target(_gl, frame.Width, frame.Height, _samples);
        }
        _gl.BindFramebuffer(Gl.Framebuffer, _target.Multisampled);
        _renderer.Draw(frame);
        if (_target.Multisampled != _target.Resolved)
        {
            _gl.BindFramebuffer(Gl.ReadFramebuffer, _target.Multisampled);
            _gl.BindFramebuffer(Gl.DrawFramebuffer, _target.Resolved);
            _gl.BlitFramebuffer(0, 0, frame.Width, frame.Height, 0, 0, frame.Width, frame.Height, Gl.ColorBufferBit, (uint)Gl.Nearest);
        }
        _gl.BindFramebuffer(Gl.ReadFramebuffer, _target.Resolved);
        _gl.PixelStore(Gl.PackAlignment, 1);
        int stride = frame.Width * 4;
        var bottomUp = new byte[stride * frame.Height];
        _gl.ReadPixels(0, 0, frame.Width, frame.Height, Gl.Rgba, Gl.UnsignedByte, bottomUp);
        uint error = _gl.GetError();
        _gl.BindFramebuffer(Gl.Framebuffer, 0);
        if (error != 0)
        {
            throw new InvalidOperationException($"OpenGL error 0x{error:X} while rendering");
        }
        var pixels = new byte[bottomUp.Length];
        for (int y = 0; y < frame.Height; y++)
        {
            bottomUp.AsSpan((frame.Height - 1 - y) * stride, stride).CopyTo(pixels.AsSpan(y * stride, stride));
        }
        for (int i = 3; i < pixels.Length; i += 4)
        {
            pixels[i] = 255;
        }
        return pixels;
    }

    public void Dispose()
    {
        _context.MakeCurrent();
        _target?.Dispose();
        _target = null;
        _renderer.Dispose();
        _context.Dispose();
    }

    /// <summary>
    /// The multisampled framebuffer (colour and depth) and the single-sampled one it resolves
    /// into; with one sample, one framebuffer with colour and a depth-stencil buffer like a window's.
    /// </summary>
    private sealed class Target : IDisposable
    {
        private readonly Gl _gl;
        private readonly uint _colorMs, _depthMs, _color;
        private readonly PlainFramebuffer _plain;

        public Target(Gl gl, int width, int height, int samplesWanted)
        {
            _gl = gl;
            Width = width;
            Height = height;
            if (samplesWanted <= 1)
            {
                _plain = PlainFramebuffer.Create(gl, width, height);
                Resolved = Multisampled = _plain.Framebuffer;
                Check(gl, "single-sampled");
                return;
            }
            int samples = Math.Clamp(gl.GetInteger(Gl.MaxSamples), 1, samplesWanted);
            Multisampled = gl.GenFramebuffer();
            gl.BindFramebuffer(Gl.Framebuffer, Multisampled);
            _colorMs = gl.GenRenderbuffer();
            gl.BindRenderbuffer(Gl.Renderbuffer, _colorMs);
            gl.RenderbufferStorageMultisample(Gl.Renderbuffer, samples, Gl.Rgba8, width, height);
            gl.FramebufferRenderbuffer(Gl.Framebuffer, Gl.ColorAttachment0, Gl.Renderbuffer, _colorMs);
            _depthMs = gl.GenRenderbuffer();
            gl.BindRenderbuffer(Gl.Renderbuffer, _depthMs);
            gl.RenderbufferStorageMultisample(Gl.Renderbuffer, samples, Gl.DepthComponent24, width, height);
            gl.FramebufferRenderbuffer(Gl.Framebuffer, Gl.DepthAttachment, Gl.Renderbuffer, _depthMs);
            Check(gl, "multisampled");

            Resolved = gl.GenFramebuffer();
            gl.BindFramebuffer(Gl.Framebuffer, Resolved);
            _color = gl.GenRenderbuffer();
            gl.BindRenderbuffer(Gl.Renderbuffer, _color);
            gl.RenderbufferStorage(Gl.Renderbuffer, Gl.Rgba8, width, height);
            gl.FramebufferRenderbuffer(Gl.Framebuffer, Gl.ColorAttachment0, Gl.Renderbuffer, _color);
            Check(gl, "resolve");
        }

        public int Width { get; }
        public int Height { get; }
        public uint Multisampled { get; }
        public uint Resolved { get; }

        private static void Check(Gl gl, string what)
        {
            uint status = gl.CheckFramebufferStatus(Gl.Framebuffer);
            if (status != Gl.FramebufferComplete)
            {
                throw new InvalidOperationException($"the {what} framebuffer is incomplete (0x{status:X})");
            }
        }

        public void Dispose()
        {
            if (_plain.Framebuffer != 0)
            {
                _plain.Delete(_gl);
                return;
            }
            _gl.DeleteFramebuffer(Multisampled);
            _gl.DeleteFramebuffer(Resolved);
            _gl.DeleteRenderbuffer(_colorMs);
            _gl.DeleteRenderbuffer(_depthMs);
            _gl.DeleteRenderbuffer(_color);
        }
    }
}
