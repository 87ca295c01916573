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
