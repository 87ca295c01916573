using Billiards.App.Cli;

namespace Billiards.App.Game;

/// <summary>
/// THE one place where <c>play</c> gets its window and renderer from the platform layer (the
/// render branch's GLFW window and GL renderer). Nothing else in the game knows about them.
/// </summary>
public static class PlatformWiring
{
    /// <summary>Title of the game's window.</summary>
    public const string WindowTitle = "Billiards";

    /// <summary>Opens the window and its renderer.</summary>
    /// <exception cref="CliException">Until the platform layer is wired in.</exception>
    public static GamePlatform Open(string title)
    {
        // MERGE(render): replace the throw with, for example,
        //   var window = new GlfwWindow(title, 1280, 720);      // : IGameWindow, and IFrameLoop via Run(Action)
        //   var renderer = new Renderer(window);                // Draw(RenderFrame) -> IFrameRenderer (adapter if named otherwise)
        //   return new GamePlatform(window, window, renderer, window);
        throw new CliException($"play: no window in this build yet ('{title}'; the GLFW window and renderer plug in at Game/PlatformWiring.cs)");
    }
}
