using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Game;

/// <summary>
/// Runs the game in a window: builds the scene's tree, routes the window's input into it, and per
/// frame runs the fixed physics steps the elapsed time owes, processes the tree and builds the
/// <see cref="RenderFrame"/> (balls interpolated with the loop's alpha).
/// </summary>
public sealed class GameHost : IDisposable
{
    private readonly IGameWindow _window;
    private readonly IClock _clock;
    private readonly GameWorld _world;
    private readonly InputRouter _router;
    private readonly Action _physicsStep;
    private double _lastFrame;

    /// <summary>Builds and starts the game for a scene in a window.</summary>
    /// <param name="scene">The scene to play.</param>
    /// <param name="createSimulation">Makes the scene's simulation (<see cref="SimulationFactory.Create"/>).</param>
    /// <param name="window">The window (input and switches).</param>
    /// <param name="clock">The clock for frame times and input timestamps.</param>
    /// <param name="match">The match to play, or null for practice.</param>
    /// <param name="practice">Practice's tools and a drill, or null.</param>
    public GameHost(Scene scene, Func<Scene, Simulation> createSimulation, IGameWindow window, IClock clock, MatchSetup? match = null, PracticeSetup? practice = null)
    {
        _window = window;
        _clock = clock;
        _world = GameSceneBuilder.Build(scene, createSimulation, match, practice);
        _physicsStep = () => _world.Tree.PhysicsProcess(_world.Loop.Dt);
        _world.Menu.QuitConfirmed += window.Close;
        _world.SystemKeys.FullscreenRequested += window.ToggleFullscreen;
        _world.InputModes.MouseCaptureChanged += window.SetMouseCaptured;
        _world.Tree.Start();
        _router = new InputRouter(window, clock, e => _world.Tree.Input(e));
        _lastFrame = clock.Now;
    }

    /// <summary>Signal: a frame starts at this clock time (s), before its physics, input and drawing.</summary>
    public event Action<double>? FrameStarting;

    /// <summary>The running game.</summary>
    public GameWorld World => _world;

    /// <summary>The scene tree.</summary>
    public SceneTree Tree => _world.Tree;

    /// <summary>The fixed-step loop.</summary>
    public FixedStepLoop Loop => _world.Loop;

    /// <summary>
    /// How many times faster than the clock the game's physics runs (1 by default; a script may
    /// ask for more to play a long game in a short time). Frames and input keep the clock's time.
    /// </summary>
    public double TimeScale { get; set; } = 1;

    /// <summary>
    /// True when nothing moves and nobody but a person is to act: the balls rest, no computer
    /// player is at work, no hint is being searched (a script that waits for rest after G
    /// shoots the hint, not whatever the cue pointed at when the search was slower), and over the
    /// network the peer is not to move and the game is not held (a script waits for its turn).
    /// </summary>
    public bool IsSettled => !_world.Physics.IsRolling && _world.Tree.Root.FindInTree<MatchNode>() is not { IsWatching: true }
        && _world.Tree.Root.FindInTree<ComputerPlayerNode>() is not { IsHinting: true };

    /// <summary>
    /// One frame: the physics steps owed since the last frame, Process with the frame's time, then
    /// the frame to draw.
    /// </summary>
    public RenderFrame RunFrame()
    {
        double now = _clock.Now;
        FrameStarting?.Invoke(now);
        _router.Repeat();
        double frameTime = now - _lastFrame;
        _lastFrame = now;
        _world.Loop.Advance(frameTime, _physicsStep, TimeScale);
        _world.Tree.Process(frameTime);
        var (width, height) = _window.FramebufferSize;
        var builder = new FrameBuilder(_world.Physics.Table, width, height, _world.Loop.Alpha);
        _world.Tree.Draw(builder);
        return builder.Frame;
    }

    /// <summary>Runs the game until the window closes, drawing every frame with <paramref name="renderer"/>.</summary>
    public void Run(IFrameLoop loop, IFrameRenderer renderer) => loop.Run(() => renderer.Draw(RunFrame()));

    /// <summary>Stops listening to the window and releases the mouse.</summary>
    public void Dispose()
    {
        _router.Dispose();
        _window.SetMouseCaptured(false);
    }
}
