using System.Runtime.InteropServices;
using System.Text;

namespace Billiards.App.Native;

/// <summary>
/// The OpenGL 3.3 core functions the renderer uses, loaded by name from whatever context is
/// current (GLFW or EGL give the loader). Only what is called is bound: a missing function
/// fails at load time with its name, not later with an access violation.
/// </summary>
internal sealed unsafe class Gl
{
    public const uint DepthBufferBit = 0x100, ColorBufferBit = 0x4000;
    public const uint Lines = 0x1, Triangles = 0x4;
    public const uint DepthTest = 0x0B71, Blend = 0x0BE2, CullFace = 0x0B44, Multisample = 0x809D, PolygonOffsetFill = 0x8037;
    public const uint Zero = 0, One = 1, SrcColor = 0x0300;
    public const uint SrcAlpha = 0x0302, OneMinusSrcAlpha = 0x0303, Less = 0x0201, LessEqual = 0x0203, Back = 0x0405;
    public const uint Byte = 0x1400, UnsignedByte = 0x1401, UnsignedInt = 0x1405, Float = 0x1406;
    public const uint ArrayBuffer = 0x8892, ElementArrayBuffer = 0x8893, StaticDraw = 0x88E4, DynamicDraw = 0x88E8;
    public const uint FragmentShader = 0x8B30, VertexShader = 0x8B31, CompileStatus = 0x8B81, LinkStatus = 0x8B82, InfoLogLength = 0x8B84;
    public const uint Texture2D = 0x0DE1, Texture0 = 0x84C0;
    public const uint TextureMagFilter = 0x2800, TextureMinFilter = 0x2801, TextureWrapS = 0x2802, TextureWrapT = 0x2803;
    public const int Nearest = 0x2600, Linear = 0x2601, LinearMipmapLinear = 0x2703, ClampToEdge = 0x812F, Repeat = 0x2901;
    public const uint Red = 0x1903, Rgba = 0x1908, R8 = 0x8229, Rgba8 = 0x8058, Srgb8Alpha8 = 0x8C43, DepthComponent24 = 0x81A6;
    public const uint Framebuffer = 0x8D40, ReadFramebuffer = 0x8CA8, DrawFramebuffer = 0x8CA9, Renderbuffer = 0x8D41;
    public const uint ColorAttachment0 = 0x8CE0, DepthAttachment = 0x8D00, DepthStencilAttachment = 0x821A, FramebufferComplete = 0x8CD5;
    public const uint Depth24Stencil8 = 0x88F0, DrawFramebufferBinding = 0x8CA6, Samples = 0x80A9;
    public const uint PackAlignment = 0x0D05, UnpackAlignment = 0x0CF5, MaxSamples = 0x8D57;
    public const uint Vendor = 0x1F00, RendererName = 0x1F01, Version = 0x1F02;

