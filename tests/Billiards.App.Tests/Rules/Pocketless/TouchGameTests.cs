using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Tests.Cli;
using Billiards.App.Tests.Game;
using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Rules.Pocketless;

/// <summary>
/// A game registered from the test project alone (<see cref="TouchRuleset"/>: no pockets, no file
/// of Core or the App names it) plays a whole game in the window and in <c>selfplay</c>, and its
/// records verify.
/// </summary>
public class TouchGameTests
{
    private const string Scene = """
        { "format": "billiards-scene/1", "name": "touch", "rules": "touch",
          "table": { "preset": "pocketless" },
          "balls": [ { "id": "cue", "position": [-0.635, 0.0] }, { "id": "1", "position": [0.635, 0.0] } ] }
        """;

    [Fact]
    public void TwoComputersPlayAGameOfTouchInTheWindowAndItsRecordVerifies()
    {
        var rules = TouchRuleset.Register();
        var scene = SceneLoader.Parse(Scene, "touch.json");
        Assert.Equal(rules, scene.PlayedAs);
        var window = new FakeWindow();
        var clock = new ManualClock();
        using var host = new GameHost(scene, SimulationFactory.Create, window, clock,
            new MatchSetup(rules, [new Seat("Computer L1", 1), new Seat("Computer L2", 2)]));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        var computer = host.Tree.Root.GetInTree<ComputerPlayerNode>();
        computer.BudgetMs = 120_000;
        computer.Fast = true;
        var limit = DateTime.UtcNow.AddSeconds(240);
        while (!match.Session.IsOver && DateTime.UtcNow < limit)
        {
            clock.Advance(1.0 / 30);
            host.RunFrame();
            if (!host.World.Physics.IsRolling)
            {
                Thread.Sleep(2);
            }
        }
        Assert.True(match.Session.IsOver, $"the game never ended ({match.Session.Game.Shots.Count} shots)");
        int winner = match.Session.Winner!.Value;
        Assert.Equal(TouchRuleset.Points, match.Session.State.Score[winner]);
        Assert.Equal(1, match.Session.GamesWon[winner]);
        var record = GameRecordFile.Parse(System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(match.Session.Game)), "touch-game.json");
        Assert.Null(GameRecordFile.Verify(record, out _).FirstDifference);
    }

    [Fact]
    public void SelfplayPlaysGamesOfTouchAndReplayVerifiesThem()
    {
        TouchRuleset.Register();
        string dir = Path.Combine(Path.GetTempPath(), $"touch-{Guid.NewGuid():N}");
        Directory.CreateDirectory(dir);
        try
        {
            string records = Path.Combine(dir, "touch.jsonl");
            var (code, stdout, stderr) = CliRun.Run("selfplay", "--rules", "touch", "--games", "2", "--levels", "2,1", "--seed", "5", "--threads", "1", "--out", records);
            Assert.True(code == 0, stderr);
            var summary = System.Text.Json.Nodes.JsonNode.Parse(stdout)!;
            Assert.Equal("touch", summary["rules"]!.GetValue<string>());
            string[] lines = File.ReadAllLines(records);
            Assert.Equal(2, lines.Length);
            foreach (string line in lines)
            {
                var record = GameRecordFile.Parse(line, "touch.jsonl");
                var report = GameRecordFile.Verify(record, out var replayed);
                Assert.Null(report.FirstDifference);
                Assert.True(replayed.IsOver);
                Assert.Equal(TouchRuleset.Points, replayed.Shots[^1].Ruling.Score[replayed.Shots[^1].Ruling.Winner!.Value]);
            }
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }

    [Fact]
    public void TheWindowRefusesAComputerSeatWhereTheGameHasNoComputerPlayer()
    {
        var rules = TouchByHandRuleset.Register();
        var scene = SceneLoader.Parse(Scene.Replace("\"touch\"", "\"touch-by-hand\"", StringComparison.Ordinal), "touch-by-hand.json");
        var refused = Assert.Throws<Billiards.App.Cli.CliException>(() => Billiards.App.Cli.PlayCommand.MatchFor(scene, rules, "human,computer:2"));
        Assert.Contains("computer player does not play touch-by-hand", refused.Message, StringComparison.Ordinal);
        Assert.Throws<ArgumentException>(() => new GameHost(scene, SimulationFactory.Create, new FakeWindow(), new ManualClock(),
            new MatchSetup(rules, [new Seat("Anna"), new Seat("Computer L2", 2)])));
        // Without --players two people sit down.
        var people = Billiards.App.Cli.PlayCommand.MatchFor(scene, rules, null)!;
        Assert.All(people.Players, p => Assert.True(p.IsHuman));
    }

    [Fact]
    public void TouchReadsAndWritesItsOwnGameBlockFieldWhichOtherGamesRefuse()
    {
        TouchRuleset.Register();
        string block = """{ "rules": "touch", "shooter": 1, "shot": 4, "score": [1, 2], "touch_misses": [2, 1] }""";
        var state = GameBlockReader.Read(JsonDocument.Parse(block).RootElement, PocketSet.None, "touch.json");
        Assert.Equal(new PerPlayer<int>(2, 1), state.PartOf<TouchPart>().Misses);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            GameBlockWriter.WriteGame(w, state);
        }
        string written = System.Text.Encoding.UTF8.GetString(stream.ToArray());
        Assert.EndsWith("\"touch_misses\":[2,1]}", written);
        Assert.Equal(state, GameBlockReader.Read(JsonDocument.Parse(written).RootElement, PocketSet.None, "touch.json"));

        var refused = Assert.Throws<SceneException>(() => GameBlockReader.Read(
            JsonDocument.Parse("""{ "rules": "eight-ball", "touch_misses": [1, 0] }""").RootElement, PocketSet.None, "eight.json"));
        Assert.Contains("$.game.touch_misses", refused.Message);
        Assert.Contains("eight-ball has no touch misses (only touch has", refused.Message);
        var bad = Assert.Throws<SceneException>(() => GameBlockReader.Read(
            JsonDocument.Parse("""{ "rules": "touch", "touch_misses": "two" }""").RootElement, PocketSet.None, "touch.json"));
        Assert.Contains("$.game.touch_misses", bad.Message);
    }

    [Fact]
    public void TouchCountsEachPlayersMissesInItsOwnPartOfTheState()
    {
        var rules = TouchRuleset.Register();
        var referee = Ruleset.For(rules).Referee(TableSpec.FromPreset("pocketless"), 0.028575);
        var before = new GameState(rules) { Shooter = 1, Shot = 3 };
        var miss = referee.Judge(before, ShotRecordOf(rules, hit: false));
        Assert.Equal(new PerPlayer<int>(0, 1), miss.Next.PartOf<TouchPart>().Misses);
        var touch = referee.Judge(miss.Next, ShotRecordOf(rules, hit: true));
        Assert.Equal(new PerPlayer<int>(0, 1), touch.Next.PartOf<TouchPart>().Misses);
    }

    // A shot of touch's two balls at rest: the cue ball strikes and, when hit, meets the 1.
    private static ShotRecord ShotRecordOf(GameRules rules, bool hit)
    {
        var ruleset = Ruleset.For(rules);
        BallId cue = ruleset.Balls[0], one = ruleset.Balls[1];
        List<SimEvent> events = [new SimEvent(0, EventKind.CueStrike, cue, cue, -1, 2.0)];
        if (hit)
        {
            events.Add(new SimEvent(0.5, EventKind.BallBall, cue, one, -1, 1.0));
        }
        BallState[] balls = [new() { Position = new Vec3(-0.6, 0, 0.028575) }, new() { Position = new Vec3(0.6, 0, 0.028575) }];
        return ShotRecord.Of([.. events], [cue, one], balls, ballsBefore: balls);
    }
}
