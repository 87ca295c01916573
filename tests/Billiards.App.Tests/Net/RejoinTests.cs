using System.Collections.Concurrent;
using System.Net;
using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Net;
using Billiards.App.Platform;
using Billiards.App.Tests.Game;

namespace Billiards.App.Tests.Net;

/// <summary>
/// A joiner whose host dropped comes back by itself: the host's connection to it is cut (the host
/// still listening, its game going on), the joiner tries the host again, the host admits it as a
/// joiner coming back and sends its game, and both stand at the same shot. The real host and join
/// code on fake windows, each on its own thread and clock; every wait is bounded.
/// </summary>
[Collection("Network")]
public class RejoinTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(2);

    // Anna breaks at 8 m/s (a legal break) or at 1 m/s (too soft: Ben, the joiner, is to choose).
    [Theory]
    [InlineData(Key.W, 20)]
    [InlineData(Key.Q, 8)]
    public async Task AJoinerWhoseHostDroppedTakesUpTheGameAgainWhenTheHostIsThere(Key power, int presses)
    {
        var log = new ConcurrentQueue<string>();
        var listening = new TaskCompletionSource<NetHost>(TaskCreationOptions.RunContinuationsAsynchronously);
        var host = new Side();
        var join = new Side();
        var hostRun = BackgroundWork.RunBlocking(() => NetCommands.Host(
            new NetCommands.HostOptions(null, LoopbackGame.Code, "Anna,Ben", null, null, null, null) { AnyPort = true, Address = IPAddress.Loopback, Listening = listening.SetResult, Clock = host.Clock },
            TextWriter.Null, line => log.Enqueue($"host {line}"), host.Open, h => host.Game = h));
        var listener = await listening.Task.WaitAsync(Bound);
        var joinRun = BackgroundWork.RunBlocking(() => NetCommands.Join($"127.0.0.1:{listener.Port}", LoopbackGame.Code, new PlayCommand.PlayOptions(null, null) { Started = h => join.Game = h },
            line => log.Enqueue($"join {line}"), join.Open, clock: join.Clock));
        try
        {
            Until(() => join.Ask(() => join.Online is { Watch.State: LinkState.Connected }) && host.Ask(() => host.Online is { Watch.State: LinkState.Connected }), "never connected", log);
            // Anna breaks; both tables come to rest after it.
            host.Do(() =>
            {
                // Straight up the table: the camera may still be turning to the break, and its
                // turn would be the aim at whichever frame the stroke came.
                host.Game!.Tree.Root.FindInTree<MatchNode>()!.AimAt(0);
                for (int i = 0; i < presses; i++)
                {
                    host.Window.Press(power);
                }
                host.Window.Press(Key.Space);
            });
            Until(() => host.Ask(() => Rested(host)) && join.Ask(() => Rested(join)), "the break never came to rest on both sides", log);
            Assert.Equal(0, host.Ask(() => host.Session!.Game.Shots[0].Input.Shot.AimDeg), 9);
            // The connection is cut at the host; its game waits, it still listens.
            host.Do(() => listener.Peer!.Dispose());
            Until(() => join.Ask(() => join.Online!.Watch is { Returns: 1, State: LinkState.Connected }) && host.Ask(() => host.Online!.Watch.Returns == 1), "the joiner never came back", log);
            Until(() => log.Any(l => l.StartsWith("join net: resync: took the host's game (1 shots)", StringComparison.Ordinal)), "the joiner never took the host's game", log);
            Until(() => join.Ask(() => Rested(join) && join.Session!.Held is null), "the joiner's game did not resume", log);
            Assert.Contains(log, l => l.StartsWith("join net: back with the host (1 shots there)", StringComparison.Ordinal));
            var hostAfter = host.Ask(() => (host.Session!.Game.Shots[0].After, host.Session.State.Shooter));
            var joinAfter = join.Ask(() => (join.Session!.Game.Shots[0].After, join.Session.State.Shooter));
            Assert.Equal(hostAfter.Item1, joinAfter.Item1);
            Assert.Equal(hostAfter.Item2, joinAfter.Item2);
            // An option left to be chosen is the joiner's to choose there too, and its choice reaches the host.
            var options = host.Ask(() => host.Session!.PendingOptions.ToList());
            Assert.Equal(options, join.Ask(() => join.Session!.PendingOptions.ToList()));
            Assert.True((power == Key.Q) == (options.Count > 0), string.Join(",", options) + " / " + string.Join(" / ", log));
            if (options.Count > 0)
            {
                join.Do(() => join.Window.Press(Key.D1));
                Until(() => host.Ask(() => host.Session!.PendingOptions.Count == 0 && host.Session.Game.Shots[0].Input.Choice == options[0]), "the joiner's choice never reached the host", log);
                Assert.Equal(options[0], join.Ask(() => join.Session!.Game.Shots[0].Input.Choice));
            }
        }
        finally
        {
            host.Window.Close();
            join.Window.Close();
            await Task.WhenAll(hostRun, joinRun).WaitAsync(Bound);
        }
    }

    private static bool Rested(Side side) => side.Session is { IsShotRunning: false, Shots.Count: 1 };

    private static void Until(Func<bool> done, string what, ConcurrentQueue<string> log)
    {
        var until = DateTime.UtcNow + Bound;
        while (!done())
        {
            Assert.True(DateTime.UtcNow < until, $"{what}: {string.Join(" / ", log)}");
            Thread.Sleep(5);
        }
    }

    // One side's fake window and clock, frames a 60th of a second of game time each, and actions
    // the test hands to the game's own thread.
    private sealed class Side : IFrameLoop
    {
        private readonly ConcurrentQueue<Action> _actions = new();

        public ManualClock Clock { get; } = new();

        public FakeWindow Window { get; } = new() { FramebufferSize = (1280, 720) };

        public volatile GameHost? Game;

        public OnlineNode? Online => Game?.Tree.Root.FindInTree<OnlineNode>();

        public Billiards.Core.Rules.Session? Session => Game?.Tree.Root.FindInTree<MatchNode>()?.Session;

        public GamePlatform Open(string title) => new(Window, this, new NullFrameRenderer());

        public void Do(Action action) => _actions.Enqueue(action);

        // What the game's own thread answers between two frames (its state is not read from another thread).
        public T Ask<T>(Func<T> question)
        {
            var answer = new TaskCompletionSource<T>(TaskCreationOptions.RunContinuationsAsynchronously);
            Do(() => answer.SetResult(question()));
            return answer.Task.Wait(Bound) ? answer.Task.Result : throw new TimeoutException("the game did not answer");
        }

        public void Run(Action frame)
        {
            var until = DateTime.UtcNow + Bound;
            while (!Window.Closed && DateTime.UtcNow < until)
            {
                while (_actions.TryDequeue(out var action))
                {
                    action();
                }
                Clock.Advance(1.0 / 60);
                frame();
                Thread.Sleep(1);
            }
        }
    }
}
