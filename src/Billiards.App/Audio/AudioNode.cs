using Billiards.App.Camera;
using Billiards.App.Game;
using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
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
/// While a shot is shown played again (<see cref="IShowsShot"/>: the instant replay, a game
/// record's playback), the sound is that shot's: its strike and collisions as the replay's time
/// passes them, and its balls' rolling; scrubbing it voices nothing the scrub passes over.
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
    private readonly List<IShowsShot> _shows = [];
    private bool _showsFound;
    private ShotReplay? _shown;
    private double _shownTime;
    private int _shownEvent;
    private int _shownSeeks;
    private EventVoicing? _shownVoicing;

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
        if (_voicing!.Voice(e, Where(e, sim.IndexOf(e.A), sim.IndexOf(e.B), sim.Balls), _physics.LastShot) is { } cue)
        {
            Output.Play(cue);
        }
    }

    /// <inheritdoc />
    protected override void PhysicsProcess(double dt)
    {
        // After the physics node's step (it was added to the tree first).
        if (Shown() is not null)
        {
            // The shot shown is heard instead, frame by frame as it is shown (Process).
            return;
        }
        var balls = _physics!.Simulation.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            Output.SetRolling(i, ShotAudio.RollingSpeed(balls[i]), balls[i].Position);
        }
    }

    private IShowsShot? Shown()
    {
        if (!_showsFound && Tree is { } tree)
        {
            // The nodes that show shots are made with the game, before the first frame.
            _showsFound = true;
            Collect(tree.Root, _shows);
        }
        foreach (var show in _shows)
        {
            if (show.ShownShot is not null)
            {
                return show;
            }
        }
        return null;
    }

    private static void Collect(Node node, List<IShowsShot> found)
    {
        if (node is IShowsShot show)
        {
            found.Add(show);
        }
        foreach (var child in node.Children)
        {
            Collect(child, found);
        }
    }

    // The shown shot's events from the time last heard to its time now, and its balls' rolling.
    private void VoiceShown(ShotReplay replay, ShotSpec? strike, int seeks)
    {
        double now = replay.Time;
        bool another = !ReferenceEquals(replay, _shown);
        // Played on (at any speed): heard; scrubbed or stepped to a time: what it passed over is not.
        bool heard = another || seeks == _shownSeeks;
        _shownSeeks = seeks;
        bool fresh = another || now < _shownTime;
        var current = replay.Current;
        if (fresh)
        {
            _shown = replay;
            _shownVoicing = new EventVoicing(replay.FeatureName);
            _shownEvent = 0;
            if (replay.StrikeEvent is { } hit)
            {
                Voice(replay, current, hit, strike, heard);
            }
        }
        var events = replay.Events;
        for (; _shownEvent < events.Count && replay.EventTime(events[_shownEvent]) <= now; _shownEvent++)
        {
            // A skipped event is voiced unheard: the variations of those after it stay the shot's own.
            Voice(replay, current, events[_shownEvent], strike, heard);
        }
        // Paused (the time stands): no rolling; else the balls' as shown.
        bool moving = now > _shownTime || fresh;
        _shownTime = now;
        for (int i = 0; i < current.Length; i++)
        {
            Output.SetRolling(i, moving ? ShotAudio.RollingSpeed(current[i]) : 0, current[i].Position);
        }
    }

    private void Voice(ShotReplay replay, ReadOnlySpan<BallState> balls, in SimEvent e, ShotSpec? strike, bool heard)
    {
        if (_shownVoicing!.Voice(e, Where(e, replay.IndexOf(e.A), replay.IndexOf(e.B), balls), strike) is { } cue && heard)
        {
            Output.Play(cue);
        }
    }

    // Where an event sounds (m): between the two balls of a click, else at its ball; the balls at
    // indexes a and b (-1: none) of those as they stand now.
    private static Core.Mathematics.Vec3 Where(in SimEvent e, int a, int b, ReadOnlySpan<BallState> balls) =>
        e.Kind == EventKind.BallBall ? (At(balls, a) + At(balls, b)) * 0.5 : At(balls, a);

    private static Core.Mathematics.Vec3 At(ReadOnlySpan<BallState> balls, int i) => i >= 0 ? balls[i].Position : Core.Mathematics.Vec3.Zero;

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
        if (Shown() is { ShownShot: { } replay } show)
        {
            VoiceShown(replay, show.ShownStrike, show.ShownSeeks);
        }
        else
        {
            _shown = null;
        }
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
        // On a line of the menu that takes what is typed, U and - are letters, not the sound's keys.
        if (e is not KeyInput { Pressed: true } key || FindInTree<Hud.MenuNode>() is { IsTyping: true })
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
