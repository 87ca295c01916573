using Billiards.App.Audio;
using Billiards.App.Game;
using Billiards.App.Input;
using Billiards.App.Platform;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Audio;

/// <summary>An output that records what the game asks of it.</summary>
internal sealed class RecordingAudio : IAudioOutput
{
    public List<SoundCue> Cues { get; } = [];

    public List<Listener> Listeners { get; } = [];

    public Dictionary<int, double> Rolling { get; } = [];

    public double MaxRollingSpeed { get; private set; }

    public bool IsSilent => false;

    public float Volume { get; set; } = AudioPlayer.DefaultVolume;

    public bool Muted { get; set; }

    public void Play(in SoundCue cue) => Cues.Add(cue);

    public void SetListener(Listener listener) => Listeners.Add(listener);

    public void SetRolling(int ball, double speed, Vec3 position)
    {
        Rolling[ball] = speed;
        MaxRollingSpeed = Math.Max(MaxRollingSpeed, speed);
    }

    public void Dispose()
    {
    }
}

public sealed class AudioNodeTests
{
    private static (GameWorld World, RecordingAudio Audio) Start(string scene)
    {
        var loaded = SceneLoader.Load(AssetFolder.Scene(scene));
        var world = GameSceneBuilder.Build(loaded, SimulationFactory.Create);
        world.Tree.Start();
        var audio = new RecordingAudio();
        // As the play verb does: the node joins the started tree.
        world.Tree.Root.AddChild(new AudioNode(audio));
        return (world, audio);
    }

    private static void RunUntilRest(GameWorld world) => RunWhile(world, () => world.Physics.IsRolling);

    // Frames (a physics step and a process each) while the condition holds, at most 250 s of them.
    private static void RunWhile(GameWorld world, Func<bool> condition)
    {
        for (int i = 0; i < 250 * 60 && condition(); i++)
        {
            world.Tree.PhysicsProcess(world.Loop.Dt);
            world.Tree.Process(world.Loop.Dt);
        }
    }

    [Fact]
    public void TheGameVoicesTheBreakExactlyAsRenderAudioDoes()
    {
        var (world, audio) = Start("eight-ball-break.json");
        RunUntilRest(world);
        var offline = ShotAudio.Score(SceneLoader.Load(AssetFolder.Scene("eight-ball-break.json")));
        Assert.Equal(offline.Cues.Count, audio.Cues.Count);
        Assert.Equal(SoundKind.CueStrike, audio.Cues[0].Kind);
        for (int i = 0; i < audio.Cues.Count; i++)
        {
            var game = audio.Cues[i];
            var render = offline.Cues[i];
            Assert.Equal((render.Time, render.Kind, render.Speed, render.Rattle, render.Seed), (game.Time, game.Kind, game.Speed, game.Rattle, game.Seed));
            // Placed where the balls were at the end of the event's step: within one step's travel.
            Assert.True((render.Position - game.Position).Length < 0.05, $"cue {i} placed {(render.Position - game.Position).Length:F3} m off");
        }
    }

    [Fact]
    public void RollingFollowsTheBallsAndFallsSilentAtRest()
    {
        var (world, audio) = Start("eight-ball-break.json");
        RunUntilRest(world);
        Assert.True(audio.MaxRollingSpeed > 1, "the break's balls roll fast");
        Assert.All(audio.Rolling.Values, speed => Assert.Equal(0, speed));
    }

    // Plays the instant replay of the shot just run, frame by frame, until it ends.
    private static void WatchReplay(GameWorld world, InstantReplayNode instant, Action? afterFirstFrame = null)
    {
        Assert.True(instant.Start());
        world.Tree.Process(world.Loop.Dt);
        afterFirstFrame?.Invoke();
        RunWhile(world, () => instant.Time < instant.Duration);
    }

    [Fact]
    public void TheInstantReplaySoundsAsTheShotDid()
    {
        var (world, audio) = Start("eight-ball-break.json");
        RunUntilRest(world);
        var shot = audio.Cues.ToList();
        audio.Cues.Clear();
        WatchReplay(world, world.Tree.Find<InstantReplayNode>()!);
        // The same shot, re-simulated bit for bit: the same strike and collisions, voiced the same.
        Assert.Equal(shot.Count, audio.Cues.Count);
        for (int i = 0; i < shot.Count; i++)
        {
            Assert.Equal((shot[i].Time, shot[i].Kind, shot[i].Speed, shot[i].Rattle, shot[i].Seed), (audio.Cues[i].Time, audio.Cues[i].Kind, audio.Cues[i].Speed, audio.Cues[i].Rattle, audio.Cues[i].Seed));
        }
        Assert.True(audio.MaxRollingSpeed > 1, "the replayed balls roll");
    }