    public Gl(Func<string, nint> loader)
    {
        nint Get(string name)
        {
            nint p = loader(name);
            return p != 0 ? p : throw new InvalidOperationException($"OpenGL function {name} is not available");
        }
        _getString = (delegate* unmanaged<uint, byte*>)Get("glGetString");
        _getError = (delegate* unmanaged<uint>)Get("glGetError");
        _getIntegerv = (delegate* unmanaged<uint, int*, void>)Get("glGetIntegerv");
        _viewport = (delegate* unmanaged<int, int, int, int, void>)Get("glViewport");
        _clearColor = (delegate* unmanaged<float, float, float, float, void>)Get("glClearColor");
        _clear = (delegate* unmanaged<uint, void>)Get("glClear");
        _enable = (delegate* unmanaged<uint, void>)Get("glEnable");
        _disable = (delegate* unmanaged<uint, void>)Get("glDisable");
        _blendFunc = (delegate* unmanaged<uint, uint, void>)Get("glBlendFunc");
        _framebufferTexture2D = (delegate* unmanaged<uint, uint, uint, uint, int, void>)Get("glFramebufferTexture2D");
        _blendFuncSeparate = (delegate* unmanaged<uint, uint, uint, uint, void>)Get("glBlendFuncSeparate");
        _depthFunc = (delegate* unmanaged<uint, void>)Get("glDepthFunc");
        _depthMask = (delegate* unmanaged<byte, void>)Get("glDepthMask");
        _cullFace = (delegate* unmanaged<uint, void>)Get("glCullFace");
        _polygonOffset = (delegate* unmanaged<float, float, void>)Get("glPolygonOffset");
        _finish = (delegate* unmanaged<void>)Get("glFinish");
        _genFramebuffers = (delegate* unmanaged<int, uint*, void>)Get("glGenFramebuffers");
        _deleteFramebuffers = (delegate* unmanaged<int, uint*, void>)Get("glDeleteFramebuffers");
        _bindFramebuffer = (delegate* unmanaged<uint, uint, void>)Get("glBindFramebuffer");
        _framebufferRenderbuffer = (delegate* unmanaged<uint, uint, uint, uint, void>)Get("glFramebufferRenderbuffer");
        _checkFramebufferStatus = (delegate* unmanaged<uint, uint>)Get("glCheckFramebufferStatus");
        _genRenderbuffers = (delegate* unmanaged<int, uint*, void>)Get("glGenRenderbuffers");
        _deleteRenderbuffers = (delegate* unmanaged<int, uint*, void>)Get("glDeleteRenderbuffers");
        _bindRenderbuffer = (delegate* unmanaged<uint, uint, void>)Get("glBindRenderbuffer");
        _renderbufferStorage = (delegate* unmanaged<uint, uint, int, int, void>)Get("glRenderbufferStorage");
        _renderbufferStorageMultisample = (delegate* unmanaged<uint, int, uint, int, int, void>)Get("glRenderbufferStorageMultisample");
        _blitFramebuffer = (delegate* unmanaged<int, int, int, int, int, int, int, int, uint, uint, void>)Get("glBlitFramebuffer");
        _readPixels = (delegate* unmanaged<int, int, int, int, uint, uint, void*, void>)Get("glReadPixels");
        _pixelStorei = (delegate* unmanaged<uint, int, void>)Get("glPixelStorei");
        _genVertexArrays = (delegate* unmanaged<int, uint*, void>)Get("glGenVertexArrays");
        _deleteVertexArrays = (delegate* unmanaged<int, uint*, void>)Get("glDeleteVertexArrays");
        _bindVertexArray = (delegate* unmanaged<uint, void>)Get("glBindVertexArray");
        _genBuffers = (delegate* unmanaged<int, uint*, void>)Get("glGenBuffers");
        _deleteBuffers = (delegate* unmanaged<int, uint*, void>)Get("glDeleteBuffers");
        _bindBuffer = (delegate* unmanaged<uint, uint, void>)Get("glBindBuffer");
        _bufferData = (delegate* unmanaged<uint, nint, void*, uint, void>)Get("glBufferData");
        _vertexAttribPointer = (delegate* unmanaged<uint, int, uint, byte, int, nint, void>)Get("glVertexAttribPointer");
        _enableVertexAttribArray = (delegate* unmanaged<uint, void>)Get("glEnableVertexAttribArray");
        _drawArrays = (delegate* unmanaged<uint, int, int, void>)Get("glDrawArrays");
        _drawElements = (delegate* unmanaged<uint, int, uint, nint, void>)Get("glDrawElements");
        _createShader = (delegate* unmanaged<uint, uint>)Get("glCreateShader");
        _shaderSource = (delegate* unmanaged<uint, int, byte**, int*, void>)Get("glShaderSource");
        _compileShader = (delegate* unmanaged<uint, void>)Get("glCompileShader");
        _getShaderiv = (delegate* unmanaged<uint, uint, int*, void>)Get("glGetShaderiv");
        _getShaderInfoLog = (delegate* unmanaged<uint, int, int*, byte*, void>)Get("glGetShaderInfoLog");
        _deleteShader = (delegate* unmanaged<uint, void>)Get("glDeleteShader");
        _createProgram = (delegate* unmanaged<uint>)Get("glCreateProgram");
        _attachShader = (delegate* unmanaged<uint, uint, void>)Get("glAttachShader");
        _bindAttribLocation = (delegate* unmanaged<uint, uint, byte*, void>)Get("glBindAttribLocation");
        _linkProgram = (delegate* unmanaged<uint, void>)Get("glLinkProgram");
        _getProgramiv = (delegate* unmanaged<uint, uint, int*, void>)Get("glGetProgramiv");
        _getProgramInfoLog = (delegate* unmanaged<uint, int, int*, byte*, void>)Get("glGetProgramInfoLog");
        _useProgram = (delegate* unmanaged<uint, void>)Get("glUseProgram");
        _deleteProgram = (delegate* unmanaged<uint, void>)Get("glDeleteProgram");
        _getUniformLocation = (delegate* unmanaged<uint, byte*, int>)Get("glGetUniformLocation");
        _uniform1i = (delegate* unmanaged<int, int, void>)Get("glUniform1i");
        _uniform1f = (delegate* unmanaged<int, float, void>)Get("glUniform1f");
        _uniform2f = (delegate* unmanaged<int, float, float, void>)Get("glUniform2f");
        _uniform3f = (delegate* unmanaged<int, float, float, float, void>)Get("glUniform3f");
        _uniform4f = (delegate* unmanaged<int, float, float, float, float, void>)Get("glUniform4f");
        _uniform4fv = (delegate* unmanaged<int, int, float*, void>)Get("glUniform4fv");
        _uniformMatrix4fv = (delegate* unmanaged<int, int, byte, float*, void>)Get("glUniformMatrix4fv");
        _genTextures = (delegate* unmanaged<int, uint*, void>)Get("glGenTextures");
        _deleteTextures = (delegate* unmanaged<int, uint*, void>)Get("glDeleteTextures");
        _bindTexture = (delegate* unmanaged<uint, uint, void>)Get("glBindTexture");
        _activeTexture = (delegate* unmanaged<uint, void>)Get("glActiveTexture");
        _texImage2D = (delegate* unmanaged<uint, int, int, int, int, int, uint, uint, void*, void>)Get("glTexImage2D");
        _texParameteri = (delegate* unmanaged<uint, uint, int, void>)Get("glTexParameteri");
        _generateMipmap = (delegate* unmanaged<uint, void>)Get("glGenerateMipmap");
    }

