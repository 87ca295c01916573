using System.Numerics;
using Billiards.App.Native;
using Billiards.Core.Table;

namespace Billiards.App.Rendering;

/// <summary>
/// A layer of the frame as last drawn (colour and depth), kept while the camera and the layer's
/// content stand still: the table, and over it the balls at rest with their shadows. A software
/// rasteriser pays most of a frame for the table, which covers the screen in thousands of
/// triangles; while the view does not change, copying the stored layer back costs a fraction of
/// that, and the balls, shadows, cue and HUD are drawn over it as before. The layer is stored only
/// once the same view has been drawn twice in a row, so a moving camera pays no copy.
/// Only for a single-sampled target whose depth format matches (the window on llvmpipe); anything
/// else (a multisampled window, the offscreen renderer) draws the table every frame.
/// </summary>
internal sealed class StaticLayer : IDisposable
{

    private readonly Gl _gl;
    private PlainFramebuffer _target;
    private int _width, _height;
    private (ViewKey View, long Content)? _stored;
    private (ViewKey View, long Content)? _previous;
    private bool _unsupported;

    public StaticLayer(Gl gl) => _gl = gl;

    /// <summary>Frames whose table came from the stored layer (for tests and stats).</summary>
    public long Reused { get; private set; }

    /// <summary>
    /// Puts the layer into the bound draw framebuffer: from the stored layer when
    /// <paramref name="view"/> and <paramref name="content"/> (a version the caller changes
    /// whenever what <paramref name="draw"/> draws changes) are the stored ones, else by
    /// <paramref name="draw"/> with <paramref name="state"/> (which clears and draws into whatever
    /// framebuffer is bound), storing the result when they stood still for two frames.
    /// </summary>
    public void Draw<TState>(ViewKey view, long content, Action<TState> draw, TState state)
    {
        var key = (view, content);
        uint target = (uint)_gl.GetInteger(Gl.DrawFramebufferBinding);
        if (_unsupported || _gl.GetInteger(Gl.Samples) > 0)
        {
            draw(state);
            return;
        }
        if (_stored == key)
        {
            CopyTo(target, view);
            Reused++;
            return;
        }
        if (_previous != key)
        {
            _previous = key;
            _stored = null;
            draw(state);
            return;
        }
        Ensure(view.Width, view.Height);
        if (_unsupported)
        {
            _gl.BindFramebuffer(Gl.Framebuffer, target);
            draw(state);
            return;
        }
        _gl.BindFramebuffer(Gl.Framebuffer, _target.Framebuffer);
        draw(state);
        _stored = key;
        CopyTo(target, view);
        if (_gl.GetError() != 0)
        {
            // The target's depth cannot take this layer's: draw directly from now on.
            _unsupported = true;
            _stored = null;
            _gl.BindFramebuffer(Gl.Framebuffer, target);
            draw(state);
        }
    }

    private void CopyTo(uint target, ViewKey view)
    {
        _gl.BindFramebuffer(Gl.ReadFramebuffer, _target.Framebuffer);
        _gl.BindFramebuffer(Gl.DrawFramebuffer, target);
        _gl.BlitFramebuffer(0, 0, view.Width, view.Height, 0, 0, view.Width, view.Height, Gl.ColorBufferBit | Gl.DepthBufferBit, (uint)Gl.Nearest);
        _gl.BindFramebuffer(Gl.Framebuffer, target);
    }

    private void Ensure(int width, int height)
    {
        if (_target.Framebuffer != 0 && width == _width && height == _height)
        {
            return;
        }
        Release();
        _width = width;
        _height = height;
        _target = PlainFramebuffer.Create(_gl, width, height);
        _unsupported |= !PlainFramebuffer.BoundIsComplete(_gl);
    }

    private void Release()
    {
        if (_target.Framebuffer == 0)
        {
            return;
        }
        _target.Delete(_gl);
        _target = default;
    }
    public void Dispose() => Release();

    /// <summary>What the stored layer depends on: the view, the table and the framebuffer's size.</summary>
    public readonly record struct ViewKey(Matrix4x4 ViewProjection, Vector3 Eye, TableSpec Table, int Width, int Height);
}
