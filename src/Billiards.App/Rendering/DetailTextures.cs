namespace Billiards.App.Rendering;

/// <summary>The <see cref="SurfaceTextures"/> on the GPU: mipmapped, repeating, filtered anisotropically where the driver can.</summary>
internal sealed class DetailTextures : IDisposable
{
    private const uint MaxAnisotropy = 0x84FE, MaxAnisotropyLimit = 0x84FF; // EXT_texture_filter_anisotropic, core in GL 4.6

    private readonly Gl _gl;

    public DetailTextures(Gl gl)
    {
        _gl = gl;
        Cloth = Upload(SurfaceTextures.Cloth());
        Wood = Upload(SurfaceTextures.Wood());
        Planks = Upload(SurfaceTextures.Planks());
    }

    public uint Cloth { get; }
    public uint Wood { get; }
    public uint Planks { get; }

    private uint Upload(byte[] texels)
    {
        uint texture = _gl.GenTexture();
        _gl.BindTexture(Gl.Texture2D, texture);
        _gl.PixelStore(Gl.UnpackAlignment, 1);
        _gl.TexImage2D(Gl.Texture2D, 0, Gl.R8, SurfaceTextures.Size, SurfaceTextures.Size, Gl.Red, Gl.UnsignedByte, texels);
        _gl.GenerateMipmap(Gl.Texture2D);
        // A software rasteriser blends no two mip levels: the table's texturing was most of a moving
        // frame's cost there, and one level took a third of it off.
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMinFilter, _gl.IsSoftwareRasterizer ? Gl.LinearMipmapNearest : Gl.LinearMipmapLinear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMagFilter, Gl.Linear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapS, Gl.Repeat);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapT, Gl.Repeat);
        Anisotropic(_gl);
        return texture;
    }

    /// <summary>
    /// Turns on anisotropic filtering (up to 8x) for the bound texture if the driver has it, except
    /// on a software rasteriser: llvmpipe takes every one of the extra samples for every pixel, which
    /// made one frame cost seconds.
    /// </summary>
    public static void Anisotropic(Gl gl)
    {
        if (gl.IsSoftwareRasterizer)
        {
            return;
        }
        float limit = gl.GetFloat(MaxAnisotropyLimit);
        gl.GetError(); // an unknown name is GL_INVALID_ENUM: the extension is absent, nothing to do
        if (limit > 1)
        {
            gl.TexParameter(Gl.Texture2D, MaxAnisotropy, MathF.Min(8, limit));
        }
    }

    public void Dispose()
    {
        _gl.DeleteTexture(Cloth);
        _gl.DeleteTexture(Wood);
        _gl.DeleteTexture(Planks);
    }
}
