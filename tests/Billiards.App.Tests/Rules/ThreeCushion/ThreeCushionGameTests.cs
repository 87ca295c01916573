using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Tests.Cli;
using Billiards.App.Tests.Game;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Rules.ThreeCushion;

/// <summary>Three-cushion in the window and in <c>selfplay</c>: a whole game to its target between computers, records that verify, the score sheet's figures.</summary>
public class ThreeCushionGameTests
{
    private const string Scene = """
        { "format": "billiards-scene/1", "name": "three-cushion", "rules": "three-cushion",
          "table": { "preset": "carom-match" }, "rack": { "game": "three-cushion" },
          "game": { "rules": "three-cushion", "target": 3 } }
        """;

    [Fact]
    public void TwoComputersPlayAThreeCushionGameInTheWindowToItsTargetAndItsRecordVerifies()
    {
        var rules = ThreeCushionRuleset.ThreeCushion;
        var scene = SceneLoader.Parse(Scene, "three-cushion.json");
        Assert.Equal(BallSet.Carom, scene.BallSet);
        var window = new FakeWindow();
        var clock = new ManualClock();
        using var host = new GameHost(scene, SimulationFactory.Create, window, clock,
            new MatchSetup(rules, [new Seat("Computer L5", 5), new Seat("Computer L3", 3)]));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        var computer = host.Tree.Root.GetInTree<ComputerPlayerNode>();
        computer.BudgetMs = 120_000;
        computer.Fast = true;
        var limit = DateTime.UtcNow.AddSeconds(400);
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
        var last = match.Session.Game.Shots[^1].Ruling;
        Assert.True(last.Score.First >= 3 || last.Score.Second >= 3, last.Message);
        Assert.All(match.Session.Game.Shots, s => Assert.Equal(Ruleset.For(rules).CueBall(s.Before), s.Before.Shooter == 0 ? BallSet.White : BallSet.Yellow));
        var record = GameRecordFile.Parse(System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(match.Session.Game)), "three-cushion-game.json");
        Assert.Null(GameRecordFile.Verify(record, out _).FirstDifference);
    }

    [Fact]
    public void SelfplayReportsEachPlayersPointsInningsAverageAndHighestRunAndReplayVerifiesTheGames()
    {
        string dir = Path.Combine(Path.GetTempPath(), $"three-cushion-{Guid.NewGuid():N}");
        Directory.CreateDirectory(dir);
        try
        {
            string records = Path.Combine(dir, "three-cushion.jsonl");
            var (code, stdout, stderr) = CliRun.Run("selfplay", "--rules", "three-cushion", "--games", "2", "--levels", "2,1", "--seed", "5", "--target", "2", "--threads", "1", "--out", records);
            Assert.True(code == 0, stderr);
            var summary = System.Text.Json.Nodes.JsonNode.Parse(stdout)!;
            Assert.Equal("three-cushion", summary["rules"]!.GetValue<string>());
            Assert.Equal(0, summary["unfinished"]!.GetValue<int>());
            int points = 0;
            foreach (var player in summary["players"]!.AsArray())
            {
                int p = player!["points"]!.GetValue<int>(), innings = player["innings"]!.GetValue<int>();
                Assert.Equal(ThreeCushionRuleset.AverageValue(p, innings), player["average"]!.GetValue<double>());
                Assert.InRange(player["highest_run"]!.GetValue<int>(), p > 0 ? 1 : 0, p);
                points += p;
            }
            string[] lines = File.ReadAllLines(records);
            Assert.Equal(2, lines.Length);
            int recorded = 0;
            foreach (string line in lines)
            {
                var record = GameRecordFile.Parse(line, "three-cushion.jsonl");
                var report = GameRecordFile.Verify(record, out var replayed);
                Assert.Null(report.FirstDifference);
                Assert.True(replayed.IsOver);
                var score = replayed.Shots[^1].Ruling.Score;
                recorded += score.First + score.Second;
            }
            Assert.Equal(recorded, points);
            var (verify, verified, _) = CliRun.Run("replay", records, "--verify");
            Assert.True(verify == 0, verified);
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }
}
