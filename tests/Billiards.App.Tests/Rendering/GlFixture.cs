using System.Diagnostics;
using System.Runtime.InteropServices;
using Billiards.App.Rendering;

namespace Billiards.App.Tests.Rendering;

/// <summary>
/// One offscreen renderer for the GL tests. EGL surfaceless (Mesa llvmpipe) is the route on a
/// headless machine; if it fails, a display is made sure of (<see cref="TestDisplay"/>) for the
/// hidden GLFW window; if that fails too, the tests fail with the reasons.
/// </summary>
public sealed class GlFixture : IDisposable
{
    public GlFixture()
    {
        try
        {
            Renderer = new OffscreenRenderer();
        }
        catch (InvalidOperationException first)
        {
            TestDisplay.Ensure(first.Message);
            Renderer = new OffscreenRenderer();
        }
    }

    internal OffscreenRenderer Renderer { get; }

    public void Dispose() => Renderer.Dispose();
}

[CollectionDefinition("GL")]
public sealed class GlCollection : ICollectionFixture<GlFixture>;

/// <summary>
/// A display for tests that open GLFW windows: the one in DISPLAY, or on Linux without one an
/// Xvfb started once for the test process and stopped when it exits.
/// </summary>
internal static class TestDisplay
{
    private static readonly Lock s_lock = new();
    private static Process? s_xvfb;

    public static void Ensure(string why = "a window needs a display")
    {
        lock (s_lock)
        {
            if (!OperatingSystem.IsLinux() || s_xvfb is not null || !string.IsNullOrEmpty(Environment.GetEnvironmentVariable("DISPLAY")))
            {
                return;
            }
            string display = $":{90 + (Environment.ProcessId % 400)}";
            try
            {
                s_xvfb = Process.Start(new ProcessStartInfo("Xvfb", $"{display} -screen 0 1280x1024x24 -nolisten tcp")
                {
                    UseShellExecute = false,
                    RedirectStandardError = true,
                })!;
            }
            catch (System.ComponentModel.Win32Exception e)
            {
                throw new InvalidOperationException($"{why}; and Xvfb could not start: {e.Message}");
            }
            s_xvfb.ErrorDataReceived += (_, _) => { };
            s_xvfb.BeginErrorReadLine();
            string socket = $"/tmp/.X11-unix/X{display[1..]}";
            for (int i = 0; i < 100 && !File.Exists(socket) && !s_xvfb.HasExited; i++)
            {
                Thread.Sleep(50);
            }
            if (s_xvfb.HasExited)
            {
                throw new InvalidOperationException($"{why}; and Xvfb {display} exited at once");
            }
            // GLFW reads the environment through libc, not through .NET's copy of it.
            _ = SetEnv("DISPLAY", display, 1);
            Environment.SetEnvironmentVariable("DISPLAY", display);
            AppDomain.CurrentDomain.ProcessExit += (_, _) =>
            {
                // SIGTERM, so that Xvfb removes its lock file and socket.
                if (s_xvfb is { HasExited: false } && Kill(s_xvfb.Id, 15) == 0)
                {
                    s_xvfb.WaitForExit(2000);
                }
            };
        }
    }

    [DllImport("libc", EntryPoint = "kill")]
    private static extern int Kill(int pid, int signal);

    [DllImport("libc", EntryPoint = "setenv")]
    private static extern int SetEnv(string name, string value, int overwrite);
}
