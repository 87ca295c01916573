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
            // -displayfd: Xvfb picks a display number no other server holds and writes it to its
            // standard output once it accepts connections (a number of our own could collide with
            // another server, and its socket can exist before the server is ready).
            try
            {
                s_xvfb = Process.Start(new ProcessStartInfo("Xvfb", "-displayfd 1 -screen 0 1280x1024x24 -nolisten tcp")
                {
                    UseShellExecute = false,
                    RedirectStandardOutput = true,
                    RedirectStandardError = true,
                })!;
            }
            catch (System.ComponentModel.Win32Exception e)
            {
                throw new InvalidOperationException($"{why}; and Xvfb could not start: {e.Message}");
            }
            s_xvfb.ErrorDataReceived += (_, _) => { };
            s_xvfb.BeginErrorReadLine();
            var ready = s_xvfb.StandardOutput.ReadLineAsync();
            if (!ready.Wait(TimeSpan.FromSeconds(10)) || !int.TryParse(ready.Result, out int number))
            {
                throw new InvalidOperationException($"{why}; and Xvfb did not report a display within 10 s{(s_xvfb.HasExited ? " (it exited)" : "")}");
            }
            string display = $":{number}";
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
