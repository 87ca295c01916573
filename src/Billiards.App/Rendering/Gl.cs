using Silk.NET.OpenGL;

namespace Billiards.App.Rendering;

/// <summary>
/// The OpenGL 3.3 core calls the renderer makes, through Silk.NET.OpenGL's bindings for whatever
/// context is current (GLFW or EGL give the loader). The renderer speaks GL's numbers (the
/// constants below are Silk.NET's enum values); this class adds what every caller would
/// otherwise repeat: shader compilation and linking with their logs, System.Numerics matrices,
/// spans for buffers and pixels.
/// </summary>
internal sealed unsafe class Gl
{
    public const uint DepthBufferBit = (uint)ClearBufferMask.DepthBufferBit, ColorBufferBit = (uint)ClearBufferMask.ColorBufferBit;
    public const uint Lines = (uint)GLEnum.Lines, Triangles = (uint)GLEnum.Triangles;
    public const uint DepthTest = (uint)GLEnum.DepthTest, Blend = (uint)GLEnum.Blend, CullFace = (uint)GLEnum.CullFace, Multisample = (uint)GLEnum.Multisample, PolygonOffsetFill = (uint)GLEnum.PolygonOffsetFill;
    public const uint Zero = (uint)GLEnum.Zero, One = (uint)GLEnum.One, SrcColor = (uint)GLEnum.SrcColor;
    public const uint SrcAlpha = (uint)GLEnum.SrcAlpha, OneMinusSrcAlpha = (uint)GLEnum.OneMinusSrcAlpha, Less = (uint)GLEnum.Less, LessEqual = (uint)GLEnum.Lequal, Back = (uint)GLEnum.Back;
    public const uint Byte = (uint)GLEnum.Byte, UnsignedByte = (uint)GLEnum.UnsignedByte, UnsignedInt = (uint)GLEnum.UnsignedInt, Float = (uint)GLEnum.Float;
    public const uint ArrayBuffer = (uint)GLEnum.ArrayBuffer, ElementArrayBuffer = (uint)GLEnum.ElementArrayBuffer, StaticDraw = (uint)GLEnum.StaticDraw, DynamicDraw = (uint)GLEnum.DynamicDraw;
    public const uint FragmentShader = (uint)GLEnum.FragmentShader, VertexShader = (uint)GLEnum.VertexShader;
    public const uint Texture2D = (uint)GLEnum.Texture2D, Texture0 = (uint)GLEnum.Texture0;
    public const uint TextureMagFilter = (uint)GLEnum.TextureMagFilter, TextureMinFilter = (uint)GLEnum.TextureMinFilter, TextureWrapS = (uint)GLEnum.TextureWrapS, TextureWrapT = (uint)GLEnum.TextureWrapT;
    public const int Nearest = (int)GLEnum.Nearest, Linear = (int)GLEnum.Linear, LinearMipmapLinear = (int)GLEnum.LinearMipmapLinear, LinearMipmapNearest = (int)GLEnum.LinearMipmapNearest, ClampToEdge = (int)GLEnum.ClampToEdge, Repeat = (int)GLEnum.Repeat;
    public const uint Red = (uint)GLEnum.Red, Rgba = (uint)GLEnum.Rgba, R8 = (uint)GLEnum.R8, Rgba8 = (uint)GLEnum.Rgba8, Srgb8Alpha8 = (uint)GLEnum.Srgb8Alpha8, DepthComponent24 = (uint)GLEnum.DepthComponent24;
    public const uint Framebuffer = (uint)GLEnum.Framebuffer, ReadFramebuffer = (uint)GLEnum.ReadFramebuffer, DrawFramebuffer = (uint)GLEnum.DrawFramebuffer, Renderbuffer = (uint)GLEnum.Renderbuffer;
    public const uint ColorAttachment0 = (uint)GLEnum.ColorAttachment0, DepthAttachment = (uint)GLEnum.DepthAttachment, DepthStencilAttachment = (uint)GLEnum.DepthStencilAttachment, FramebufferComplete = (uint)GLEnum.FramebufferComplete;
    public const uint Depth24Stencil8 = (uint)GLEnum.Depth24Stencil8, DrawFramebufferBinding = (uint)GLEnum.DrawFramebufferBinding, Samples = (uint)GLEnum.Samples;
    public const uint PackAlignment = (uint)GLEnum.PackAlignment, UnpackAlignment = (uint)GLEnum.UnpackAlignment, MaxSamples = (uint)GLEnum.MaxSamples;
    public const uint Vendor = (uint)GLEnum.Vendor, RendererName = (uint)GLEnum.Renderer, Version = (uint)GLEnum.Version;

    private readonly GL _gl;

