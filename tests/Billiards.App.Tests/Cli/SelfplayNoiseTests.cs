using System.Text.Json;

namespace Billiards.App.Tests.Cli;

/// <summary><c>selfplay --noise fastfiz[:K] --planners A,B</c>: noisy runs that shard, merge and verify.</summary>
public sealed class SelfplayNoiseTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-noise-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string P(string name) => Path.Combine(_dir, name);

    private static readonly string[] Run = ["selfplay", "--rules", "eight-ball", "--games", "3", "--levels", "2,2", "--seed", "5", "--noise", "fastfiz:2", "--planners", "noise,blind"];

    [Fact]
    public void ANoisyRunNamesItsNoiseShardsToTheWholeRunAndItsRecordsVerify()
    {
        var whole = CliRun.Run([.. Run, "--threads", "2", "--out", P("all.jsonl"), "--summary", P("all.json")]);
        Assert.True(whole.Code == 0, whole.Err);
        using (var doc = JsonDocument.Parse(File.ReadAllText(P("all.json"))))
        {
            var root = doc.RootElement;
            Assert.Equal("fastfiz:2", root.GetProperty("noise").GetString());
            Assert.Equal(["noise", "blind"], root.GetProperty("planners").EnumerateArray().Select(p => p.GetString()));
            foreach (var p in root.GetProperty("players").EnumerateArray())
            {
                Assert.True(p.GetProperty("pot_attempts").GetInt32() >= p.GetProperty("pots").GetInt32());
                Assert.True(p.GetProperty("breaks").GetInt32() >= p.GetProperty("break_and_runs").GetInt32());
            }
        }
        for (int k = 0; k < 2; k++)
        {
            var shard = CliRun.Run([.. Run, "--threads", "1", "--shard", $"{k}/2", "--out", P($"g{k}.jsonl"), "--summary", P($"s{k}.json")]);
            Assert.True(shard.Code == 0, shard.Err);
        }
        var merged = CliRun.Run("selfplay", "--merge", P("s0.json"), P("s1.json"));
        Assert.True(merged.Code == 0, merged.Err);
        Assert.Equal(SelfplayShardTests.Counts(File.ReadAllText(P("all.json"))), SelfplayShardTests.Counts(merged.Out));
        string[] a = File.ReadAllLines(P("g0.jsonl")), b = File.ReadAllLines(P("g1.jsonl"));
        Assert.Equal(File.ReadAllLines(P("all.jsonl")), Enumerable.Range(0, 3).Select(g => g % 2 == 0 ? a[g / 2] : b[g / 2]));

        var verify = CliRun.Run("replay", P("all.jsonl"), "--verify");
        Assert.True(verify.Code == 0, verify.Out + verify.Err);
        Assert.Equal(3, verify.Out.Trim().Split('\n').Length);
    }

    [Fact]
    public void ShardsOfRunsWithAnotherNoiseDoNotMerge()
    {
        string[] small = ["selfplay", "--rules", "nine-ball", "--games", "2", "--levels", "1,1", "--seed", "1"];
        Assert.Equal(0, CliRun.Run([.. small, "--noise", "fastfiz", "--shard", "0/2", "--summary", P("a.json")]).Code);
        Assert.Equal(0, CliRun.Run([.. small, "--noise", "fastfiz:5", "--shard", "1/2", "--summary", P("b.json")]).Code);
        var merged = CliRun.Run("selfplay", "--merge", P("a.json"), P("b.json"));
        Assert.Equal(2, merged.Code);
        Assert.Contains("$.noise", merged.Err, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("selfplay", "--noise", "fastfiz:-1", "--noise fastfiz:-1: the scale \"-1\" is not a number from 0 to 100")]
    [InlineData("selfplay", "--noise", "foo", "--noise foo: unknown noise model \"foo\"")]
    [InlineData("selfplay", "--noise", "fastfiz:NaN", "--noise fastfiz:NaN: the scale \"NaN\"")]
    [InlineData("selfplay", "--planners", "noise,own", "--planners noise,own: a planner that plays for the noise needs --noise")]
    [InlineData("selfplay", "--planners", "blind", "--planners blind: expected two of own, noise and blind")]
    [InlineData("suggest", "--noise", "fastfiz:-1", "--noise fastfiz:-1: the scale \"-1\"")]
    [InlineData("suggest", "--noise", "NaN", "--noise NaN: unknown noise model \"NaN\"")]
    public void ABadNoiseIsOneLineExitTwo(string verb, string option, string value, string expected)
    {
        string[] args = verb == "selfplay"
            ? ["selfplay", "--rules", "eight-ball", "--games", "1", "--levels", "1,1", "--seed", "1", option, value, "--summary", P("s.json")]
            : ["suggest", WriteScene(), option, value];
        SelfplayShardTests.AssertOneLineExitTwo(CliRun.Run(args), expected, P("s.json"));
    }

    [Fact]
    public void SuggestPlansForTheNoise()
    {
        string scene = WriteScene();
        var plain = CliRun.Run("suggest", scene, "--level", "2", "--budget-ms", "600000");
        var noisy = CliRun.Run("suggest", scene, "--level", "2", "--budget-ms", "600000", "--noise", "fastfiz:5");
        Assert.True(plain.Code == 0, plain.Err);
        Assert.True(noisy.Code == 0, noisy.Err);
        // The search sampled the noise instead of the level's own error: another expected outcome
        // (the same scene without noise gives the same suggestion every time).
        Assert.NotEqual(WithoutTime(plain.Out), WithoutTime(noisy.Out));
        Assert.Equal(WithoutTime(plain.Out), WithoutTime(CliRun.Run("suggest", scene, "--level", "2", "--budget-ms", "600000").Out));
    }

    private static string WithoutTime(string json)
    {
        var root = System.Text.Json.Nodes.JsonNode.Parse(json)!.AsObject();
        root.Remove("ms");
        return root.ToJsonString();
    }

    private string WriteScene()
    {
        string path = P("scene.json");
        File.WriteAllText(path, """
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
              "balls": [ { "id": "cue", "position": [0.0, 0.0] }, { "id": "9", "position": [0.6, 0.3] } ],
              "rules": "nine-ball" }
            """);
        return path;
    }
}
