using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The instant replay from the shipped script <c>assets/scripts/instant-replay.json</c>, played
/// headless through <c>play</c>: a break, the tracking lines on, the replay at 1/4 speed, paused,
/// stepped to the next collision, scrubbed back and left. The replay is the shot itself: it ends
/// where the shot ended, bit for bit.
/// </summary>
public class InstantReplayTests
{
    private static string Script => Path.Combine(AssetFolder.Assets, "scripts", "instant-replay.json");

    private sealed record Sample(double Clock, bool Active, bool Paused, double Speed, double Time, int Shapes, int Balls);

    private static (List<Sample> Samples, GameHost Host) Play(double frameSeconds)
    {
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var samples = new List<Sample>();
        GameHost? host = null;
        InstantReplayNode? replay = null;
        var renderer = new WatchingRenderer(frame =>
        {
            if (replay is { } r)
            {
                samples.Add(new Sample(clock.Now, r.IsActive, r.IsPaused, r.Speed, r.Time, r.Shapes(frame).Count, frame.Balls.Count));
            }
        });
        int code = PlayCommand.Play(AssetFolder.Scene("eight-ball.json"), _ => new GamePlatform(window, new UntilClosedLoop(clock, window, frameSeconds), renderer), SimulationFactory.Create, clock,
            new PlayCommand.PlayOptions(Script, null)
            {
                Players = "human,human",
                Started = h =>
                {
                    host = h;
                    replay = h.Tree.Root.GetInTree<InstantReplayNode>();
                },
            });
        Assert.Equal(0, code);
        Assert.True(window.Closed, "the script never ended");
        return (samples, host!);
    }

    [Fact]
    public void TheScriptReplaysTheBreakAtAQuarterSpeedAndTheReplayEndsWhereTheBreakEnded()
    {
        var (samples, host) = Play(1.0 / 60);
        var replay = host.Tree.Root.GetInTree<InstantReplayNode>();
        var match = host.Tree.Root.GetInTree<MatchNode>();
        var shown = replay.Replay!;

        // The replay ran at 1/4 speed: while it played, its clock moved a quarter of the frames' time.
        var playing = samples.Where(s => s.Active && !s.Paused && s.Speed == 0.25).ToList();
        Assert.True(playing.Count > 120, $"{playing.Count} frames at 1/4 speed");
        for (int k = 1; k < playing.Count; k++)
        {
            double frames = playing[k].Clock - playing[k - 1].Clock;
            double moved = playing[k].Time - playing[k - 1].Time;
            if (frames < 0.02)
            {
                Assert.Equal(frames * 0.25, moved, 9);
            }
        }
        // Paused (Space), then N stepped to a collision, Left scrubbed 0.1 s back, R left the replay.
        var paused = samples.Where(s => s.Active && s.Paused).ToList();
        Assert.NotEmpty(paused);
        Assert.Contains(paused, s => shown.Marks.Any(m => Math.Abs(m.Time - s.Time) < 1e-12));
        Assert.Contains(paused, s => shown.Marks.Any(m => Math.Abs(m.Time - 0.1 - s.Time) < 1e-9));
        Assert.False(replay.IsActive);
        Assert.True(samples[^1].Active == false);

        // The tracking lines were drawn during the replay, and every ball of the table with them.
        Assert.All(samples.Where(s => s.Active), s => Assert.Equal(shown.Ids.Count, s.Balls));
        Assert.Contains(samples, s => s.Active && s.Shapes > 20);

        // The replay is the shot: its end is the table the referee judged, bit for bit.
        var atRest = match.Session.Game!.Shots[0].After;
        foreach (var (id, position) in atRest)
        {
            int i = shown.Ids.ToList().IndexOf(id);
            Assert.Equal(position.X, shown.Final[i].Position.X);
            Assert.Equal(position.Y, shown.Final[i].Position.Y);
        }
        // Out-of-play balls aside, the shot's balls are all on the judged table.
        Assert.Equal(atRest.Count, shown.Final.Count(b => !b.IsOutOfPlay));
    }

}

/// <summary>A renderer that draws nothing and hands each frame to a callback.</summary>
internal sealed class WatchingRenderer(Action<RenderFrame> watch) : IFrameRenderer
{
    public void Draw(RenderFrame frame) => watch(frame);
}