    /// <summary>Binds the context's functions through <paramref name="loader"/> (its GetProcAddress).</summary>
    public Gl(Func<string, nint> loader)
    {
        _gl = GL.GetApi(loader);
        // Fail here, with a message, when the context gives no GL at all, not at the first draw.
        string version;
        try
        {
            version = GetString(Version);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            throw new InvalidOperationException($"the OpenGL context gives no functions: {e.Message}", e);
        }
        if (string.IsNullOrEmpty(version))
        {
            throw new InvalidOperationException("the OpenGL context reports no version");
        }
        IsSoftwareRasterizer = IsSoftware(GetString(RendererName));
    }

    /// <summary>True when the context renders in software (Mesa llvmpipe or softpipe): every pixel is paid in CPU time.</summary>
    public bool IsSoftwareRasterizer { get; }

    /// <summary>True for the renderer strings of Mesa's CPU rasterisers.</summary>
    private static bool IsSoftware(string renderer) =>
        renderer.Contains("llvmpipe", StringComparison.OrdinalIgnoreCase) || renderer.Contains("softpipe", StringComparison.OrdinalIgnoreCase);

    public string GetString(uint name) => _gl.GetStringS((StringName)name) ?? "";
    public uint GetError() => (uint)_gl.GetError();
    public int GetInteger(uint name) => _gl.GetInteger((GetPName)name);
    public float GetFloat(uint name) => _gl.GetFloat((GetPName)name);
    public void Viewport(int x, int y, int w, int h) => _gl.Viewport(x, y, (uint)w, (uint)h);
    public void ClearColor(float r, float g, float b, float a) => _gl.ClearColor(r, g, b, a);
    public void Clear(uint mask) => _gl.Clear(mask);
    public void Enable(uint cap) => _gl.Enable((EnableCap)cap);
    public void Disable(uint cap) => _gl.Disable((EnableCap)cap);
    public void BlendFunc(uint s, uint d) => _gl.BlendFunc((BlendingFactor)s, (BlendingFactor)d);
    public void BlendFuncSeparate(uint s, uint d, uint sAlpha, uint dAlpha) =>
        _gl.BlendFuncSeparate((BlendingFactor)s, (BlendingFactor)d, (BlendingFactor)sAlpha, (BlendingFactor)dAlpha);
    public void DepthFunc(uint f) => _gl.DepthFunc((DepthFunction)f);
    public void DepthMask(bool on) => _gl.DepthMask(on);
    public void CullFaceMode(uint mode) => _gl.CullFace((TriangleFace)mode);
    public void PolygonOffset(float factor, float units) => _gl.PolygonOffset(factor, units);
    public void Finish() => _gl.Finish();