    private readonly delegate* unmanaged<uint, byte*> _getString;
    private readonly delegate* unmanaged<uint> _getError;
    private readonly delegate* unmanaged<uint, int*, void> _getIntegerv;
    private readonly delegate* unmanaged<int, int, int, int, void> _viewport;
    private readonly delegate* unmanaged<float, float, float, float, void> _clearColor;
    private readonly delegate* unmanaged<uint, void> _clear, _enable, _disable, _depthFunc, _cullFace;
    private readonly delegate* unmanaged<uint, uint, void> _blendFunc;
    private readonly delegate* unmanaged<uint, uint, uint, uint, void> _blendFuncSeparate;
    private readonly delegate* unmanaged<uint, uint, uint, uint, int, void> _framebufferTexture2D;
    private readonly delegate* unmanaged<byte, void> _depthMask;
    private readonly delegate* unmanaged<float, float, void> _polygonOffset;
    private readonly delegate* unmanaged<void> _finish;
    private readonly delegate* unmanaged<int, uint*, void> _genFramebuffers, _deleteFramebuffers, _genRenderbuffers, _deleteRenderbuffers;
    private readonly delegate* unmanaged<int, uint*, void> _genVertexArrays, _deleteVertexArrays, _genBuffers, _deleteBuffers, _genTextures, _deleteTextures;
    private readonly delegate* unmanaged<uint, uint, void> _bindFramebuffer, _bindRenderbuffer, _bindBuffer, _bindTexture, _attachShader;
    private readonly delegate* unmanaged<uint, uint, uint, uint, void> _framebufferRenderbuffer;
    private readonly delegate* unmanaged<uint, uint> _checkFramebufferStatus, _createShader;
    private readonly delegate* unmanaged<uint, uint, int, int, void> _renderbufferStorage;
    private readonly delegate* unmanaged<uint, int, uint, int, int, void> _renderbufferStorageMultisample;
    private readonly delegate* unmanaged<int, int, int, int, int, int, int, int, uint, uint, void> _blitFramebuffer;
    private readonly delegate* unmanaged<int, int, int, int, uint, uint, void*, void> _readPixels;
    private readonly delegate* unmanaged<uint, int, void> _pixelStorei;
    private readonly delegate* unmanaged<uint, void> _bindVertexArray, _enableVertexAttribArray, _compileShader, _deleteShader;
    private readonly delegate* unmanaged<uint, void> _linkProgram, _useProgram, _deleteProgram, _activeTexture, _generateMipmap;
    private readonly delegate* unmanaged<uint, nint, void*, uint, void> _bufferData;
    private readonly delegate* unmanaged<uint, int, uint, byte, int, nint, void> _vertexAttribPointer;
    private readonly delegate* unmanaged<uint, int, int, void> _drawArrays;
    private readonly delegate* unmanaged<uint, int, uint, nint, void> _drawElements;
    private readonly delegate* unmanaged<uint, int, byte**, int*, void> _shaderSource;
    private readonly delegate* unmanaged<uint, uint, int*, void> _getShaderiv, _getProgramiv;
    private readonly delegate* unmanaged<uint, int, int*, byte*, void> _getShaderInfoLog, _getProgramInfoLog;
    private readonly delegate* unmanaged<uint> _createProgram;
    private readonly delegate* unmanaged<uint, uint, byte*, void> _bindAttribLocation;
    private readonly delegate* unmanaged<uint, byte*, int> _getUniformLocation;
    private readonly delegate* unmanaged<int, int, void> _uniform1i;
    private readonly delegate* unmanaged<int, float, void> _uniform1f;
    private readonly delegate* unmanaged<int, float, float, void> _uniform2f;
    private readonly delegate* unmanaged<int, float, float, float, void> _uniform3f;
    private readonly delegate* unmanaged<int, float, float, float, float, void> _uniform4f;
    private readonly delegate* unmanaged<int, int, float*, void> _uniform4fv;
    private readonly delegate* unmanaged<int, int, byte, float*, void> _uniformMatrix4fv;
    private readonly delegate* unmanaged<uint, int, int, int, int, int, uint, uint, void*, void> _texImage2D;
    private readonly delegate* unmanaged<uint, uint, int, void> _texParameteri;

