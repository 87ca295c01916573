using Billiards.App.Platform;
using Billiards.App.Rendering;

namespace Billiards.App.Game;

/// <summary>
/// The one place where <c>play</c> gets its window and renderer from the platform layer (the GLFW
/// window and the GL renderer). Nothing else in the game knows about them.
/// </summary>
public static class PlatformWiring
{
    /// <summary>Title of the game's window.</summary>
    public const string WindowTitle = "Billiards";

    /// <summary>The frame cap (frames/s) where the display does not give its refresh rate.</summary>
    public const int DefaultFrameCap = 60;

    /// <summary>The most frames/s a cap may ask for.</summary>
    public const int MaxFrameCap = 1000;

    /// <summary>Opens the window at the display's frame cap (<see cref="Open(string, double?)"/>).</summary>
    public static GamePlatform Open(string title) => Open(title, null);

    /// <summary>
    /// Opens a 1280x720 window and a renderer on its GL context: 4x MSAA on a GPU, none on a
    /// software rasteriser, where multisampling multiplied the cost of a frame about threefold.
    /// Frames are capped at <paramref name="frameCap"/> a second (0: no cap); by default at the
    /// display's refresh rate, or <see cref="DefaultFrameCap"/> when it gives none.
    /// </summary>
    public static GamePlatform Open(string title, double? frameCap)
    {
        Cli.PlayCommand.RequireDisplay();
        var window = new GlfwWindow(title, 1280, 720, samples: 4);
        if (window.IsSoftwareRenderer)
        {
            window.Dispose();
            window = new GlfwWindow(title, 1280, 720, samples: 0);
        }
        int refresh = GlfwWindow.RefreshRate;
        window.FrameCap = frameCap ?? (refresh > 0 ? refresh : DefaultFrameCap);
        try
        {
            // On a software rasteriser a moving camera is drawn at reduced resolution (Renderer.DynamicResolution).
            var renderer = new Renderer(window.Gl) { DynamicResolution = window.IsSoftwareRenderer };
            if (Environment.GetEnvironmentVariable("BILLIARDS_PASS_PROFILE") is { Length: > 0 })
            {
                renderer.Profile = new PassProfile(window.Gl.Finish);
            }
            var resources = new Resources(renderer, window);
            return new GamePlatform(window, new WindowLoop(window), new FrameRenderer(renderer, window), resources, window.Gl.GetString(Gl.RendererName))
            {
                SetTitle = window.SetTitle,
                SetGraphics = quality => renderer.DynamicResolution = GraphicsWords.ReducesWhileMoving(quality, window.IsSoftwareRenderer),
            };
        }
        catch
        {
            window.Dispose();
            throw;
        }
    }

    // The renderer draws at the framebuffer's current size, told how long the last frame took
    // against the cap's period (or 60 Hz's without a cap).
    private sealed class FrameRenderer(Renderer renderer, GlfwWindow window) : IFrameRenderer
    {
        public void Draw(RenderFrame frame)
        {
            (frame.Width, frame.Height) = window.FramebufferSize;
            renderer.ReportFrameTime(window.LastWorkSeconds, 1.0 / (window.FrameCap > 0 ? window.FrameCap : DefaultFrameCap));
            renderer.Draw(frame);
        }
    }

    private sealed class WindowLoop(GlfwWindow window) : IFrameLoop
    {
        public void Run(Action frame) => window.Run(_ => frame());
    }

    // The renderer's GL objects go before the context that owns them.
    private sealed class Resources(Renderer renderer, GlfwWindow window) : IDisposable
    {
        public void Dispose()
        {
            if (renderer.Profile is { } profile)
            {
                foreach (var (pass, wall, cpu, count) in profile.PerFrame())
                {
                    Console.Error.WriteLine(string.Create(System.Globalization.CultureInfo.InvariantCulture, $"pass {pass,-28} wall {wall,7:F2} ms  cpu {cpu,7:F2} ms a frame  ({count} of {profile.Frames} frames)"));
                }
            }
            renderer.Dispose();
            window.Dispose();
        }
    }
}
