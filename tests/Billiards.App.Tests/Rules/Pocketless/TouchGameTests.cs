using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Tests.Cli;
using Billiards.App.Tests.Game;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

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
        Assert.Equal(rules, scene.Game?.Rules ?? GameRules.FromString(scene.Rules!));
        var window = new FakeWindow();
        var clock = new ManualClock();
        using var host = new GameHost(scene, SimulationFactory.Create, window, clock,
            new MatchSetup(rules, [new Seat("Computer L1", 1), new Seat("Computer L2", 2)]));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        var computer = host.Tree.Root.GetInTree<ComputerPlayerNode>();
        computer.BudgetMs = 120_000;
        computer.Fast = true;
        var limit = DateTime.UtcNow.AddSeconds(240);
        while (!match.IsOver && DateTime.UtcNow < limit)
        {
            clock.Advance(1.0 / 30);
            host.RunFrame();
            if (!host.World.Physics.IsRolling)
            {
                Thread.Sleep(2);
            }
        }
        Assert.True(match.IsOver, $"the game never ended ({match.Game.Shots.Count} shots)");
        int winner = match.Session.Winner!.Value;
        Assert.Equal(TouchRuleset.Points, match.State.Score[winner]);
        Assert.Equal(1, match.GamesWon[winner]);
        var record = GameRecordFile.Parse(System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(match.Game)), "touch-game.json");
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
}