    public string GetString(uint name) => Marshal.PtrToStringUTF8((nint)_getString(name)) ?? "";
    public uint GetError() => _getError();
    public int GetInteger(uint name)
    {
        int v;
        _getIntegerv(name, &v);
        return v;
    }
    public void Viewport(int x, int y, int w, int h) => _viewport(x, y, w, h);
    public void ClearColor(float r, float g, float b, float a) => _clearColor(r, g, b, a);
    public void Clear(uint mask) => _clear(mask);
    public void Enable(uint cap) => _enable(cap);
    public void Disable(uint cap) => _disable(cap);
    public void BlendFunc(uint s, uint d) => _blendFunc(s, d);
    public void BlendFuncSeparate(uint s, uint d, uint sAlpha, uint dAlpha) => _blendFuncSeparate(s, d, sAlpha, dAlpha);
    public void DepthFunc(uint f) => _depthFunc(f);
    public void DepthMask(bool on) => _depthMask(on ? (byte)1 : (byte)0);
    public void CullFaceMode(uint mode) => _cullFace(mode);
    public void PolygonOffset(float factor, float units) => _polygonOffset(factor, units);
    public void Finish() => _finish();

    public uint GenFramebuffer() { uint id; _genFramebuffers(1, &id); return id; }
    public void DeleteFramebuffer(uint id) => _deleteFramebuffers(1, &id);
    public void BindFramebuffer(uint target, uint id) => _bindFramebuffer(target, id);
    public void FramebufferRenderbuffer(uint target, uint attachment, uint rbTarget, uint rb) => _framebufferRenderbuffer(target, attachment, rbTarget, rb);
    public void FramebufferTexture2D(uint target, uint attachment, uint textureTarget, uint texture, int level) => _framebufferTexture2D(target, attachment, textureTarget, texture, level);
    public uint CheckFramebufferStatus(uint target) => _checkFramebufferStatus(target);
    public uint GenRenderbuffer() { uint id; _genRenderbuffers(1, &id); return id; }
    public void DeleteRenderbuffer(uint id) => _deleteRenderbuffers(1, &id);
    public void BindRenderbuffer(uint target, uint id) => _bindRenderbuffer(target, id);
    public void RenderbufferStorage(uint target, uint format, int w, int h) => _renderbufferStorage(target, format, w, h);
    public void RenderbufferStorageMultisample(uint target, int samples, uint format, int w, int h) => _renderbufferStorageMultisample(target, samples, format, w, h);
    public void BlitFramebuffer(int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1, int dy1, uint mask, uint filter) =>
        _blitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
    public void ReadPixels(int x, int y, int w, int h, uint format, uint type, Span<byte> into)
    {
        fixed (byte* p = into)
        {
            _readPixels(x, y, w, h, format, type, p);
        }
    }
    public void PixelStore(uint name, int value) => _pixelStorei(name, value);

    public uint GenVertexArray() { uint id; _genVertexArrays(1, &id); return id; }
    public void DeleteVertexArray(uint id) => _deleteVertexArrays(1, &id);
    public void BindVertexArray(uint id) => _bindVertexArray(id);
    public uint GenBuffer() { uint id; _genBuffers(1, &id); return id; }
    public void DeleteBuffer(uint id) => _deleteBuffers(1, &id);
    public void BindBuffer(uint target, uint id) => _bindBuffer(target, id);
    public void BufferData<T>(uint target, ReadOnlySpan<T> data, uint usage) where T : unmanaged
    {
        fixed (T* p = data)
        {
            _bufferData(target, data.Length * sizeof(T), p, usage);
        }
    }
    public void VertexAttribPointer(uint index, int size, uint type, bool normalized, int stride, int offset) =>
        _vertexAttribPointer(index, size, type, normalized ? (byte)1 : (byte)0, stride, offset);
    public void EnableVertexAttribArray(uint index) => _enableVertexAttribArray(index);
    public void DrawArrays(uint mode, int first, int count) => _drawArrays(mode, first, count);
    public void DrawElements(uint mode, int count) => _drawElements(mode, count, UnsignedInt, 0);

