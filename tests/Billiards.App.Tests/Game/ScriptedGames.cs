using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// What the scripted-game tests share: a shipped input script played through <c>play</c> to its
/// game record, headless (a fake window and a manual clock, frames of a given length) or in a
/// real GLFW window (under Xvfb when there is no display).
/// </summary>
internal static class ScriptedGames
{
    /// <summary>
    /// Plays <paramref name="script"/> headless with frames <paramref name="frameSeconds"/> long
    /// (the frame index to its length, s), on <paramref name="scene"/> (default: the rules' scene);
    /// returns the game record as written.
    /// </summary>
    public static string PlayHeadless(string script, string rules, string players, Func<int, double> frameSeconds, string? scene = null)
    {
        string record = Path.Combine(Path.GetTempPath(), $"record-{Guid.NewGuid():N}.json");
        try
        {
            var clock = new ManualClock();
            var window = new FakeWindow { FramebufferSize = (1280, 720) };
            var loop = new UntilClosedLoop(clock, window, frameSeconds);
            int code = PlayCommand.Play(scene, _ => new GamePlatform(window, loop, new NullFrameRenderer()), SimulationFactory.Create, clock,
                new PlayCommand.PlayOptions(script, null) { Rules = rules, Players = players, Record = record });
            Assert.Equal(0, code);
            Assert.True(window.Closed, "the script never ended");
            return File.ReadAllText(record);
        }
        finally
        {
            File.Delete(record);
        }
    }

    /// <summary>Plays <paramref name="script"/> headless with frames of one length (s).</summary>
    public static string PlayHeadless(string script, string rules, string players, double frameSeconds) =>
        PlayHeadless(script, rules, players, _ => frameSeconds);

    /// <summary>
    /// Frame lengths as a loaded machine gives them (seeded): mostly a 60th of a second, now and
    /// then a stall of up to <paramref name="longest"/> seconds, so that events fall into frames
    /// in every grouping.
    /// </summary>
    public static Func<int, double> Jitter(ulong seed, double longest)
    {
        var random = new Random((int)seed);
        return _ => random.Next(4) == 0 ? 0.001 + (random.NextDouble() * longest) : 1.0 / 60;
    }

    /// <summary>
    /// Plays <paramref name="script"/> in a real window through <c>play</c>; returns the game
    /// record as written, and the HUD of every frame drawn to <paramref name="seen"/> when given.
    /// </summary>
    public static string PlayInWindow(string script, string rules, string players, Action<RenderFrame>? seen = null, string? stats = null, string? scene = null)
    {
        TestDisplay.Ensure();
        string record = Path.Combine(Path.GetTempPath(), $"record-{Guid.NewGuid():N}.json");
        try
        {
            int code = PlayCommand.Play(scene, title =>
            {
                var platform = PlatformWiring.Open(title);
                return seen is null ? platform : platform with { Renderer = new Watching(platform.Renderer, seen) };
            }, options: new PlayCommand.PlayOptions(script, stats) { Rules = rules, Players = players, Record = record });
            Assert.Equal(0, code);
            return File.ReadAllText(record);
        }
        finally
        {
            File.Delete(record);
        }
    }

    /// <summary>Checks that a game record replays shot for shot (<c>replay --verify</c>).</summary>
    public static void AssertReplays(string recordText)
    {
        var record = GameRecordFile.Parse(recordText, "record.json");
        var report = GameRecordFile.Verify(record, out _);
        Assert.Null(report.FirstDifference);
        Assert.Equal(record.Shots.Count, report.Same);
        Assert.Equal(report.Shots, report.Same);
    }

    private sealed class Watching(IFrameRenderer inner, Action<RenderFrame> seen) : IFrameRenderer
    {
        public void Draw(RenderFrame frame)
        {
            seen(frame);
            inner.Draw(frame);
        }
    }
}

/// <summary>A frame loop that runs frames on a manual clock until the window closes, each as long as <c>frameSeconds</c> says.</summary>
internal sealed class UntilClosedLoop(ManualClock clock, FakeWindow window, Func<int, double> frameSeconds, int maxFrames = 1_000_000) : IFrameLoop
{
    public UntilClosedLoop(ManualClock clock, FakeWindow window, double frameSeconds, int maxFrames = 1_000_000)
        : this(clock, window, _ => frameSeconds, maxFrames)
    {
    }

    public void Run(Action frame)
    {
        for (int i = 0; i < maxFrames && !window.Closed; i++)
        {
            clock.Advance(frameSeconds(i));
            frame();
        }
    }
}
