using Billiards.App.Native;

namespace Billiards.App.Platform;

/// <summary>An OpenGL 3.3 core context of an invisible GLFW window (Windows, macOS, Linux with a display or Xvfb).</summary>
internal sealed class HiddenGlfwContext : IGlContext
{
    private nint _window;

    private HiddenGlfwContext(nint window) => _window = window;

    public string Description => "hidden GLFW window";

    /// <summary>Creates the context, or returns null with the reason.</summary>
    public static HiddenGlfwContext? TryCreate(out string? error)
    {
        error = null;
        try
        {
            if (!GlfwRuntime.Acquire(out error))
            {
                return null;
            }
            Glfw.DefaultWindowHints();
            Glfw.WindowHint(Glfw.Visible, Glfw.False);
            GlfwRuntime.CoreProfileHints();
            nint window = Glfw.CreateWindow(64, 64, "billiards offscreen", 0, 0);
            if (window == 0)
            {
                error = $"GLFW: cannot create a hidden OpenGL 3.3 window ({Glfw.GetError() ?? "no reason given"})";
                return null;
            }
            var context = new HiddenGlfwContext(window);
            context.MakeCurrent();
            return context;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            error = $"GLFW: {e.Message}";
            return null;
        }
    }

    public void MakeCurrent() => Glfw.MakeContextCurrent(_window);

    public void ReleaseCurrent() => Glfw.MakeContextCurrent(0);

    public nint GetProcAddress(string name) => Glfw.GetProcAddress(name);

    public void Dispose()
    {
        if (_window != 0)
        {
            Glfw.MakeContextCurrent(0);
            Glfw.DestroyWindow(_window);
            _window = 0;
        }
    }
}

/// <summary>
/// glfwInit, once for the process: the game window and the hidden contexts share it, and it is
/// never terminated (terminating and initialising GLFW again at once sometimes failed to reopen
/// the X display; the process's exit frees what it holds).
/// </summary>
internal static class GlfwRuntime
{
    private static readonly Lock s_lock = new();
    private static bool s_initialised;

    public static bool Acquire(out string? error)
    {
        lock (s_lock)
        {
            error = null;
            if (!s_initialised && !Glfw.Init())
            {
                error = $"GLFW: glfwInit failed ({Glfw.GetError() ?? "no display?"})";
                return false;
            }
            s_initialised = true;
            return true;
        }
    }

    /// <summary>Asks for an OpenGL 3.3 core, forward-compatible context.</summary>
    public static void CoreProfileHints()
    {
        Glfw.WindowHint(Glfw.ContextVersionMajor, 3);
        Glfw.WindowHint(Glfw.ContextVersionMinor, 3);
        Glfw.WindowHint(Glfw.OpenGlProfile, Glfw.OpenGlCoreProfile);
        Glfw.WindowHint(Glfw.OpenGlForwardCompat, Glfw.True);
    }
}
