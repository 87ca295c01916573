using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Cli;

/// <summary>The verbs <c>suggest</c> and <c>selfplay</c> (scene-format.md).</summary>
public sealed class AiCommandTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-ai-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    // The cue ball, the 9 on the straight line to the foot-left pocket: the one pot of the position.
    private const string StraightIn = """
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
          "balls": [ { "id": "cue", "position": [0.0, 0.0] }, { "id": "9", "position": [0.6, 0.3] } ],
          "rules": "nine-ball" }
        """;

    private string Write(string name, string json)
    {
        string path = Path.Combine(_dir, name);
        File.WriteAllText(path, json);
        return path;
    }

    [Fact]
    public void SuggestReturnsTheStraightInPotAndItsShotPotsTheBall()
    {
        string scene = Write("straight.json", StraightIn);
        var (code, stdout, stderr) = CliRun.Run("suggest", scene, "--level", "5", "--budget-ms", "600000");

        Assert.True(code == 0, stderr);
        using var doc = JsonDocument.Parse(stdout);
        var root = doc.RootElement;
        Assert.Equal(JsonValueKind.Null, root.GetProperty("place").ValueKind);
        Assert.Equal(JsonValueKind.Null, root.GetProperty("call").ValueKind);
        Assert.True(root.GetProperty("simulations").GetInt32() > 0);
        // The decision ran simulations, so it took some time: a positive, finite figure (never gated on speed).
        double ms = root.GetProperty("ms").GetDouble();
        Assert.True(ms > 0 && double.IsFinite(ms), $"ms = {ms}");
        var expected = root.GetProperty("expected");
        Assert.InRange(expected.GetProperty("pot").GetDouble(), 0.9, 1.0);
        Assert.Equal("9", expected.GetProperty("ruling").GetProperty("pocketed")[0].GetString());

        AssertPotsTheNine(scene, ShotOf(root));
    }

    private static ShotSpec ShotOf(JsonElement suggestion)
    {
        var s = suggestion.GetProperty("shot");
        var tip = s.GetProperty("tip");
        return new ShotSpec(s.GetProperty("speed").GetDouble(), s.GetProperty("aim_deg").GetDouble(), tip[0].GetDouble(), tip[1].GetDouble(), s.GetProperty("elevation_deg").GetDouble());
    }

    // The shot, simulated from the scene, pots the 9 and not the cue ball.
    private static void AssertPotsTheNine(string scene, ShotSpec shot)
    {
        var sim = SimulationFactory.Create(SceneLoader.Load(scene));
        sim.Strike(shot);
        sim.AdvanceTo(120);
        var record = ShotRecord.LastShot(sim, shot);
        Assert.True(record.IsPocketedAfter(new BallId(9)));
        Assert.False(record.IsPocketedAfter(PoolBalls.Cue));
    }

    [Fact]
    public void SuggestFromACueBallFrozenToARailRaisesTheCueOverTheRailAndTheShotStillPots()
    {
        // The cue ball touches the long rail; the 9 lies on the line to the far corner, 22 deg off
        // the rail's normal: a level cue would pass through the rail behind the cue ball.
        string scene = Write("frozen.json", """
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
              "balls": [ { "id": "cue", "position": [0.77, -0.606425] }, { "id": "9", "position": [1.045, 0.0764] } ],
              "rules": "nine-ball" }
            """);
        // The search, not the wall-clock cap, must end the decision on a loaded machine, or the choice is not reproducible.
        var (code, stdout, stderr) = CliRun.Run("suggest", scene, "--level", "5", "--budget-ms", "600000");

        Assert.True(code == 0, stderr);
        using var doc = JsonDocument.Parse(stdout);
        var shot = ShotOf(doc.RootElement);
        var loaded = SceneLoader.Load(scene);
        var cue = loaded.Balls.Single(b => PoolBalls.IsCue(b.Id)).Position with { Z = loaded.BallRadius };
        double a = shot.AimDeg * Math.PI / 180;
        var aim = new Billiards.Core.Mathematics.Vec3(Math.Cos(a), Math.Sin(a), 0);
        double rail = CueClearance.RailElevationDegrees(cue, aim, loaded.Table, loaded.BallRadius, shot.TipHeight);
        Assert.True(rail > 15, $"the rail needs {rail} deg");
        Assert.True(shot.ElevationDeg >= rail - 1e-9, $"elevation {shot.ElevationDeg} deg, the rail needs {rail}");
        AssertPotsTheNine(scene, shot);
    }

    [Theory]
    [InlineData("--level", "6", "--level 6")]
    [InlineData("--level", "0", "--level 0")]
    [InlineData("--budget-ms", "0", "--budget-ms 0")]
    public void SuggestRefusesABadArgumentInOneLine(string option, string value, string expected)
    {
        string scene = Write("straight.json", StraightIn);
        var (code, stdout, stderr) = CliRun.Run("suggest", scene, option, value);
        Assert.Equal(2, code);
        Assert.Equal("", stdout);
        Assert.Single(stderr.TrimEnd('\n').Split('\n'));
        Assert.Contains(expected, stderr, StringComparison.Ordinal);
    }

    [Fact]
    public void SelfplayPrintsTheSummaryAndWritesOneRecordPerGame()
    {
        string output = Path.Combine(_dir, "games.jsonl");
        var (code, stdout, stderr) = CliRun.Run("selfplay", "--rules", "nine-ball", "--games", "2", "--levels", "2,1", "--seed", "4", "--out", output);

        Assert.True(code == 0, stderr);
        Assert.Contains("selfplay: 2/2 games", stderr, StringComparison.Ordinal);
        using var doc = JsonDocument.Parse(stdout);
        var root = doc.RootElement;
        Assert.Equal("nine-ball", root.GetProperty("rules").GetString());
        Assert.Equal(2, root.GetProperty("games").GetInt32());
        var players = root.GetProperty("players");
        Assert.Equal(2, players.GetArrayLength());
        int won = 0, breaks = 0;
        foreach (var p in players.EnumerateArray())
        {
            won += p.GetProperty("games_won").GetInt32();
            breaks += p.GetProperty("breaks").GetInt32();
            Assert.True(p.GetProperty("pots").GetInt32() <= p.GetProperty("pot_attempts").GetInt32());
            Assert.True(p.GetProperty("break_and_runs").GetInt32() + p.GetProperty("run_outs").GetInt32() <= p.GetProperty("games_won").GetInt32());
            var times = p.GetProperty("decision_ms");
            Assert.True(times.GetProperty("median").GetDouble() <= times.GetProperty("p95").GetDouble());
        }
        Assert.Equal(2 - root.GetProperty("unfinished").GetInt32(), won);
        Assert.True(breaks >= 2);
        Assert.Equal(2, players[0].GetProperty("level").GetInt32());

        string[] lines = File.ReadAllLines(output);
        Assert.Equal(2, lines.Length);
        foreach (string line in lines)
        {
            using var game = JsonDocument.Parse(line);
            Assert.Equal("billiards-game/1", game.RootElement.GetProperty("format").GetString());
            var shots = game.RootElement.GetProperty("shots");
            Assert.True(shots.GetArrayLength() > 0);
            Assert.Equal(0, shots[0].GetProperty("game").GetProperty("shot").GetInt32());
            // The record is the Core's, and its shots reproduce every ruling.
            var record = GameRecordFile.Parse(line, output);
            Assert.Equal(shots.GetArrayLength(), record.Shots.Count);
            Assert.Equal(-1, GameRecordFile.Replay(record, out _));
        }
    }

    [Theory]
    [InlineData("--levels", "5", "--levels 5")]
    [InlineData("--levels", "5,9", "--levels 5,9")]
    [InlineData("--rules", "carom", "--rules carom")]
    [InlineData("--target", "0", "--target 0")]
    [InlineData("--games", "0", "--games 0")]
    public void SelfplayRefusesABadArgumentInOneLine(string option, string value, string expected)
    {
        var args = new Dictionary<string, string> { ["--rules"] = "nine-ball", ["--games"] = "1", ["--levels"] = "1,1", ["--seed"] = "1" };
        args[option] = value;
        var (code, stdout, stderr) = CliRun.Run(["selfplay", .. args.SelectMany(a => new[] { a.Key, a.Value })]);
        Assert.Equal(2, code);
        Assert.Equal("", stdout);
        Assert.Single(stderr.TrimEnd('\n').Split('\n'));
        Assert.Contains(expected, stderr, StringComparison.Ordinal);
    }
}
