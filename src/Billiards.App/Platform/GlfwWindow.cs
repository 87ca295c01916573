using System.Numerics;
using System.Runtime.InteropServices;
using Billiards.App.Native;
using Billiards.App.Rendering;

namespace Billiards.App.Platform;

/// <summary>
/// The game's window: GLFW, 1280 x 720 by default, resizable, 4x MSAA, OpenGL 3.3 core, vsync.
/// Translates GLFW's callbacks into <see cref="IGameWindow"/> events. One thread: create it,
/// call <see cref="Run"/> and dispose it on the same thread.
/// </summary>
internal sealed unsafe class GlfwWindow : IGameWindow, IDisposable
{
    private static readonly Dictionary<nint, GlfwWindow> s_windows = [];

    private nint _window;
    private (int X, int Y, int Width, int Height) _windowedBounds;
    private Exception? _pending;

    /// <summary>Opens the window (visible) and makes its context current; throws <see cref="InvalidOperationException"/> if it cannot.</summary>
    public GlfwWindow(string title = "Billiards", int width = 1280, int height = 720, int samples = 4)
    {
        if (!GlfwRuntime.Acquire(out string? error))
        {
            throw new InvalidOperationException(error);
        }
        Glfw.DefaultWindowHints();
        Glfw.WindowHint(Glfw.Resizable, Glfw.True);
        Glfw.WindowHint(Glfw.Samples, samples);
        Samples = samples;
        GlfwRuntime.CoreProfileHints();
        _window = Glfw.CreateWindow(width, height, title, 0, 0);
        if (_window == 0)
        {
            string reason = Glfw.GetError() ?? "no reason given";
            throw new InvalidOperationException($"cannot open an OpenGL 3.3 window: {reason}");
        }
        s_windows[_window] = this;
        Glfw.MakeContextCurrent(_window);
        Glfw.SwapInterval(1);
        Glfw.SetKeyCallback(_window, &OnKey);
        Glfw.SetCursorPosCallback(_window, &OnCursor);
        Glfw.SetMouseButtonCallback(_window, &OnButton);
        Glfw.SetScrollCallback(_window, &OnScroll);
        Glfw.SetFramebufferSizeCallback(_window, &OnFramebufferSize);
        Gl = new Gl(Glfw.GetProcAddress);
    }

    public event Action<Key>? KeyDown;
    public event Action<Key>? KeyUp;
    public event Action<Vector2>? MouseMove;
    public event Action<MouseButton>? MouseDown;
    public event Action<MouseButton>? MouseUp;
    public event Action<float>? Scroll;
    public event Action<int, int>? Resize;

    /// <summary>MSAA samples asked for when the window was opened.</summary>
    public int Samples { get; }

    /// <summary>True when the context renders in software (<see cref="Gl.IsSoftwareRasterizer"/>).</summary>
    public bool IsSoftwareRenderer => Gl.IsSoftwareRasterizer;

    /// <summary>The GL functions of this window's context.</summary>
    public Gl Gl { get; }

    public (int Width, int Height) FramebufferSize => Glfw.GetFramebufferSize(_window);

    /// <summary>True when the window should close (close button or <see cref="Close"/>).</summary>
    public bool ShouldClose => Glfw.WindowShouldClose(_window);

    /// <summary>
    /// Runs the loop until the window closes: polls events, calls <paramref name="frame"/> with
    /// the seconds since the previous frame (0 on the first), swaps buffers, and waits as
    /// <see cref="FrameCap"/> says.
    /// </summary>
    public void Run(Action<double> frame)
    {
        var pacer = new FramePacer(FrameCap);
        double last = Glfw.GetTime();
        bool first = true;
        while (!Glfw.WindowShouldClose(_window))
        {
            double started = Glfw.GetTime();
            Glfw.PollEvents();
            if (_pending is { } pending)
            {
                _pending = null;
                System.Runtime.ExceptionServices.ExceptionDispatchInfo.Throw(pending);
            }
            double now = Glfw.GetTime();
            frame(first ? 0 : now - last);
            first = false;
            last = now;
            Glfw.SwapBuffers(_window);
            // At most one frame in flight: the frame just swapped is finished before the next
            // frame's input is read, so input shows on the next frame. Without it a driver may
            // queue frames (or, without vsync, pile them up) between the input and the screen.
            Gl.Finish();
            double ended = Glfw.GetTime();
            LastWorkSeconds = ended - started;
            double wait = pacer.WaitAfter(ended);
            if (wait > 0)
            {
                Thread.Sleep(TimeSpan.FromSeconds(wait));
            }
        }
    }

    /// <summary>
    /// The most frames a second <see cref="Run"/> draws (0: no cap). The swap waits for the
    /// display's refresh where the driver can (vsync); this cap also holds where it cannot (a
    /// software rasteriser, a virtual display), so that the game does not keep every core busy.
    /// </summary>
    public double FrameCap { get; set; }

    /// <summary>How long the last frame's work took (s): input, the frame, the swap and the wait for the GPU, not the cap's wait.</summary>
    public double LastWorkSeconds { get; private set; }

    /// <summary>The primary monitor's refresh rate (Hz), or 0 when the display does not say.</summary>
    public static int RefreshRate
    {
        get
        {
            nint monitor = Glfw.GetPrimaryMonitor();
            return monitor == 0 ? 0 : Math.Max(0, Glfw.GetVideoMode(monitor).RefreshRate);
        }
    }

