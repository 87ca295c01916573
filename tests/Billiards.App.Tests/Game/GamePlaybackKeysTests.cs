using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// <c>replay GAME.json</c> in the window: the next and previous shot keys, each shot's ruling on
/// the HUD, and a game picked from a file of several (<c>selfplay --out</c>, <c>--game N</c>).
/// </summary>
public sealed class GamePlaybackKeysTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-playback-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string SelfplayRecords()
    {
        string output = Path.Combine(_dir, "g.jsonl");
        var (code, _, stderr) = Billiards.App.Tests.Cli.CliRun.Run("selfplay", "--rules", "nine-ball", "--games", "2", "--levels", "3,2", "--seed", "41", "--out", output);
        Assert.True(code == 0, stderr);
        return output;
    }

    /// <summary>Runs frames on a manual clock and, before frame k, does what <paramref name="at"/> says.</summary>
    private sealed class KeyedLoop(ManualClock clock, FakeWindow window, IReadOnlyDictionary<int, Action> at) : IFrameLoop
    {
        public void Run(Action frame)
        {
            for (int i = 0; i < 200_000 && !window.Closed; i++)
            {
                if (at.TryGetValue(i, out var act))
                {
                    act();
                }
                clock.Advance(1.0 / 30);
                frame();
            }
        }
    }

    [Fact]
    public void TheShotKeysGoForwardsAndBackAndEveryShotShownGetsItsRecordedRuling()
    {
        string path = SelfplayRecords();
        var records = ReplayCommand.Load(path);
        var record = ReplayCommand.Pick(records, 2, path);
        Assert.Same(records[1], record);
        Assert.True(record.Shots.Count >= 4, $"{record.Shots.Count} shots");

        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        ReplayNode? node = null;
        var seen = new List<(int Frame, int Shot, string? Status)>();
        void Look(int frame) => seen.Add((frame, node!.Shot, node.Status));
        var at = new Dictionary<int, Action>
        {
            // Before shot 0 is struck (the table stands a second first): on to shot 1, then 2.
            [5] = () => window.Press(ReplayNode.NextShotKey),
            [8] = () => { Look(8); window.Press(ReplayNode.NextShotKey); },
            [11] = () => { Look(11); window.Press(ReplayNode.PreviousShotKey); },
            [14] = () => Look(14),
        };
        var rulings = new List<(int Shot, Ruling Ruling)>();
        int code = ReplayCommand.Play(record, path, 0, 8, _ => new GamePlatform(window, new KeyedLoop(clock, window, at), new WatchingRenderer(_ => { })), clock,
            (k, r) => rulings.Add((k, r)), host => node = host.Tree.Root.GetInTree<ReplayNode>(), closeAtEnd: true);
        Assert.Equal(0, code);
        Assert.True(window.Closed, "the playback never ended");

        Assert.True(rulings.Count >= 3, $"shot {node!.Shot} of {record.Shots.Count}: {node.Status}; rulings {rulings.Count}; clock {clock.Now}; {rulings[^1].Ruling.Message} / {record.Rulings[rulings[^1].Shot]}");
        Assert.Equal([(8, 1), (11, 2), (14, 1)], seen.Select(s => (s.Frame, s.Shot)));
        // The record's shot 2 (from 0) is the third: counted from 1, "shot 3 of" the record's shots.
        Assert.Contains($"shot 3 of {record.Shots.Count}", seen[1].Status, StringComparison.Ordinal);
        // Shot 0 was skipped before it was struck; from shot 1 every shot played and was judged as recorded.
        Assert.Equal(Enumerable.Range(1, record.Shots.Count - 1), rulings.Select(r => r.Shot));
        foreach (var (shot, ruling) in rulings)
        {
            Assert.Equal(record.Rulings[shot], System.Text.Encoding.UTF8.GetString(GameBlockWriter.RulingToUtf8(ruling)));
        }
        // The HUD's line names the last shot's ruling.
        Assert.Contains(rulings[^1].Ruling.Message, node!.Status, StringComparison.Ordinal);
    }

    [Fact]
    public void EveryShotShownIsHeardFromItsStrikeAtAnySpeed()
    {
        string path = SelfplayRecords();
        var record = ReplayCommand.Load(path)[0];
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var audio = new Billiards.App.Tests.Audio.RecordingAudio();
        int shown = 0;
        // At 8 times real time a frame of 1/30 s passes 0.27 s of a shot: every collision is still heard.
        int code = ReplayCommand.Play(record, path, 0, 8, _ => new GamePlatform(window, new KeyedLoop(clock, window, new Dictionary<int, Action>()), new WatchingRenderer(_ => { })), clock,
            (_, _) => shown++, openAudio: () => audio, closeAtEnd: true);
        Assert.Equal(0, code);
        Assert.Equal(record.Shots.Count, shown);
        Assert.Equal(shown, audio.Cues.Count(c => c.Kind is Billiards.App.Audio.SoundKind.CueStrike or Billiards.App.Audio.SoundKind.Miscue));
        Assert.True(audio.Cues.Count(c => c.Kind == Billiards.App.Audio.SoundKind.BallClick) >= shown, "the shots' collisions are heard");
        Assert.True(audio.MaxRollingSpeed > 0.5, "the shown balls are heard rolling");
    }

    [Fact]
    public void AGameNumberOutsideTheFileIsOneLineAndExitTwo()
    {
        string path = SelfplayRecords();
        var (code, stdout, stderr) = Billiards.App.Tests.Cli.CliRun.Run("replay", path, "--game", "3");
        Assert.Equal(2, code);
        Assert.Equal("", stdout);
        Assert.Equal($"billiards: --game 3: {path} holds games 1 to 2", stderr.TrimEnd('\n'));
        var (verify, _, error) = Billiards.App.Tests.Cli.CliRun.Run("replay", path, "--verify", "--game", "1");
        Assert.Equal(2, verify);
        Assert.Contains("--game", error, StringComparison.Ordinal);
    }
}
