using System.CommandLine;
using Billiards.App.Game;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>play [SCENE]</c>: the game, and the default verb (no verb plays <see cref="DefaultScene"/>).
/// The scene is loaded and checked before any window opens, so a bad scene is one line on stderr
/// and a non-zero exit.
/// </summary>
public static class PlayCommand
{
    /// <summary>The scene played without arguments: 8-ball on a 9 ft table.</summary>
    public const string DefaultScene = "assets/scenes/eight-ball.json";

    /// <summary>Adds the <c>play</c> verb to the root command and makes it the root's own action.</summary>
    public static void AddTo(RootCommand root)
    {
        var scene = new Argument<string?>("scene")
        {
            Description = $"The scene file (billiards-scene/1 JSON); default {DefaultScene}.",
            Arity = ArgumentArity.ZeroOrOne,
        };
        var command = new Command("play", "Play a scene in a window (the default verb).") { scene };
        command.SetAction(parse => Play(parse.GetValue(scene), PlatformWiring.Open));
        root.Add(command);
        root.SetAction(_ => Play(null, PlatformWiring.Open));
    }

    /// <summary>Loads the scene, opens the platform and runs the game until the window closes.</summary>
    /// <param name="scenePath">The scene, or null for <see cref="DefaultScene"/>.</param>
    /// <param name="openPlatform">Opens the window and renderer for a window title.</param>
    /// <param name="createSimulation">Makes the simulation; <see cref="SimulationFactory.Create"/> by default.</param>
    /// <param name="clock">The clock; the real one by default.</param>
    /// <returns>The exit code.</returns>
    public static int Play(string? scenePath, Func<string, GamePlatform> openPlatform, Func<Scene, Simulation>? createSimulation = null, IClock? clock = null)
    {
        var scene = SceneLoader.Load(scenePath ?? FindDefaultScene());
        string title = scene.Name is { } name ? $"{PlatformWiring.WindowTitle}: {name}" : PlatformWiring.WindowTitle;
        using var platform = OpenOrExplain(openPlatform, title);
        using var host = new GameHost(scene, createSimulation ?? SimulationFactory.Create, platform.Window, clock ?? new StopwatchClock());
        host.Run(platform.Loop, platform.Renderer);
        return 0;
    }

    // No display, no GL driver, no GLFW: an environment problem, one line and exit code 1.
    private static GamePlatform OpenOrExplain(Func<string, GamePlatform> openPlatform, string title)
    {
        try
        {
            return openPlatform(title);
        }
        catch (Exception e) when (e is InvalidOperationException or DllNotFoundException or EntryPointNotFoundException)
        {
            throw new EnvironmentException($"play: cannot open the game's window: {e.Message}", e);
        }
    }

    /// <summary>
    /// The default scene: relative to the working directory, else in the shipped assets
    /// (<see cref="AssetFolder"/>), so the game starts from the repository and from a build folder.
    /// </summary>
    public static string FindDefaultScene() =>
        File.Exists(DefaultScene) ? DefaultScene : AssetFolder.Scene(Path.GetFileName(DefaultScene));
}
