using System.Collections.Concurrent;
using System.Net;
using System.Text.Json;
using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Net;
using Billiards.App.Platform;
using Billiards.App.Tests.Game;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Net;

/// <summary>
/// The host and join verbs end to end, headless: each side is the whole game (<c>host</c> or
/// <c>join</c> through <see cref="PlayCommand.Play"/>) on a fake window and its own clock, on its
/// own thread, connected over loopback. The shipped scripts
/// <c>assets/scripts/online-eight-ball-host.json</c> and <c>-join.json</c> (made by
/// <c>tools/game-script --split</c> from the whole 8-ball game of two people) play a whole game;
/// every wait is bounded.
/// </summary>
[Collection("Network")]
public class OnlineGameTests
{
    private const string Code = "K7PQ2M";
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(4);

    private static string Script(string side) => Path.Combine(AssetFolder.Assets, "scripts", $"online-eight-ball-{side}.json");

    [Fact]
    public async Task TheTwoScriptsPlayAWholeGameAndBothRecordsAreTheSameBytesAndReplay()
    {
        string hostRecord = Temp(), joinRecord = Temp();
        var log = new ConcurrentQueue<string>();
        try
        {
            var listening = new TaskCompletionSource<int>(TaskCreationOptions.RunContinuationsAsynchronously);
            var hostSide = new Side();
            var host = BackgroundWork.RunBlocking(() => NetCommands.Host(
                new NetCommands.HostOptions(null, Code, "Anna,Ben", null, Script("host"), hostRecord, null)
                {
                    AnyPort = true,
                    Address = IPAddress.Loopback,
                    Listening = l => listening.SetResult(l.Port),
                    Clock = hostSide.Clock,
                },
                TextWriter.Null, line => log.Enqueue($"host {line}"), hostSide.Open));
            int port = await listening.Task.WaitAsync(TimeSpan.FromSeconds(30));
            var joinSide = new Side();
            var join = BackgroundWork.RunBlocking(() => NetCommands.Join($"127.0.0.1:{port}", Code, new PlayCommand.PlayOptions(Script("join"), null) { Record = joinRecord },
                line => log.Enqueue($"join {line}"), joinSide.Open, clock: joinSide.Clock));
            var both = Task.WhenAll(host, join);
            Assert.Same(both, await Task.WhenAny(both, Task.Delay(Bound)));
            int[] codes = await both;
            Assert.Equal(new[] { 0, 0 }, codes);
            Assert.True(hostSide.Window.Closed && joinSide.Window.Closed);
            byte[] hostBytes = File.ReadAllBytes(hostRecord), joinBytes = File.ReadAllBytes(joinRecord);
            Assert.Equal(hostBytes, joinBytes);
            string text = File.ReadAllText(hostRecord);
            ScriptedGames.AssertReplays(text);
            using var doc = JsonDocument.Parse(text);
            var shots = doc.RootElement.GetProperty("shots");
            var last = shots[shots.GetArrayLength() - 1].GetProperty("ruling");
            // The whole game, as at one table (game-script --split says so of the shipped script):
            // Ben scratches on shot 3, and Anna (the host) pots the 8 in the called pocket on shot 16.
            Assert.True(last.GetProperty("game_over").GetBoolean());
            Assert.Equal(0, last.GetProperty("winner").GetInt32());
            Assert.Equal(16, shots.GetArrayLength());
            Assert.DoesNotContain(log, l => l.Contains("refused", StringComparison.Ordinal) || l.Contains("desync", StringComparison.Ordinal));
        }
        finally
        {
            File.Delete(hostRecord);
            File.Delete(joinRecord);
        }
    }

    private static string Temp() => Path.Combine(Path.GetTempPath(), $"online-{Guid.NewGuid():N}.json");

    // One side's fake window and clock, its frames a 60th of a second of game time paced by a
    // millisecond of real time (the other side runs meanwhile).
    private sealed class Side
    {
        public ManualClock Clock { get; } = new();

        public FakeWindow Window { get; } = new() { FramebufferSize = (1280, 720) };

        public GamePlatform Open(string title) => new(Window, new PacedLoop(Clock, Window), new NullFrameRenderer());
    }

    private sealed class PacedLoop(ManualClock clock, FakeWindow window) : IFrameLoop
    {
        public void Run(Action frame)
        {
            var until = DateTime.UtcNow + Bound;
            while (!window.Closed && DateTime.UtcNow < until)
            {
                clock.Advance(1.0 / 60);
                frame();
                Thread.Sleep(1);
            }
        }
    }
}