    public uint GenFramebuffer() => _gl.GenFramebuffer();
    public void DeleteFramebuffer(uint id) => _gl.DeleteFramebuffer(id);
    public void BindFramebuffer(uint target, uint id) => _gl.BindFramebuffer((FramebufferTarget)target, id);
    public void FramebufferRenderbuffer(uint target, uint attachment, uint rbTarget, uint rb) =>
        _gl.FramebufferRenderbuffer((FramebufferTarget)target, (FramebufferAttachment)attachment, (RenderbufferTarget)rbTarget, rb);
    public void FramebufferTexture2D(uint target, uint attachment, uint textureTarget, uint texture, int level) =>
        _gl.FramebufferTexture2D((FramebufferTarget)target, (FramebufferAttachment)attachment, (TextureTarget)textureTarget, texture, level);
    public uint CheckFramebufferStatus(uint target) => (uint)_gl.CheckFramebufferStatus((FramebufferTarget)target);
    public uint GenRenderbuffer() => _gl.GenRenderbuffer();
    public void DeleteRenderbuffer(uint id) => _gl.DeleteRenderbuffer(id);
    public void BindRenderbuffer(uint target, uint id) => _gl.BindRenderbuffer((RenderbufferTarget)target, id);
    public void RenderbufferStorage(uint target, uint format, int w, int h) =>
        _gl.RenderbufferStorage((RenderbufferTarget)target, (InternalFormat)format, (uint)w, (uint)h);
    public void RenderbufferStorageMultisample(uint target, int samples, uint format, int w, int h) =>
        _gl.RenderbufferStorageMultisample((RenderbufferTarget)target, (uint)samples, (InternalFormat)format, (uint)w, (uint)h);
    public void BlitFramebuffer(int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1, int dy1, uint mask, uint filter) =>
        _gl.BlitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, (ClearBufferMask)mask, (BlitFramebufferFilter)filter);
    public void ReadPixels(int x, int y, int w, int h, uint format, uint type, Span<byte> into) =>
        _gl.ReadPixels(x, y, (uint)w, (uint)h, (PixelFormat)format, (PixelType)type, into);
    public void PixelStore(uint name, int value) => _gl.PixelStore((PixelStoreParameter)name, value);

    public uint GenVertexArray() => _gl.GenVertexArray();
    public void DeleteVertexArray(uint id) => _gl.DeleteVertexArray(id);
    public void BindVertexArray(uint id) => _gl.BindVertexArray(id);
    public uint GenBuffer() => _gl.GenBuffer();
    public void DeleteBuffer(uint id) => _gl.DeleteBuffer(id);
    public void BindBuffer(uint target, uint id) => _gl.BindBuffer((BufferTargetARB)target, id);
    public void BufferData<T>(uint target, ReadOnlySpan<T> data, uint usage) where T : unmanaged =>
        _gl.BufferData((BufferTargetARB)target, data, (BufferUsageARB)usage);
    public void VertexAttribPointer(uint index, int size, uint type, bool normalized, int stride, int offset) =>
        _gl.VertexAttribPointer(index, size, (VertexAttribPointerType)type, normalized, (uint)stride, (void*)offset);
    public void EnableVertexAttribArray(uint index) => _gl.EnableVertexAttribArray(index);
    public void DrawArrays(uint mode, int first, int count) => _gl.DrawArrays((PrimitiveType)mode, first, (uint)count);
    public void DrawElements(uint mode, int count) => _gl.DrawElements((PrimitiveType)mode, (uint)count, DrawElementsType.UnsignedInt, null);

    public uint CompileShader(uint kind, string source)
    {
        uint shader = _gl.CreateShader((ShaderType)kind);
        _gl.ShaderSource(shader, source);
        _gl.CompileShader(shader);
        _gl.GetShader(shader, ShaderParameterName.CompileStatus, out int ok);
        if (ok == 0)
        {
            string log = _gl.GetShaderInfoLog(shader).TrimEnd('\0', '\n');
            _gl.DeleteShader(shader);
            throw new InvalidOperationException($"shader compilation failed: {log}");
        }
        return shader;
    }

    public uint LinkProgram(uint vertex, uint fragment, IReadOnlyList<string> attributes)
    {
        uint program = _gl.CreateProgram();
        _gl.AttachShader(program, vertex);
        _gl.AttachShader(program, fragment);
        for (int i = 0; i < attributes.Count; i++)
        {
            _gl.BindAttribLocation(program, (uint)i, attributes[i]);
        }
        _gl.LinkProgram(program);
        _gl.GetProgram(program, ProgramPropertyARB.LinkStatus, out int ok);
        if (ok == 0)
        {
            string log = _gl.GetProgramInfoLog(program).TrimEnd('\0', '\n');
            _gl.DeleteProgram(program);
            throw new InvalidOperationException($"shader link failed: {log}");
        }
        _gl.DeleteShader(vertex);
        _gl.DeleteShader(fragment);
        return program;
    }

    public void UseProgram(uint program) => _gl.UseProgram(program);
    public void DeleteProgram(uint program) => _gl.DeleteProgram(program);
    public int GetUniformLocation(uint program, string name) => _gl.GetUniformLocation(program, name);
    public void Uniform1(int location, int value) => _gl.Uniform1(location, value);
    public void Uniform1(int location, float value) => _gl.Uniform1(location, value);
    public void Uniform2(int location, float x, float y) => _gl.Uniform2(location, x, y);
    public void Uniform3(int location, float x, float y, float z) => _gl.Uniform3(location, x, y, z);
    public void Uniform4(int location, float x, float y, float z, float w) => _gl.Uniform4(location, x, y, z, w);
    public void Uniform4Array(int location, ReadOnlySpan<float> values) => _gl.Uniform4(location, (uint)(values.Length / 4), values);
    public void UniformMatrix4(int location, in System.Numerics.Matrix4x4 m)
    {
        // System.Numerics stores rows of a row-vector matrix: the same 16 floats are GL's
        // column-major matrix for column vectors, so no transpose.
        fixed (System.Numerics.Matrix4x4* p = &m)
        {
            _gl.UniformMatrix4(location, 1, false, (float*)p);
        }
    }

    public uint GenTexture() => _gl.GenTexture();
    public void DeleteTexture(uint id) => _gl.DeleteTexture(id);
    public void BindTexture(uint target, uint id) => _gl.BindTexture((TextureTarget)target, id);
    public void ActiveTexture(uint unit) => _gl.ActiveTexture((TextureUnit)unit);
    public void TexImage2D(uint target, int level, uint internalFormat, int w, int h, uint format, uint type, ReadOnlySpan<byte> data)
    {
        fixed (byte* p = data)
        {
            _gl.TexImage2D((TextureTarget)target, level, (InternalFormat)internalFormat, (uint)w, (uint)h, 0, (PixelFormat)format, (PixelType)type, p);
        }
    }
    public void TexParameter(uint target, uint name, int value) => _gl.TexParameter((TextureTarget)target, (TextureParameterName)name, value);
    public void TexParameter(uint target, uint name, float value) => _gl.TexParameter((TextureTarget)target, (TextureParameterName)name, value);
    public void GenerateMipmap(uint target) => _gl.GenerateMipmap((TextureTarget)target);
}
