using Billiards.App.Camera;
using Billiards.App.Game;
using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Physics;

namespace Billiards.App.Audio;

/// <summary>
/// The game's sound: voices every event the <see cref="PhysicsNode"/> signals (the same
/// <see cref="EventVoicing"/> as render-audio), gives every ball's rolling speed after each physics
/// step, and follows the camera as the listener. Keys: <c>+</c> / <c>-</c> volume, <c>U</c> mute;
/// the HUD shows each change for a moment (<see cref="StatusLine"/>), and all the time that the
/// game is silent when there is no audio device.
/// </summary>
/// <remarks>
/// It may join a tree that has already started: on <see cref="Node.Ready"/> it voices the events
/// logged in the last <see cref="CatchUp"/> seconds, so a scene's opening shot, struck when the
/// physics node became ready, is heard.
/// </remarks>
public sealed class AudioNode(IAudioOutput output) : Node
{
    /// <summary>Volume change per key press.</summary>
    public const float VolumeStep = 0.1f;

    /// <summary>How far back (s) a node joining a running game voices events already logged.</summary>
    public const double CatchUp = 0.05;

    /// <summary>How long the HUD shows a volume or mute change (s).</summary>
    public const double FeedbackSeconds = 2;

    private PhysicsNode? _physics;
    private CameraNode? _camera;
    private double _feedbackLeft;
    private EventVoicing? _voicing;
    private Simulation? _simulation;

    /// <summary>The output the sounds go to.</summary>
    public IAudioOutput Output { get; } = output;

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _camera = FindInTree<CameraNode>();
        _physics.EventOccurred += OnEvent;
        UpdateListener();
        var sim = _physics.Simulation;
        foreach (var e in sim.Events.AsSpan())
        {
            if (e.Time >= sim.Time - CatchUp)
            {
                OnEvent(e);
            }
        }
    }

    private void OnEvent(SimEvent e)
    {
        var sim = _physics!.Simulation;
        if (!ReferenceEquals(sim, _simulation))
        {
            // A match runs every shot in a simulation of its own, which names its features afresh.
            _simulation = sim;
            _voicing = new EventVoicing(sim.FeatureName);
        }
        var position = e.Kind == EventKind.BallBall ? (Position(sim, e.A) + Position(sim, e.B)) * 0.5 : Position(sim, e.A);
        if (_voicing!.Voice(e, position, _physics.LastShot) is { } cue)
        {
            Output.Play(cue);
        }
    }

    private static Core.Mathematics.Vec3 Position(Simulation sim, Core.Balls.BallId id) =>
        sim.IndexOf(id) is var i and >= 0 ? sim.Balls[i].Position : Core.Mathematics.Vec3.Zero;

    /// <inheritdoc />
    protected override void PhysicsProcess(double dt)
    {
        // After the physics node's step (it was added to the tree first).
        var balls = _physics!.Simulation.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            Output.SetRolling(i, ShotAudio.RollingSpeed(balls[i]), balls[i].Position);
        }
    }

    /// <summary>
    /// The sound's line on the HUD, or null: the volume or mute just set (for
    /// <see cref="FeedbackSeconds"/>), and always that there is no sound when there is no device.
    /// </summary>
    public string? StatusLine
    {
        get
        {
            string device = Output.IsSilent ? "no audio device" : "";
            if (_feedbackLeft <= 0)
            {
                return Output.IsSilent ? "Sound: off (no audio device)" : null;
            }
            string volume = string.Create(System.Globalization.CultureInfo.InvariantCulture, $"volume {Output.Volume * 100:0} %");
            string state = Output.Muted ? $"Sound: muted (U), {volume}" : $"Sound: {volume} (+/-)";
            return device.Length > 0 ? $"{state}, {device}" : state;
        }
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        UpdateListener();
        _feedbackLeft -= dt;
    }

    private void UpdateListener()
    {
        if (_camera is not null)
        {
            Output.SetListener(new Listener(_camera.Camera.Eye, _camera.Camera.Centre));
        }
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true } key)
        {
            return false;
        }
        switch (key.Key)
        {
            case Key.Plus:
                Output.Volume = MathF.Round(Math.Min(1, Output.Volume + VolumeStep), 2);
                Output.Muted = false;
                _feedbackLeft = FeedbackSeconds;
                return true;
            case Key.Minus:
                Output.Volume = MathF.Round(Math.Max(0, Output.Volume - VolumeStep), 2);
                _feedbackLeft = FeedbackSeconds;
                return true;
            case Key.U:
                Output.Muted = !Output.Muted;
                _feedbackLeft = FeedbackSeconds;
                return true;
            default:
                return false;
        }
    }
}