    [Fact]
    public void AReplayScrubbedAheadVoicesOnlyWhatItShowsAfterTheScrub()
    {
        var (world, audio) = Start("eight-ball-break.json");
        RunUntilRest(world);
        var shot = audio.Cues.ToList();
        audio.Cues.Clear();
        var instant = world.Tree.Find<InstantReplayNode>()!;
        const double scrubTo = 1.0;
        double strikeTime = shot[0].Time;
        WatchReplay(world, instant, () =>
        {
            instant.SeekTo(scrubTo);
            instant.TogglePause();
        });
        // The strike and the first frame's events, then only those after the scrub's time.
        var expected = shot.Where(c => c.Time - strikeTime <= world.Loop.Dt * 2 || c.Time - strikeTime > scrubTo).ToList();
        Assert.True(expected.Count < shot.Count, "the scrub skips some of the break's collisions");
        Assert.Equal(expected.Select(c => (c.Time, c.Kind, c.Seed)), audio.Cues.Select(c => (c.Time, c.Kind, c.Seed)));
    }

    [Fact]
    public void ThePausedReplayIsSilent()
    {
        var (world, audio) = Start("eight-ball-break.json");
        RunUntilRest(world);
        var instant = world.Tree.Find<InstantReplayNode>()!;
        Assert.True(instant.Start());
        for (int i = 0; i < 30; i++)
        {
            world.Tree.Process(world.Loop.Dt);
        }
        Assert.True(audio.Rolling.Values.Any(v => v > 0), "the balls are heard rolling half a second in");
        world.Tree.Input(new KeyInput(0, Key.Space, true));
        Assert.True(instant.IsPaused);
        int cues = audio.Cues.Count;
        int frames = 0;
        RunWhile(world, () => frames++ < 30);
        Assert.Equal(cues, audio.Cues.Count);
        Assert.All(audio.Rolling.Values, speed => Assert.Equal(0, speed));
    }

    [Fact]
    public void TheListenerIsTheCamera()
    {
        var (world, audio) = Start("eight-ball-break.json");
        world.Tree.Process(0.016);
        var camera = world.Tree.Find<Billiards.App.Camera.CameraNode>()!.Camera;
        Assert.Equal(new Listener(camera.Eye, camera.Centre), audio.Listeners[^1]);
    }

    [Fact]
    public void PlusAndMinusSetTheVolumeAndUMutes()
    {
        var (world, audio) = Start("eight-ball.json");
        void Press(Key key) => world.Tree.Input(new KeyInput(0, key, true));
        Press(Key.Minus);
        Assert.Equal(0.7f, audio.Volume, 3);
        Press(Key.Plus);
        Press(Key.Plus);
        Press(Key.Plus);
        Assert.Equal(1f, audio.Volume, 3);
        Press(Key.U);
        Assert.True(audio.Muted);
        Press(Key.U);
        Assert.False(audio.Muted);
        for (int i = 0; i < 12; i++)
        {
            Press(Key.Minus);
        }
        Assert.Equal(0f, audio.Volume);
    }

    [Fact]
    public void TheHelpOverlayNamesTheSoundKeys()
    {
        Assert.Contains(Billiards.App.Hud.HelpText.Lines, l => l.Contains("volume", StringComparison.Ordinal) && l.Contains('+'));
        Assert.Contains(Billiards.App.Hud.HelpText.Lines, l => l.TrimStart().StartsWith('U') && l.Contains("mute", StringComparison.Ordinal));
    }
}

public sealed class SoundStateTests
{
    private static string? SoundLine(Billiards.App.Tests.Game.TestGame game) =>
        game.Frame().Hud!.Lines.SingleOrDefault(l => l.StartsWith("Sound: ", StringComparison.Ordinal));

    [Fact]
    public void WithoutADeviceTheHudSaysSoAndShowsTheVolumeKeysEffectForAMoment()
    {
        using var game = new Billiards.App.Tests.Game.TestGame();
        game.World.Tree.Root.AddChild(new AudioNode(new SilentAudio()));
        Assert.Equal("Sound: off (no audio device)", SoundLine(game));
        game.Window.Press(Key.Plus);
        Assert.Equal($"Sound: volume {(AudioPlayer.DefaultVolume + AudioNode.VolumeStep) * 100:0} % (+/-), no audio device", SoundLine(game));
        for (int i = 0; i < 3 * 64; i++)
        {
            game.Frame();
        }
        Assert.Equal("Sound: off (no audio device)", SoundLine(game));
    }

    [Fact]
    public void WithADeviceMuteAndVolumeShowForAMomentAndThenTheLineGoes()
    {
        using var game = new Billiards.App.Tests.Game.TestGame();
        game.World.Tree.Root.AddChild(new AudioNode(new RecordingAudio()));
        Assert.Null(SoundLine(game));
        game.Window.Press(Key.U);
        Assert.Equal($"Sound: muted (U), volume {AudioPlayer.DefaultVolume * 100:0} %", SoundLine(game));
        game.Window.Press(Key.Minus);
        Assert.Equal($"Sound: muted (U), volume {(AudioPlayer.DefaultVolume - AudioNode.VolumeStep) * 100:0} %", SoundLine(game));
        game.Window.Press(Key.Plus);   // + also unmutes
        Assert.Equal($"Sound: volume {AudioPlayer.DefaultVolume * 100:0} % (+/-)", SoundLine(game));
        for (int i = 0; i < 3 * 64; i++)
        {
            game.Frame();
        }
        Assert.Null(SoundLine(game));
    }
}