    public uint CompileShader(uint kind, string source)
    {
        uint shader = _createShader(kind);
        byte[] bytes = Encoding.UTF8.GetBytes(source);
        fixed (byte* p = bytes)
        {
            byte* ptr = p;
            int length = bytes.Length;
            _shaderSource(shader, 1, &ptr, &length);
        }
        _compileShader(shader);
        int ok;
        _getShaderiv(shader, CompileStatus, &ok);
        if (ok == 0)
        {
            string log = InfoLog(shader, _getShaderiv, _getShaderInfoLog);
            _deleteShader(shader);
            throw new InvalidOperationException($"shader compilation failed: {log}");
        }
        return shader;
    }

    public uint LinkProgram(uint vertex, uint fragment, IReadOnlyList<string> attributes)
    {
        uint program = _createProgram();
        _attachShader(program, vertex);
        _attachShader(program, fragment);
        for (int i = 0; i < attributes.Count; i++)
        {
            byte[] name = Encoding.UTF8.GetBytes(attributes[i] + "\0");
            fixed (byte* n = name)
            {
                _bindAttribLocation(program, (uint)i, n);
            }
        }
        _linkProgram(program);
        int ok;
        _getProgramiv(program, LinkStatus, &ok);
        if (ok == 0)
        {
            string log = InfoLog(program, _getProgramiv, _getProgramInfoLog);
            _deleteProgram(program);
            throw new InvalidOperationException($"shader link failed: {log}");
        }
        _deleteShader(vertex);
        _deleteShader(fragment);
        return program;
    }

    private static string InfoLog(uint id, delegate* unmanaged<uint, uint, int*, void> getiv, delegate* unmanaged<uint, int, int*, byte*, void> getLog)
    {
        int length;
        getiv(id, InfoLogLength, &length);
        byte[] log = new byte[Math.Max(1, length)];
        fixed (byte* l = log)
        {
            getLog(id, log.Length, null, l);
        }
        return Encoding.UTF8.GetString(log).TrimEnd('\0', '\n');
    }

    public void UseProgram(uint program) => _useProgram(program);
    public void DeleteProgram(uint program) => _deleteProgram(program);
    public int GetUniformLocation(uint program, string name)
    {
        byte[] bytes = Encoding.UTF8.GetBytes(name + "\0");
        fixed (byte* p = bytes)
        {
            return _getUniformLocation(program, p);
        }
    }
    public void Uniform1(int location, int value) => _uniform1i(location, value);
    public void Uniform1(int location, float value) => _uniform1f(location, value);
    public void Uniform2(int location, float x, float y) => _uniform2f(location, x, y);
    public void Uniform3(int location, float x, float y, float z) => _uniform3f(location, x, y, z);
    public void Uniform4(int location, float x, float y, float z, float w) => _uniform4f(location, x, y, z, w);
    public void Uniform4Array(int location, ReadOnlySpan<float> values)
    {
        fixed (float* p = values)
        {
            _uniform4fv(location, values.Length / 4, p);
        }
    }
    public void UniformMatrix4(int location, in System.Numerics.Matrix4x4 m)
    {
        // System.Numerics stores rows of a row-vector matrix: the same 16 floats are GL's
        // column-major matrix for column vectors, so no transpose.
        fixed (System.Numerics.Matrix4x4* p = &m)
        {
            _uniformMatrix4fv(location, 1, 0, (float*)p);
        }
    }

    public uint GenTexture() { uint id; _genTextures(1, &id); return id; }
    public void DeleteTexture(uint id) => _deleteTextures(1, &id);
    public void BindTexture(uint target, uint id) => _bindTexture(target, id);
    public void ActiveTexture(uint unit) => _activeTexture(unit);
    public void TexImage2D(uint target, int level, uint internalFormat, int w, int h, uint format, uint type, ReadOnlySpan<byte> data)
    {
        fixed (byte* p = data)
        {
            _texImage2D(target, level, (int)internalFormat, w, h, 0, format, type, p);
        }
    }
    public void TexParameter(uint target, uint name, int value) => _texParameteri(target, name, value);
    public void GenerateMipmap(uint target) => _generateMipmap(target);
}
