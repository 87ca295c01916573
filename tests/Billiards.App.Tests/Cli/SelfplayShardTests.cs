using System.Text.Json;
using System.Text.Json.Nodes;

namespace Billiards.App.Tests.Cli;

/// <summary><c>selfplay --shard K/N</c> and <c>selfplay --merge</c>: shards that add up to the whole run.</summary>
public sealed class SelfplayShardTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-shard-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string P(string name) => Path.Combine(_dir, name);

    private static readonly string[] Run = ["selfplay", "--rules", "eight-ball", "--games", "5", "--levels", "1,2", "--seed", "9"];

    /// <summary>A summary without its wall-clock figures: "ms" and the decision times (measurements).</summary>
    internal static string Counts(string json)
    {
        var root = JsonNode.Parse(json)!.AsObject();
        root.Remove("ms");
        foreach (var player in root["players"]!.AsArray())
        {
            player!.AsObject().Remove("decision_ms");
        }
        return root.ToJsonString();
    }

    [Fact]
    public void TwoShardsMergedGiveEveryCountAndRecordOfTheWholeRun()
    {
        var whole = CliRun.Run([.. Run, "--out", P("all.jsonl"), "--summary", P("all.json")]);
        Assert.True(whole.Code == 0, whole.Err);
        Assert.Equal("", whole.Out);
        for (int k = 0; k < 2; k++)
        {
            var shard = CliRun.Run([.. Run, "--shard", $"{k}/2", "--out", P($"games-{k}.jsonl"), "--summary", P($"summary-{k}.json")]);
            Assert.True(shard.Code == 0, shard.Err);
            Assert.Contains($"selfplay {k}/2: {(k == 0 ? 3 : 2)}/{(k == 0 ? 3 : 2)} games", shard.Err, StringComparison.Ordinal);
        }
        var merged = CliRun.Run("selfplay", "--merge", P("summary-1.json"), P("summary-0.json"));
        Assert.True(merged.Code == 0, merged.Err);

        string all = File.ReadAllText(P("all.json"));
        Assert.Equal(Counts(all), Counts(merged.Out));
        using (var doc = JsonDocument.Parse(merged.Out))
        {
            Assert.Equal(5, doc.RootElement.GetProperty("games").GetInt32());
            Assert.False(doc.RootElement.TryGetProperty("shard", out _));
            // The merged decision times come from the shards' histograms: as many times as shots.
            foreach (var p in doc.RootElement.GetProperty("players").EnumerateArray())
            {
                long binned = p.GetProperty("decision_ms").GetProperty("histogram").GetProperty("counts").EnumerateArray().Sum(c => c[1].GetInt64());
                Assert.Equal(p.GetProperty("shots").GetInt32(), binned);
            }
        }
        // Game g is line g / N of shard g mod N: the shards' records interleave into the whole run's.
        string[] a = File.ReadAllLines(P("games-0.jsonl")), b = File.ReadAllLines(P("games-1.jsonl"));
        Assert.Equal(File.ReadAllLines(P("all.jsonl")), Enumerable.Range(0, 5).Select(g => g % 2 == 0 ? a[g / 2] : b[g / 2]));
    }

    [Theory]
    [InlineData("2/2", "--shard 2/2: expected K from 0 to N - 1 = 1")]
    [InlineData("0/0", "--shard 0/0: expected N >= 1")]
    [InlineData("x", "--shard x: expected K/N")]
    public void ABadShardIsOneLineExitTwo(string shard, string expected)
    {
        AssertOneLineExitTwo(CliRun.Run([.. Run, "--shard", shard, "--summary", P("s.json")]), expected, P("s.json"));
    }

    /// <summary>A refused run: exit 2, nothing on stdout, one line on stderr starting with <paramref name="expected"/>, and <paramref name="unwritten"/> not written.</summary>
    internal static void AssertOneLineExitTwo((int Code, string Out, string Err) run, string expected, string unwritten)
    {
        Assert.Equal(2, run.Code);
        Assert.Equal("", run.Out);
        Assert.Single(run.Err.TrimEnd('\n').Split('\n'));
        Assert.StartsWith($"billiards: {expected}", run.Err, StringComparison.Ordinal);
        Assert.False(File.Exists(unwritten));
    }

    [Fact]
    public void SummariesThatAreNotTheShardsOfOneRunDoNotMerge()
    {
        string[] small = ["selfplay", "--rules", "nine-ball", "--games", "2", "--levels", "1,1"];
        Assert.Equal(0, CliRun.Run([.. small, "--seed", "1", "--shard", "0/2", "--summary", P("a.json")]).Code);
        Assert.Equal(0, CliRun.Run([.. small, "--seed", "2", "--shard", "1/2", "--summary", P("b.json")]).Code);
        File.WriteAllText(P("broken.json"), "{ \"format\": ");

        foreach (var (args, expected) in new (string[], string)[]
        {
            ([P("a.json"), P("b.json")], $"{P("b.json")}: $.seed: 2 differs from 1 in {P("a.json")}"),
            ([P("a.json")], "shard 1 of 2 is missing"),
            ([P("a.json"), P("a.json")], "shard 0 of 2 is also"),
            ([P("a.json"), P("none.json")], $"--merge {P("none.json")}: cannot read the file"),
            ([P("broken.json")], $"{P("broken.json")}: $: not valid JSON"),
        })
        {
            var (code, stdout, stderr) = CliRun.Run(["selfplay", "--merge", .. args, "--summary", P("m.json")]);
            Assert.Equal(2, code);
            Assert.Equal("", stdout);
            Assert.Single(stderr.TrimEnd('\n').Split('\n'));
            Assert.Contains(expected, stderr, StringComparison.Ordinal);
            Assert.False(File.Exists(P("m.json")));
        }
        var mixed = CliRun.Run("selfplay", "--merge", P("a.json"), "--seed", "3");
        Assert.Equal(2, mixed.Code);
        Assert.Contains("--merge: --seed does not go with it", mixed.Err, StringComparison.Ordinal);
    }
    [Fact]
    public void TheSearchThreadsChangeNoGame()
    {
        string[] run = ["selfplay", "--rules", "eight-ball", "--games", "2", "--levels", "2,3", "--seed", "4"];
        foreach (string threads in new[] { "1", "3" })
        {
            var r = CliRun.Run([.. run, "--threads", threads, "--out", P($"games-{threads}.jsonl"), "--summary", P($"summary-{threads}.json")]);
            Assert.True(r.Code == 0, r.Err);
        }
        Assert.Equal(File.ReadAllText(P("games-1.jsonl")), File.ReadAllText(P("games-3.jsonl")));
        Assert.Equal(Counts(File.ReadAllText(P("summary-1.json"))), Counts(File.ReadAllText(P("summary-3.json"))));
        Assert.True(File.ReadAllLines(P("games-1.jsonl")).Length == 2);

        var bad = CliRun.Run([.. run, "--threads", "0"]);
        Assert.Equal(2, bad.Code);
        Assert.Equal("billiards: --threads 0: expected 1 to 1024", bad.Err.TrimEnd('\n'));
        var merge = CliRun.Run("selfplay", "--merge", P("summary-1.json"), "--threads", "2");
        Assert.Equal(2, merge.Code);
        Assert.Contains("--threads does not go with it", merge.Err, StringComparison.Ordinal);
    }
}
