using Billiards.App.Camera;
using Billiards.App.Hud;
using Billiards.App.Input.Modes;
using Billiards.App.Nodes;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Game;

/// <summary>A built game: its tree (not started) and the nodes the host connects to the window and the loop.</summary>
/// <param name="Tree">The scene tree.</param>
/// <param name="Loop">The fixed-step loop at the simulation's step.</param>
/// <param name="Physics">The physics node.</param>
/// <param name="InputModes">The control modes.</param>
/// <param name="SystemKeys">Pause, step, help, debug, fullscreen and quit.</param>
/// <param name="Menu">The pause menu and the option buttons.</param>
public sealed record GameWorld(SceneTree Tree, FixedStepLoop Loop, PhysicsNode Physics, InputModeNode InputModes, SystemKeysNode SystemKeys, MenuNode Menu);

/// <summary>A match to play: the game and the two players.</summary>
/// <param name="Rules">The game.</param>
/// <param name="Players">The two players.</param>
public sealed record MatchSetup(GameRules Rules, IReadOnlyList<Seat> Players)
{
    /// <summary>The game exactly (a networked game's, the same on both sides), or null for the scene's.</summary>
    public GameSetup? Game { get; init; }
}

/// <summary>
/// Builds the node tree a scene asks for: a scene loads only what it declares. Always: table,
/// physics, camera, control modes, system keys, the take-back and the instant replay, and HUD. Only with a cue ball: the cue (without it
/// there is nothing to shoot, and only view mode works). Only with a match (the scene's rules, or a chosen game): the match, the computer player, the call picker and the view that turns to the next legal ball.
/// </summary>
public static class GameSceneBuilder
{
    /// <summary>Builds the tree for a scene; <paramref name="createSimulation"/> makes its simulation.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="createSimulation">Makes the scene's simulation.</param>
    /// <param name="match">The match to play on the scene's rules, or null for none (practice).</param>
    /// <param name="practice">Practice's tools and a drill (<see cref="PracticeNode"/>), or null; only without a match.</param>
    public static GameWorld Build(Scene scene, Func<Scene, Simulation> createSimulation, MatchSetup? match = null, PracticeSetup? practice = null)
    {
        var root = new Node("Game");
        root.AddChild(new TableNode(scene));
        var physics = root.AddChild(new PhysicsNode(scene, createSimulation));
        var loop = new FixedStepLoop(physics.Simulation.Dt);
        root.AddChild(new CameraNode());
        if (scene.Balls.Any(b => b.Id == scene.CueBall))
        {
            root.AddChild(new CueNode());
            root.AddChild(new AimLineNode());
            root.AddChild(new DiamondAidNode());
        }
        var modes = root.AddChild(new InputModeNode());
        if (match is not null && scene.Balls.Any(b => b.Id == scene.CueBall))
        {
            var session = match.Game is { } game ? new Session(game, match.Players, createSimulation) : Session.OfScene(scene, match.Rules, match.Players, physics.Simulation, createSimulation);
            root.AddChild(new MatchNode(session));
            root.AddChild(new ComputerPlayerNode());
            root.AddChild(new CallPickerNode());
            root.AddChild(new TargetViewNode());
        }
        if (match is null && practice is null && scene.Balls.Any(b => b.Id == scene.CueBall))
        {
            // A scene without a game: its shots go through a session without a referee too.
            root.AddChild(new FreeTableNode());
        }
        // Added after the modes: input runs from the last child back, so these keys come first.
        var keys = root.AddChild(new SystemKeysNode(loop));
        // After the physics node (the replay draws its balls over the table's) and before the
        // system keys in input (P and N pause and step the replay while it is shown).
        root.AddChild(new TakeBackNode());
        root.AddChild(new InstantReplayNode());
        root.AddChild(new HudNode());
        if (practice is not null && match is null && scene.Balls.Any(b => b.Id == scene.CueBall))
        {
            // After the HUD: it adds its lines and the drill's zone to the HUD's frame, and takes its keys before the others.
            root.AddChild(new PracticeNode(scene, practice));
        }
        // Last: it draws over the HUD and takes input first (a menu takes it all).
        var menu = root.AddChild(new MenuNode());
        return new GameWorld(new SceneTree(root), loop, physics, modes, keys, menu);
    }
}
