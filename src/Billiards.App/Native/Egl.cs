using System.Runtime.InteropServices;

namespace Billiards.App.Native;

/// <summary>
/// EGL 1.5 (Mesa's libEGL): just enough for a headless OpenGL 3.3 core context on the
/// surfaceless platform (EGL_MESA_platform_surfaceless), which needs neither a display server
/// nor a GPU. Linux only.
/// </summary>
internal static unsafe class Egl
{
    public const int None = 0x3038, Extensions = 0x3055, VendorName = 0x3053;
    public const int AlphaSize = 0x3021, BlueSize = 0x3022, GreenSize = 0x3023, RedSize = 0x3024, DepthSize = 0x3025;
    public const int SurfaceType = 0x3033, RenderableType = 0x3040, OpenGlBit = 0x0008, OpenGlApi = 0x30A2;
    public const int ContextMajorVersion = 0x3098, ContextMinorVersion = 0x30FB, ContextOpenGlProfileMask = 0x30FD, CoreProfileBit = 0x1;
    public const int PlatformSurfacelessMesa = 0x31DD;

    private static readonly Lazy<nint> s_library = new(() => NativeLoader.Load("EGL", "libEGL.so.1", "libEGL.so"));

    private static nint F(string name) => NativeLoader.Export(s_library.Value, name);

    public static nint GetProcAddress(string name)
    {
        byte* n = (byte*)Marshal.StringToCoTaskMemUTF8(name);
        try
        {
            return ((delegate* unmanaged<byte*, nint>)F("eglGetProcAddress"))(n);
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)n);
        }
    }

    public static string QueryString(nint display, int name) =>
        Marshal.PtrToStringUTF8(((delegate* unmanaged<nint, int, nint>)F("eglQueryString"))(display, name)) ?? "";

    /// <summary>eglGetPlatformDisplayEXT for the given platform, or 0.</summary>
    public static nint GetPlatformDisplay(int platform)
    {
        nint f = GetProcAddress("eglGetPlatformDisplayEXT");
        return f == 0 ? 0 : ((delegate* unmanaged<int, nint, int*, nint>)f)(platform, 0, null);
    }

    public static bool Initialize(nint display, out int major, out int minor)
    {
        int ma, mi;
        bool ok = ((delegate* unmanaged<nint, int*, int*, uint>)F("eglInitialize"))(display, &ma, &mi) != 0;
        (major, minor) = (ma, mi);
        return ok;
    }

    public static bool Terminate(nint display) => ((delegate* unmanaged<nint, uint>)F("eglTerminate"))(display) != 0;
    public static bool BindApi(int api) => ((delegate* unmanaged<int, uint>)F("eglBindAPI"))(api) != 0;
    public static int GetError() => ((delegate* unmanaged<int>)F("eglGetError"))();

    /// <summary>The first config matching the attribute list (pairs, closed by <see cref="None"/>), or 0.</summary>
    public static nint ChooseConfig(nint display, ReadOnlySpan<int> attributes)
    {
        nint config = 0;
        int count = 0;
        fixed (int* a = attributes)
        {
            if (((delegate* unmanaged<nint, int*, nint*, int, int*, uint>)F("eglChooseConfig"))(display, a, &config, 1, &count) == 0)
            {
                return 0;
            }
        }
        return count > 0 ? config : 0;
    }

    public static nint CreateContext(nint display, nint config, nint share, ReadOnlySpan<int> attributes)
    {
        fixed (int* a = attributes)
        {
            return ((delegate* unmanaged<nint, nint, nint, int*, nint>)F("eglCreateContext"))(display, config, share, a);
        }
    }

    public static bool DestroyContext(nint display, nint context) => ((delegate* unmanaged<nint, nint, uint>)F("eglDestroyContext"))(display, context) != 0;

    public static bool MakeCurrent(nint display, nint draw, nint read, nint context) =>
        ((delegate* unmanaged<nint, nint, nint, nint, uint>)F("eglMakeCurrent"))(display, draw, read, context) != 0;
}
