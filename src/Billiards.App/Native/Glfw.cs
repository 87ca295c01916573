using System.Runtime.InteropServices;

namespace Billiards.App.Native;

/// <summary>GLFW 3 (windows, contexts, input): the functions the App uses, bound at first use.</summary>
internal static unsafe class Glfw
{
    public const int True = 1, False = 0;
    public const int Focused = 0x20001, Resizable = 0x20003, Visible = 0x20004;
    public const int Samples = 0x2100D, ContextVersionMajor = 0x22002, ContextVersionMinor = 0x22003;
    public const int OpenGlForwardCompat = 0x22006, OpenGlProfile = 0x22008, OpenGlCoreProfile = 0x32001;
    public const int CursorMode = 0x33001, CursorNormal = 0x34001, CursorHidden = 0x34002, CursorDisabled = 0x34003, RawMouseMotion = 0x33005;
    public const int Release = 0, Press = 1, Repeat = 2;

    private static readonly Lazy<nint> s_library = new(() => NativeLoader.Load("GLFW 3",
        OperatingSystem.IsWindows() ? ["glfw3.dll", "glfw.dll"] :
        OperatingSystem.IsMacOS() ? ["libglfw.3.dylib", "libglfw.dylib"] :
        ["libglfw.so.3", "libglfw.so"]));

    private static nint F(string name) => NativeLoader.Export(s_library.Value, name);

    /// <summary>True when the GLFW library can be loaded.</summary>
    public static bool IsAvailable
    {
        get
        {
            try
            {
                return s_library.Value != 0;
            }
            catch (DllNotFoundException)
            {
                return false;
            }
        }
    }

    public static bool Init() => ((delegate* unmanaged<int>)F("glfwInit"))() == True;
    public static void Terminate() => ((delegate* unmanaged<void>)F("glfwTerminate"))();
    public static void DefaultWindowHints() => ((delegate* unmanaged<void>)F("glfwDefaultWindowHints"))();
    public static void WindowHint(int hint, int value) => ((delegate* unmanaged<int, int, void>)F("glfwWindowHint"))(hint, value);

