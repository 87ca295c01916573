using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// A trivial simulation for game tests: balls move in straight lines and slow down at a constant
/// rate; a strike gives the cue ball the cue's speed along the aim. No collisions.
/// </summary>
internal sealed class FakeSimulation : Simulation
{
    private readonly BallState[] _balls;
    private readonly BallState[] _initial;

    public FakeSimulation(Scene scene)
        : base("fake", scene.Physics.Integrator, scene.Physics.Dt, scene.Table, scene.Balls.Select(b => b.Id).ToList())
    {
        _initial = scene.Balls.Select(b => new BallState
        {
            Position = b.Position,
            Velocity = b.Velocity,
            Orientation = Quaternion.Identity,
            State = MotionState.Stationary,
            Pocket = -1,
        }).ToArray();
        _balls = (BallState[])_initial.Clone();
    }

    public override void Reset()
    {
        _initial.CopyTo(_balls, 0);
        Time = 0;
        StepCount = 0;
        Events.Clear();
    }

    /// <summary>Slowing down of every moving ball (m/s²); 0 keeps them moving until <see cref="StopAll"/>.</summary>
    public double Deceleration { get; set; } = 2.0;

    public List<ShotSpec> Strikes { get; } = [];

    public BallState[] State => _balls;

    public override ReadOnlySpan<BallState> Balls => _balls;

    public override bool IsAtRest => _balls.All(b => b.IsPocketed || b.Velocity == Vec3.Zero);

    public override void Step()
    {
        for (int i = 0; i < _balls.Length; i++)
        {
            ref var b = ref _balls[i];
            if (b.IsPocketed || b.Velocity == Vec3.Zero)
            {
                continue;
            }
            b.Position += b.Velocity * Dt;
            double speed = b.Velocity.Length - Deceleration * Dt;
            b.Velocity = speed > 0 ? b.Velocity * (speed / b.Velocity.Length) : Vec3.Zero;
            b.State = speed > 0 ? MotionState.Rolling : MotionState.Stationary;
        }
        Time += Dt;
        StepCount++;
    }

    protected override void ApplyStrike(int cue, ShotSpec shot)
    {
        Strikes.Add(shot);
        double a = shot.AimDeg * Math.PI / 180;
        _balls[cue].Velocity = new Vec3(Math.Cos(a), Math.Sin(a), 0) * shot.Speed;
        _balls[cue].State = MotionState.Sliding;
    }

    /// <summary>Logs a collision of ball <paramref name="a"/> with ball <paramref name="b"/> (the balls do not move).</summary>
    public void Hit(BallId a, BallId b) => Events.Add(new SimEvent(Time, EventKind.BallBall, a, b, 0, 1));

    /// <summary>Drops a ball into pocket <paramref name="pocket"/> (by default the first) and logs the event.</summary>
    public void Pocket(BallId id, int pocket = 0)
    {
        int i = IndexOf(id);
        _balls[i].State = MotionState.Pocketed;
        _balls[i].Velocity = Vec3.Zero;
        _balls[i].Pocket = pocket;
        Events.Add(new SimEvent(Time, EventKind.BallPocket, id, id, pocket, 0));
    }

    public void StopAll()
    {
        for (int i = 0; i < _balls.Length; i++)
        {
            _balls[i].Velocity = Vec3.Zero;
        }
    }

    public override string FeatureName(EventKind kind, int feature) => "fake";

    public override double BallRadius => PhysicsParams.DefaultRadius;

    public override Billiards.Core.Table.CushionId CushionOf(int feature) => Billiards.Core.Table.CushionId.None;

    protected override void PutBall(int index, Vec3 position)
    {
        _balls[index] = _balls[index] with { Position = position, Velocity = Vec3.Zero, State = MotionState.Stationary, Pocket = -1 };
    }

    protected override void TakeOut(int index)
    {
        _balls[index] = _balls[index] with { Velocity = Vec3.Zero, State = MotionState.Pocketed, Pocket = -1 };
    }
}

/// <summary>A window that only exists in memory: tests raise its events and read what the game asked of it.</summary>
internal sealed class FakeWindow : IGameWindow
{
    public event Action<Key>? KeyDown;
    public event Action<Key>? KeyUp;
    public event Action<Vector2>? MouseMove;
    public event Action<MouseButton>? MouseDown;
    public event Action<MouseButton>? MouseUp;
    public event Action<float>? Scroll;
#pragma warning disable CS0067 // the game does not listen to Resize; it reads FramebufferSize per frame
    public event Action<int, int>? Resize;
#pragma warning restore CS0067

