using System.Diagnostics;
using System.Runtime.InteropServices;
using Billiards.App.Rendering;

namespace Billiards.App.Tests.Rendering;

/// <summary>
/// One offscreen renderer for the GL tests. EGL surfaceless (Mesa llvmpipe) is the route on a
/// headless machine; if it fails and there is no display, an Xvfb is started for the hidden GLFW
/// window; if that fails too, the tests fail with both reasons.
/// </summary>
public sealed class GlFixture : IDisposable
{
    private readonly Process? _xvfb;

    public GlFixture()
    {
        try
        {
            Renderer = new OffscreenRenderer();
            return;
        }
        catch (InvalidOperationException first) when (OperatingSystem.IsLinux() && Environment.GetEnvironmentVariable("DISPLAY") is null)
        {
            _xvfb = StartXvfb(first.Message);
        }
        Renderer = new OffscreenRenderer();
    }

    internal OffscreenRenderer Renderer { get; }

    private static Process StartXvfb(string why)
    {
        const string Display = ":97";
        Process xvfb;
        try
        {
            xvfb = Process.Start(new ProcessStartInfo("Xvfb", $"{Display} -screen 0 1280x1024x24 -nolisten tcp") { UseShellExecute = false })!;
        }
        catch (System.ComponentModel.Win32Exception e)
        {
            throw new InvalidOperationException($"{why}; and Xvfb could not start: {e.Message}");
        }
        Thread.Sleep(1500);
        // GLFW reads the process environment through libc, not .NET's copy of it.
        _ = SetEnv("DISPLAY", Display, 1);
        Environment.SetEnvironmentVariable("DISPLAY", Display);
        return xvfb;
    }

    [DllImport("libc", EntryPoint = "setenv")]
    private static extern int SetEnv(string name, string value, int overwrite);

    public void Dispose()
    {
        Renderer.Dispose();
        if (_xvfb is { HasExited: false })
        {
            _xvfb.Kill();
            _xvfb.WaitForExit();
        }
        _xvfb?.Dispose();
    }
}

[CollectionDefinition("GL")]
public sealed class GlCollection : ICollectionFixture<GlFixture>;
