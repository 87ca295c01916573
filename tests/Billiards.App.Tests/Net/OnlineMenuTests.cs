using System.Net;
using System.Text.RegularExpressions;
using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Net;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.App.Tests.Game;

namespace Billiards.App.Tests.Net;

/// <summary>
/// "Play online" in the start menu, end to end on fake windows: one game hosts through its menu
/// pages (Play online, Host a game, the game, Host) and shows its code; another joins through
/// its own (Play online, Join a game, the address and the code typed key by key, Join); both
/// then show the same game on loopback, and the host's break arrives on the joiner's table.
/// Each side runs on its own thread and clock; every wait is bounded.
/// </summary>
[Collection("Network")]
public partial class OnlineMenuTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(2);

    [Fact]
    public async Task TheMenuHostsAGameShowingItsCodeAndAnotherMenuJoinsItByTypingTheAddressAndTheCode()
    {
        string folder = Path.Combine(Path.GetTempPath(), $"online-menu-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        try
        {
            var hosting = new TaskCompletionSource<(string Code, int Port)>(TaskCreationOptions.RunContinuationsAsynchronously);
            HudInfo? codePage = null, entryPage = null;
            var host = new Side(
            [
                Click("Play online"),
                Click("Host a game"),
                Click("9-ball"),
                Click("Host"),
                (hud, _) =>
                {
                    // The code, large, and where this machine listens.
                    if (hud.Labels?.FirstOrDefault(l => l.Size == 3 && l.Text != "Billiards") is not { Text: var code } || !MessageCodec.IsCode(code))
                    {
                        return false;
                    }
                    var port = hud.Labels.Select(l => PortOf().Match(l.Text)).First(m => m.Success);
                    codePage = hud;
                    hosting.SetResult((code, int.Parse(port.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture)));
                    return true;
                },
                // The page closes by itself once the player joined; the host breaks.
                (hud, window) => Connected(hud, "Player 2") && Press(window, Key.W, Key.W, Key.W, Key.W, Key.W, Key.W, Key.Space),
                (hud, _) => hud.Board?.Title.Contains("shot 1", StringComparison.Ordinal) == true,
            ]);
            var hostRun = BackgroundWork.RunBlocking(() => host.Play(folder, "host"));
            var (code, port) = await hosting.Task.WaitAsync(Bound);
            var join = new Side(
            [
                Click("Play online"),
                Click("Join a game"),
                // U and - are letters here, not the sound's mute and volume keys; Backspace deletes them.
                (_, window) => Type(window, "u-"),
                (hud, window) => hud.Buttons!.Any(b => b.Label == "Address: u-_") && Press(window, Key.Backspace, Key.Backspace),
                (hud, window) => hud.Buttons!.Any(b => b.Label == "Address: _") && Type(window, $"127.0.0.1:{port}") && Press(window, Key.Enter),
                (_, window) => Type(window, code.ToLowerInvariant()),
                (hud, _) =>
                {
                    entryPage = hud;
                    return true;
                },
                (_, window) => Press(window, Key.Enter),
                (hud, _) => Connected(hud, "Player 1"),
                // The host's break, played here.
                (hud, _) => hud.Board?.Title.Contains("shot 1", StringComparison.Ordinal) == true,
            ]);
            var joinRun = BackgroundWork.RunBlocking(() => join.Play(folder, "join"));
            var both = Task.WhenAll(hostRun, joinRun);
            Assert.Same(both, await Task.WhenAny(both, Task.Delay(Bound)));
            Assert.Equal(new[] { 0, 0 }, await both);
            Assert.True(host.Done, $"the host stopped at step {host.Step}");
            Assert.True(join.Done, $"the joiner stopped at step {join.Step}");
            Assert.Contains(codePage!.Labels!, l => l.Text.StartsWith("Waiting for a player", StringComparison.Ordinal));
            Assert.Contains(entryPage!.Buttons!, b => b.Label == $"Address: 127.0.0.1:{port}");
            Assert.Contains(entryPage.Buttons!, b => b.Label == $"Code: {code}_");
            // The joiner got the host's game: 9-ball, chosen on the host's menu.
            Assert.StartsWith("9-ball", join.Last!.Board!.Title, StringComparison.Ordinal);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [GeneratedRegex(@"port (\d+)\)")]
    private static partial Regex PortOf();

    private static bool Connected(HudInfo hud, string peer) =>
        !hud.Backdrop && hud.Labels?.Any(l => l.Text.StartsWith($"Online: {peer} connected", StringComparison.Ordinal)) == true;

    private static Func<HudInfo, FakeWindow, bool> Click(string label) => (hud, window) =>
    {
        if (hud.Buttons?.FirstOrDefault(b => b.Label == label) is not { } button)
        {
            return false;
        }
        window.MoveTo(button.X + (button.Width / 2), button.Y + (button.Height / 2));
        window.Down();
        window.Up();
        return true;
    };

    private static bool Press(FakeWindow window, params Key[] keys)
    {
        foreach (var key in keys)
        {
            window.Press(key);
        }
        return true;
    }

    // Typed as a keyboard types it: letters, digits, '.', '-' and ':' (the semicolon key).
    private static bool Type(FakeWindow window, string text) => Press(window, [.. text.Select(c => c switch
    {
        >= 'a' and <= 'z' => Key.A + (c - 'a'),
        >= '0' and <= '9' => Key.D0 + (c - '0'),
        '.' => Key.Period,
        ':' => Key.Semicolon,
        '-' => Key.Minus,
        _ => throw new ArgumentException($"no key for {c}"),
    })]);

    // One side: the whole game (plain play with the start menu) on a fake window, its steps taken
    // one a frame, each when the frame shows what it needs; the window closes after the last.
    private sealed class Side : IFrameLoop, IFrameRenderer
    {
        private readonly List<Func<HudInfo, FakeWindow, bool>> _steps;
        private readonly ManualClock _clock = new();
        private readonly FakeWindow _window = new() { FramebufferSize = (1280, 720) };

        public Side(IEnumerable<Func<HudInfo, FakeWindow, bool>> steps) => _steps = [.. steps];

        public int Step { get; private set; }

        public bool Done => Step == _steps.Count;

        public HudInfo? Last { get; private set; }

        public int Play(string folder, string name)
        {
            var options = new PlayCommand.PlayOptions(null, null)
            {
                StartMenu = true,
                SettingsPath = Path.Combine(folder, $"{name}-settings.json"),
                DataFolder = Path.Combine(folder, name),
                HostAt = new IPEndPoint(IPAddress.Loopback, 0),
            };
            return PlayCommand.Play(null, _ => new GamePlatform(_window, this, this), clock: _clock, options: options);
        }

        public void Run(Action frame)
        {
            var until = DateTime.UtcNow + Bound;
            while (!_window.Closed && DateTime.UtcNow < until)
            {
                _clock.Advance(1.0 / 60);
                frame();
                if (Last is { } hud && !Done && _steps[Step](hud, _window))
                {
                    Step++;
                }
                if (Done)
                {
                    _window.Close();
                }
                Thread.Sleep(1);
            }
        }

        public void Draw(RenderFrame frame) => Last = frame.Hud;
    }
}