    public (int Width, int Height) FramebufferSize { get; set; } = (800, 600);

    public List<bool> CaptureCalls { get; } = [];

    public bool Captured => CaptureCalls.Count > 0 && CaptureCalls[^1];

    public int FullscreenToggles { get; private set; }

    public bool Closed { get; private set; }

    public void SetMouseCaptured(bool captured) => CaptureCalls.Add(captured);

    public void ToggleFullscreen() => FullscreenToggles++;

    public void Close() => Closed = true;

    public void Press(Key key)
    {
        KeyDown?.Invoke(key);
        KeyUp?.Invoke(key);
    }

    public void Hold(Key key) => KeyDown?.Invoke(key);

    public void Release(Key key) => KeyUp?.Invoke(key);

    public void MoveTo(float x, float y) => MouseMove?.Invoke(new Vector2(x, y));

    public void Down(MouseButton button = MouseButton.Left) => MouseDown?.Invoke(button);

    public void Up(MouseButton button = MouseButton.Left) => MouseUp?.Invoke(button);

    public void Wheel(float notches) => Scroll?.Invoke(notches);
}

/// <summary>A frame loop that runs a fixed number of frames, advancing a manual clock between them.</summary>
internal sealed class FakeFrameLoop(ManualClock clock, int frames, double frameSeconds) : IFrameLoop
{
    public int FramesRun { get; private set; }

    public void Run(Action frame)
    {
        for (int i = 0; i < frames; i++)
        {
            clock.Advance(frameSeconds);
            frame();
            FramesRun++;
        }
    }
}

internal sealed class RecordingRenderer : IFrameRenderer
{
    public List<RenderFrame> Frames { get; } = [];

    public void Draw(RenderFrame frame) => Frames.Add(frame);
}

/// <summary>Scenes for game tests, parsed from JSON (no file, no physics).</summary>
internal static class TestScenes
{
    /// <summary>dt = 1/256 s, exact in binary, so step counts are exact.</summary>
    public const double Dt = 1.0 / 256;

    /// <summary>9 ft table; cue ball on the head spot (-0.635, 0), the 1 ball on the foot spot.</summary>
    public static Scene TwoBalls(string? rules = null, bool withShot = false, bool withCue = true)
    {
        string balls = withCue
            ? """[ { "id": "cue", "position": [-0.635, 0.0] }, { "id": "1", "position": [0.635, 0.0] } ]"""
            : """[ { "id": "1", "position": [0.635, 0.0] } ]""";
        string extra = (rules is null ? "" : $", \"rules\": \"{rules}\"")
            + (withShot ? """, "shot": { "speed": 2.0, "aim_deg": 0.0 }""" : "");
        string json = $$"""
            { "format": "billiards-scene/1", "name": "test",
              "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
              "balls": {{balls}}{{extra}} }
            """;
        return SceneLoader.Parse(json, "test.json");
    }

    public static FakeSimulation Create(Scene scene) => new(scene);
}

/// <summary>A game host on a fake window, a manual clock and fake physics.</summary>
internal sealed class TestGame : IDisposable
{
    public TestGame(Scene? scene = null, MatchSetup? match = null, PracticeSetup? practice = null, Func<Scene, Billiards.Core.Physics.Simulation>? create = null)
    {
        Window = new FakeWindow();
        Clock = new ManualClock();
        Scene = scene ?? TestScenes.TwoBalls();
        Host = new GameHost(Scene, create ?? (s => Simulation = new FakeSimulation(s)), Window, Clock, match, practice);
    }

    public Scene Scene { get; }

    public FakeWindow Window { get; }

    public ManualClock Clock { get; }

    public GameHost Host { get; }

    public FakeSimulation Simulation { get; private set; } = null!;

    public GameWorld World => Host.World;

    /// <summary>Advances the clock and runs one frame.</summary>
    public RenderFrame Frame(double seconds = 1.0 / 64)
    {
        Clock.Advance(seconds);
        return Host.RunFrame();
    }

    /// <summary>Runs frames until the balls rest.</summary>
    public void RunUntilRest(int maxFrames = 10_000)
    {
        for (int i = 0; i < maxFrames && World.Physics.IsRolling; i++)
        {
            Frame();
        }
        Assert.False(World.Physics.IsRolling, "the balls never came to rest");
    }

    public void Dispose() => Host.Dispose();
}
