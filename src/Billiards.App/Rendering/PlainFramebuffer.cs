using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>
/// A single-sampled framebuffer with RGBA8 colour and a 24-bit depth with 8-bit stencil buffer,
/// the formats of a window's, so that colour and depth can be copied between them.
/// </summary>
internal readonly record struct PlainFramebuffer(uint Framebuffer, uint Color, uint Depth)
{
    /// <summary>Makes one of <paramref name="width"/> x <paramref name="height"/> and leaves it bound.</summary>
    public static PlainFramebuffer Create(Gl gl, int width, int height)
    {
        uint framebuffer = gl.GenFramebuffer();
        gl.BindFramebuffer(Gl.Framebuffer, framebuffer);
        uint color = gl.GenRenderbuffer();
        gl.BindRenderbuffer(Gl.Renderbuffer, color);
        gl.RenderbufferStorage(Gl.Renderbuffer, Gl.Rgba8, width, height);
        gl.FramebufferRenderbuffer(Gl.Framebuffer, Gl.ColorAttachment0, Gl.Renderbuffer, color);
        uint depth = gl.GenRenderbuffer();
        gl.BindRenderbuffer(Gl.Renderbuffer, depth);
        gl.RenderbufferStorage(Gl.Renderbuffer, Gl.Depth24Stencil8, width, height);
        gl.FramebufferRenderbuffer(Gl.Framebuffer, Gl.DepthStencilAttachment, Gl.Renderbuffer, depth);
        return new PlainFramebuffer(framebuffer, color, depth);
    }

    /// <summary>True when the bound framebuffer can be drawn into.</summary>
    public static bool BoundIsComplete(Gl gl) => gl.CheckFramebufferStatus(Gl.Framebuffer) == Gl.FramebufferComplete;

    public void Delete(Gl gl)
    {
        gl.DeleteFramebuffer(Framebuffer);
        gl.DeleteRenderbuffer(Color);
        gl.DeleteRenderbuffer(Depth);
    }
}

/// <summary>A framebuffer whose colour is an RGBA8 texture, to be drawn from afterwards (the HUD's stored layer, the reduced frame).</summary>
internal static class TextureFramebuffer
{
    /// <summary>Makes a <paramref name="width"/> x <paramref name="height"/> texture filtered by <paramref name="filter"/> (clamped at the edges), and a framebuffer drawing into it, left bound.</summary>
    public static (uint Framebuffer, uint Texture) Create(Gl gl, int width, int height, int filter)
    {
        uint texture = gl.GenTexture();
        gl.BindTexture(Gl.Texture2D, texture);
        gl.TexImage2D(Gl.Texture2D, 0, Gl.Rgba8, width, height, Gl.Rgba, Gl.UnsignedByte, default);
        gl.TexParameter(Gl.Texture2D, Gl.TextureMinFilter, filter);
        gl.TexParameter(Gl.Texture2D, Gl.TextureMagFilter, filter);
        gl.TexParameter(Gl.Texture2D, Gl.TextureWrapS, Gl.ClampToEdge);
        gl.TexParameter(Gl.Texture2D, Gl.TextureWrapT, Gl.ClampToEdge);
        uint framebuffer = gl.GenFramebuffer();
        gl.BindFramebuffer(Gl.Framebuffer, framebuffer);
        gl.FramebufferTexture2D(Gl.Framebuffer, Gl.ColorAttachment0, Gl.Texture2D, texture, 0);
        return (framebuffer, texture);
    }
}
