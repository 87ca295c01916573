using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Platform;

[Collection("GL")]
public class GlfwWindowTests
{
    [Fact]
    public void WindowOpensDrawsFramesAndTogglesFullscreen()
    {
        TestDisplay.Ensure();
        using var window = new GlfwWindow("smoke", 640, 360);
        using var renderer = new Renderer(window.Gl);
        int frames = 0;
        int resized = 0;
        window.Resize += (_, _) => resized++;
        window.Run(dt =>
        {
            var (w, h) = window.FramebufferSize;
            renderer.Draw(new RenderFrame { Table = TableSpec.FromPreset("pool-9ft"), Width = w, Height = h, Hud = new HudInfo(["fps"], default, false, []) });
            if (++frames == 5)
            {
                window.ToggleFullscreen();
            }
            if (frames == 10)
            {
                window.ToggleFullscreen();
            }
            if (frames >= 20)
            {
                window.Close();
            }
        });
        Assert.Equal(20, frames);
    }

    [Fact]
    public void TheWindowLoopKeepsToItsCap()
    {
        TestDisplay.Ensure();
        using var window = new GlfwWindow("cap", 160, 90) { FrameCap = 50 };
        int frames = 0;
        var clock = System.Diagnostics.Stopwatch.StartNew();
        window.Run(_ =>
        {
            if (++frames >= 11)
            {
                window.Close();
            }
        });
        // Ten periods of 20 ms between the first frame and the eleventh at least (a busy machine may take longer).
        Assert.True(clock.Elapsed.TotalSeconds >= 0.2 - 0.002, $"{clock.Elapsed.TotalMilliseconds} ms");
    }
    [Fact]
    public void StrokingHidesTheCursorRatherThanDisablingItSoAbsolutePointersKeepTheirPositions()
    {
        TestDisplay.Ensure();
        using var window = new GlfwWindow("cursor", 320, 200);
        window.SetMouseCaptured(true);
        Assert.True(window.IsCursorHidden);
        window.SetMouseCaptured(false);
        Assert.False(window.IsCursorHidden);
    }

    [Theory]
    [InlineData(65, Key.A)]
    [InlineData(90, Key.Z)]
    [InlineData(48, Key.D0)]
    [InlineData(32, Key.Space)]
    [InlineData(256, Key.Escape)]
    [InlineData(265, Key.Up)]
    [InlineData(300, Key.F11)]
    [InlineData(334, Key.Plus)]
    [InlineData(340, Key.Shift)]
    [InlineData(344, Key.Shift)]
    [InlineData(46, Key.Period)]
    [InlineData(330, Key.Period)]
    [InlineData(59, Key.Semicolon)]
    [InlineData(999, Key.Unknown)]
    public void MapKeyTranslatesGlfwKeyCodes(int glfwKey, Key expected)
    {
        Assert.Equal(expected, GlfwWindow.MapKey(glfwKey));
    }
}
