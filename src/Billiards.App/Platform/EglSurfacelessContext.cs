using Billiards.App.Native;

namespace Billiards.App.Platform;

/// <summary>
/// A headless OpenGL 3.3 core context on Mesa's surfaceless EGL platform: no display server,
/// no window, no GPU needed (llvmpipe). The renderer draws into its own framebuffer object.
/// </summary>
internal sealed class EglSurfacelessContext : IGlContext
{
    private readonly nint _display;
    private nint _context;

    private EglSurfacelessContext(nint display, nint context, string description)
    {
        _display = display;
        _context = context;
        Description = description;
    }

    public string Description { get; }

    /// <summary>Creates the context, or returns null with the reason.</summary>
    public static EglSurfacelessContext? TryCreate(out string? error)
    {
        error = null;
        if (!OperatingSystem.IsLinux())
        {
            error = "EGL surfaceless is only used on Linux";
            return null;
        }
        try
        {
            nint display = Egl.GetPlatformDisplay(Egl.PlatformSurfacelessMesa);
            if (display == 0)
            {
                error = "EGL: no surfaceless platform display (EGL_MESA_platform_surfaceless missing)";
                return null;
            }
            if (!Egl.Initialize(display, out _, out _))
            {
                error = $"EGL: eglInitialize failed (0x{Egl.GetError():X})";
                return null;
            }
            string extensions = Egl.QueryString(display, Egl.Extensions);
            if (!extensions.Contains("EGL_KHR_surfaceless_context", StringComparison.Ordinal))
            {
                error = "EGL: EGL_KHR_surfaceless_context missing";
                return null;
            }
            if (!Egl.BindApi(Egl.OpenGlApi))
            {
                error = "EGL: desktop OpenGL API not available";
                return null;
            }
            nint config = Egl.ChooseConfig(display, [Egl.RenderableType, Egl.OpenGlBit, Egl.SurfaceType, 0, Egl.None]);
            nint context = Egl.CreateContext(display, config, 0,
                [Egl.ContextMajorVersion, 3, Egl.ContextMinorVersion, 3, Egl.ContextOpenGlProfileMask, Egl.CoreProfileBit, Egl.None]);
            if (context == 0)
            {
                error = $"EGL: cannot create an OpenGL 3.3 core context (0x{Egl.GetError():X})";
                return null;
            }
            var result = new EglSurfacelessContext(display, context, "EGL surfaceless");
            result.MakeCurrent();
            return result;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException or InvalidOperationException)
        {
            error = $"EGL: {e.Message}";
            return null;
        }
    }

    public void MakeCurrent()
    {
        if (!Egl.MakeCurrent(_display, 0, 0, _context))
        {
            throw new InvalidOperationException($"EGL: eglMakeCurrent failed (0x{Egl.GetError():X})");
        }
    }

    public void ReleaseCurrent() => Egl.MakeCurrent(_display, 0, 0, 0);

    public nint GetProcAddress(string name) => Egl.GetProcAddress(name);

    public void Dispose()
    {
        if (_context != 0)
        {
            Egl.MakeCurrent(_display, 0, 0, 0);
            Egl.DestroyContext(_display, _context);
            // The platform display is one per process and shared by every context on it:
            // eglTerminate would pull it from under the others, so it stays initialised.
            _context = 0;
        }
    }
}