    /// <summary>Sets the title bar text.</summary>
    public void SetTitle(string title) => Glfw.SetWindowTitle(_window, title);

    /// <summary>
    /// Hides the cursor while stroking (or shows it again). The cursor is hidden, not disabled:
    /// a disabled cursor reports motion relative to a point GLFW warps it back to, which only a
    /// relative mouse gives; a tablet, a remote desktop or a virtual machine moves the pointer to
    /// absolute positions, and the stroke (which reads the pointer's height) would see jumps or
    /// nothing. While the button is held the window keeps the pointer's reports even outside it.
    /// </summary>
    public void SetMouseCaptured(bool captured) =>
        Glfw.SetInputMode(_window, Glfw.CursorMode, captured ? Glfw.CursorHidden : Glfw.CursorNormal);

    /// <summary>True while the cursor is hidden for a stroke.</summary>
    public bool IsCursorHidden => Glfw.GetInputMode(_window, Glfw.CursorMode) == Glfw.CursorHidden;

    public void ToggleFullscreen()
    {
        if (Glfw.GetWindowMonitor(_window) != 0)
        {
            var (x, y, w, h) = _windowedBounds;
            Glfw.SetWindowMonitor(_window, 0, x, y, w, h, 0);
            return;
        }
        nint monitor = Glfw.GetPrimaryMonitor();
        if (monitor == 0)
        {
            return;
        }
        var (px, py) = Glfw.GetWindowPos(_window);
        var (pw, ph) = Glfw.GetWindowSize(_window);
        _windowedBounds = (px, py, pw, ph);
        var mode = Glfw.GetVideoMode(monitor);
        Glfw.SetWindowMonitor(_window, monitor, 0, 0, mode.Width, mode.Height, mode.RefreshRate);
    }

    public void Close() => Glfw.SetWindowShouldClose(_window, true);

    public void Dispose()
    {
        if (_window != 0)
        {
            s_windows.Remove(_window);
            Glfw.DestroyWindow(_window);
            _window = 0;
        }
    }

    /// <summary>GLFW key code to the game's key.</summary>
    internal static Key MapKey(int key) => key switch
    {
        >= 65 and <= 90 => Key.A + (key - 65),
        >= 48 and <= 57 => Key.D0 + (key - 48),
        >= 320 and <= 329 => Key.D0 + (key - 320),
        32 => Key.Space,
        256 => Key.Escape,
        257 or 335 => Key.Enter,
        258 => Key.Tab,
        262 => Key.Right,
        263 => Key.Left,
        264 => Key.Down,
        265 => Key.Up,
        266 => Key.PageUp,
        267 => Key.PageDown,
        61 or 334 => Key.Plus,
        45 or 333 => Key.Minus,
        290 => Key.F1,
        291 => Key.F2,
        292 => Key.F3,
        293 => Key.F4,
        300 => Key.F11,
        294 => Key.F5,
        295 => Key.F6,
        296 => Key.F7,
        298 => Key.F9,
        260 => Key.Insert,
        261 => Key.Delete,
        259 => Key.Backspace,
        340 or 344 => Key.Shift,
        46 or 330 => Key.Period,
        59 => Key.Semicolon,
        _ => Key.Unknown,
    };

    // An exception must not unwind through GLFW's C frames: keep it and rethrow after PollEvents.
    private static void Dispatch(nint window, Action<GlfwWindow> handler)
    {
        if (s_windows.TryGetValue(window, out var w) && w._pending is null)
        {
            try
            {
                handler(w);
            }
            catch (Exception e)
            {
                w._pending = e;
            }
        }
    }

    [UnmanagedCallersOnly]
    private static void OnKey(nint window, int key, int scancode, int action, int mods)
    {
        var mapped = MapKey(key);
        // The system's repeats (Glfw.Repeat) are left out: the game repeats held keys itself (KeyRepeat).
        if (action == Glfw.Press)
        {
            Dispatch(window, w => w.KeyDown?.Invoke(mapped));
        }
        else if (action == Glfw.Release)
        {
            Dispatch(window, w => w.KeyUp?.Invoke(mapped));
        }
    }

    [UnmanagedCallersOnly]
    private static void OnCursor(nint window, double x, double y)
    {
        Dispatch(window, w => w.MouseMove?.Invoke(new Vector2((float)x, (float)y)));
    }

    [UnmanagedCallersOnly]
    private static void OnButton(nint window, int button, int action, int mods)
    {
        if (button is < 0 or > 2)
        {
            return;
        }
        var mapped = (MouseButton)button;
        if (action == Glfw.Press)
        {
            Dispatch(window, w => w.MouseDown?.Invoke(mapped));
        }
        else
        {
            Dispatch(window, w => w.MouseUp?.Invoke(mapped));
        }
    }

    [UnmanagedCallersOnly]
    private static void OnScroll(nint window, double dx, double dy)
    {
        Dispatch(window, w => w.Scroll?.Invoke((float)dy));
    }

    [UnmanagedCallersOnly]
    private static void OnFramebufferSize(nint window, int width, int height)
    {
        Dispatch(window, w => w.Resize?.Invoke(width, height));
    }
}
