using Billiards.App.Platform;
using Billiards.App.Rendering;

namespace Billiards.App.Game;

/// <summary>What the game needs from a renderer: draw one frame's plain data.</summary>
public interface IFrameRenderer
{
    /// <summary>Draws the frame (the window presents it when the frame callback returns).</summary>
    void Draw(RenderFrame frame);
}

/// <summary>What the game needs from a window's frame loop.</summary>
public interface IFrameLoop
{
    /// <summary>
    /// Runs until the window closes: each iteration polls events (raising <see cref="IGameWindow"/>'s
    /// events), calls <paramref name="frame"/>, then swaps buffers.
    /// </summary>
    void Run(Action frame);
}

/// <summary>A window, its frame loop and a renderer: everything <c>play</c> takes from the platform layer.</summary>
/// <param name="Window">Input events and window switches.</param>
/// <param name="Loop">The frame loop (usually the window itself).</param>
/// <param name="Renderer">Draws a <see cref="RenderFrame"/>.</param>
/// <param name="Resources">Released when the game ends (window, GL context), or null.</param>
/// <param name="GlRenderer">The GL renderer's name (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"), or null.</param>
public sealed record GamePlatform(IGameWindow Window, IFrameLoop Loop, IFrameRenderer Renderer, IDisposable? Resources = null, string? GlRenderer = null) : IDisposable
{
    /// <summary>Sets the window's title (a game chosen in the start menu names itself), or null where there is no title.</summary>
    public Action<string>? SetTitle { get; init; }

    /// <summary>Applies the Settings screen's graphics to the renderer, or null where nothing is drawn.</summary>
    public Action<GraphicsQuality>? SetGraphics { get; init; }

    /// <summary>Releases <see cref="Resources"/>.</summary>
    public void Dispose() => Resources?.Dispose();
}