    public static nint CreateWindow(int width, int height, string title, nint monitor, nint share)
    {
        byte* t = (byte*)Marshal.StringToCoTaskMemUTF8(title);
        try
        {
            return ((delegate* unmanaged<int, int, byte*, nint, nint, nint>)F("glfwCreateWindow"))(width, height, t, monitor, share);
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)t);
        }
    }

    public static void DestroyWindow(nint window) => ((delegate* unmanaged<nint, void>)F("glfwDestroyWindow"))(window);
    public static void MakeContextCurrent(nint window) => ((delegate* unmanaged<nint, void>)F("glfwMakeContextCurrent"))(window);

    public static nint GetProcAddress(string name)
    {
        byte* n = (byte*)Marshal.StringToCoTaskMemUTF8(name);
        try
        {
            return ((delegate* unmanaged<byte*, nint>)F("glfwGetProcAddress"))(n);
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)n);
        }
    }

    public static void SwapBuffers(nint window) => ((delegate* unmanaged<nint, void>)F("glfwSwapBuffers"))(window);
    public static void SwapInterval(int interval) => ((delegate* unmanaged<int, void>)F("glfwSwapInterval"))(interval);
    public static void PollEvents() => ((delegate* unmanaged<void>)F("glfwPollEvents"))();
    public static bool WindowShouldClose(nint window) => ((delegate* unmanaged<nint, int>)F("glfwWindowShouldClose"))(window) != 0;
    public static void SetWindowShouldClose(nint window, bool value) => ((delegate* unmanaged<nint, int, void>)F("glfwSetWindowShouldClose"))(window, value ? True : False);
    public static double GetTime() => ((delegate* unmanaged<double>)F("glfwGetTime"))();

    public static (int Width, int Height) GetFramebufferSize(nint window)
    {
        int w, h;
        ((delegate* unmanaged<nint, int*, int*, void>)F("glfwGetFramebufferSize"))(window, &w, &h);
        return (w, h);
    }

    public static (int X, int Y) GetWindowPos(nint window)
    {
        int x, y;
        ((delegate* unmanaged<nint, int*, int*, void>)F("glfwGetWindowPos"))(window, &x, &y);
        return (x, y);
    }

    public static (int Width, int Height) GetWindowSize(nint window)
    {
        int w, h;
        ((delegate* unmanaged<nint, int*, int*, void>)F("glfwGetWindowSize"))(window, &w, &h);
        return (w, h);
    }

    public static int GetInputMode(nint window, int mode) => ((delegate* unmanaged<nint, int, int>)F("glfwGetInputMode"))(window, mode);

    public static void SetInputMode(nint window, int mode, int value) => ((delegate* unmanaged<nint, int, int, void>)F("glfwSetInputMode"))(window, mode, value);
    public static bool RawMouseMotionSupported() => ((delegate* unmanaged<int>)F("glfwRawMouseMotionSupported"))() != 0;
    public static nint GetPrimaryMonitor() => ((delegate* unmanaged<nint>)F("glfwGetPrimaryMonitor"))();
    public static nint GetWindowMonitor(nint window) => ((delegate* unmanaged<nint, nint>)F("glfwGetWindowMonitor"))(window);

    /// <summary>The monitor's current mode: width, height and refresh rate.</summary>
    public static (int Width, int Height, int RefreshRate) GetVideoMode(nint monitor)
    {
        // GLFWvidmode: width, height, redBits, greenBits, blueBits, refreshRate (six ints).
        int* mode = ((delegate* unmanaged<nint, int*>)F("glfwGetVideoMode"))(monitor);
        return mode == null ? (1280, 720, 60) : (mode[0], mode[1], mode[5]);
    }

    public static void SetWindowMonitor(nint window, nint monitor, int x, int y, int w, int h, int refresh) =>
        ((delegate* unmanaged<nint, nint, int, int, int, int, int, void>)F("glfwSetWindowMonitor"))(window, monitor, x, y, w, h, refresh);

    public static void SetWindowTitle(nint window, string title)
    {
        byte* t = (byte*)Marshal.StringToCoTaskMemUTF8(title);
        try
        {
            ((delegate* unmanaged<nint, byte*, void>)F("glfwSetWindowTitle"))(window, t);
        }
        finally
        {
            Marshal.FreeCoTaskMem((nint)t);
        }
    }

    /// <summary>The last error's description, or null.</summary>
    public static string? GetError()
    {
        byte* description = null;
        int code = ((delegate* unmanaged<byte**, int>)F("glfwGetError"))(&description);
        return code == 0 ? null : Marshal.PtrToStringUTF8((nint)description) ?? $"GLFW error 0x{code:X}";
    }

    public static void SetKeyCallback(nint window, delegate* unmanaged<nint, int, int, int, int, void> callback) =>
        ((delegate* unmanaged<nint, delegate* unmanaged<nint, int, int, int, int, void>, nint>)F("glfwSetKeyCallback"))(window, callback);

    public static void SetCursorPosCallback(nint window, delegate* unmanaged<nint, double, double, void> callback) =>
        ((delegate* unmanaged<nint, delegate* unmanaged<nint, double, double, void>, nint>)F("glfwSetCursorPosCallback"))(window, callback);

    public static void SetMouseButtonCallback(nint window, delegate* unmanaged<nint, int, int, int, void> callback) =>
        ((delegate* unmanaged<nint, delegate* unmanaged<nint, int, int, int, void>, nint>)F("glfwSetMouseButtonCallback"))(window, callback);

    public static void SetScrollCallback(nint window, delegate* unmanaged<nint, double, double, void> callback) =>
        ((delegate* unmanaged<nint, delegate* unmanaged<nint, double, double, void>, nint>)F("glfwSetScrollCallback"))(window, callback);

    public static void SetFramebufferSizeCallback(nint window, delegate* unmanaged<nint, int, int, void> callback) =>
        ((delegate* unmanaged<nint, delegate* unmanaged<nint, int, int, void>, nint>)F("glfwSetFramebufferSizeCallback"))(window, callback);
}
