using System.Globalization;
using System.Text.Json;
using System.Text.Json.Nodes;

namespace Billiards.App.Tests.Cli;

/// <summary><c>replay GAME --verify</c> (scene-format.md): records re-simulated and compared shot by shot.</summary>
public sealed class ReplayCommandTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-replay-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string SelfplayRecords()
    {
        string output = Path.Combine(_dir, "g.jsonl");
        var (code, _, stderr) = CliRun.Run("selfplay", "--rules", "nine-ball", "--games", "3", "--levels", "3,2", "--seed", "41", "--out", output);
        Assert.True(code == 0, stderr);
        return output;
    }

    [Fact]
    public void EverySelfplayRecordReplaysTheSameShotForShot()
    {
        string records = SelfplayRecords();
        var (code, stdout, stderr) = CliRun.Run("replay", records, "--verify");
        Assert.True(code == 0, stderr + stdout);
        string[] lines = stdout.TrimEnd('\n').Split('\n');
        Assert.Equal(3, lines.Length);
        foreach (string line in lines)
        {
            using var doc = JsonDocument.Parse(line);
            var root = doc.RootElement;
            int shots = root.GetProperty("shots").GetInt32();
            Assert.True(shots > 0);
            Assert.Equal(shots, root.GetProperty("same").GetInt32());
            Assert.Equal(JsonValueKind.Null, root.GetProperty("first_difference").ValueKind);
        }
    }

    [Fact]
    public void AShotAimedTwoDegreesOffIsNamedAndExitsOne()
    {
        string first = File.ReadAllLines(SelfplayRecords())[0];
        var record = JsonNode.Parse(first)!;
        const int changed = 4;
        var shot = record["shots"]![changed]!["shot"]!;
        shot["aim_deg"] = shot["aim_deg"]!.GetValue<double>() + 2;
        string path = Path.Combine(_dir, "changed.json");
        File.WriteAllText(path, record.ToJsonString());

        var (code, stdout, _) = CliRun.Run("replay", path, "--verify");
        Assert.Equal(1, code);
        using var doc = JsonDocument.Parse(stdout);
        var root = doc.RootElement;
        Assert.Equal(changed, root.GetProperty("same").GetInt32());
        var difference = root.GetProperty("first_difference");
        Assert.Equal(changed, difference.GetProperty("shot").GetInt32());
        Assert.Matches("^(ruling\\.[a-z_]+|balls)$", difference.GetProperty("field").GetString());
        Assert.NotEqual(difference.GetProperty("recorded").GetRawText(), difference.GetProperty("replayed").GetRawText());
    }

    [Theory]
    [InlineData("""{ "format": "billiards-scene/1" }""", "$.format")]
    [InlineData("not json", "not valid JSON")]
    public void ABadRecordIsOneLineAndExitTwo(string json, string expected)
    {
        string path = Path.Combine(_dir, "bad.json");
        File.WriteAllText(path, json);
        var (code, stdout, stderr) = CliRun.Run("replay", path, "--verify");
        Assert.Equal(2, code);
        Assert.Equal("", stdout);
        Assert.Single(stderr.TrimEnd('\n').Split('\n'));
        Assert.Contains(path, stderr, StringComparison.Ordinal);
        Assert.Contains(expected, stderr, StringComparison.Ordinal);
    }

    [Fact]
    public void AMissingFileIsExitTwo()
    {
        string path = Path.Combine(_dir, "none.json");
        var (code, _, stderr) = CliRun.Run("replay", path, "--verify");
        Assert.Equal(2, code);
        Assert.Contains(path, stderr, StringComparison.Ordinal);
    }

    [Fact]
    public void PlaybackRefusesAShotTheRecordDoesNotHave()
    {
        string first = File.ReadAllLines(SelfplayRecords())[0];
        string path = Path.Combine(_dir, "one.json");
        File.WriteAllText(path, first);
        int shots = JsonNode.Parse(first)!["shots"]!.AsArray().Count;
        var (code, _, stderr) = CliRun.Run("replay", path, "--shot", shots.ToString(CultureInfo.InvariantCulture));
        Assert.Equal(2, code);
        Assert.Contains("--shot", stderr, StringComparison.Ordinal);
    }
}
