using System.Text.Json;
using System.Text.Json.Nodes;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Cli;

/// <summary>
/// <c>suggest</c> on a position: a scene with a game block and no shot (scene-format.md). The
/// shipped easy positions (assets/scenes/positions) each get a suggestion, and that suggestion,
/// played through <c>simulate</c> with the position's game block, pots the called ball legally.
/// </summary>
public sealed class SuggestPositionTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-position-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    public static TheoryData<string> Positions => new(Directory.GetFiles(AssetFolder.Scene("positions"), "*.json").Select(Path.GetFileName)!);

    [Theory]
    [MemberData(nameof(Positions))]
    public void TheSuggestionForAnEasyPositionPotsWhenPlayed(string file)
    {
        string position = AssetFolder.Scene(Path.Combine("positions", file));
        var scene = JsonNode.Parse(File.ReadAllText(position))!.AsObject();
        Assert.False(scene.ContainsKey("shot"), "a position has no shot");
        Assert.True(scene.ContainsKey("game"), "a position has a game block");

        // A cap far above what the search needs, so a slow machine cannot cut it short: the
        // decision is seeded and the same on every machine.
        var (code, stdout, stderr) = CliRun.Run("suggest", position, "--budget-ms", "600000");
        Assert.True(code == 0, stderr);
        var suggestion = JsonNode.Parse(stdout)!.AsObject();
        string? called = suggestion["call"]?["ball"]?.GetValue<string>();

        // Play it: the suggested shot, call (where the rules call the shot) and placement (ball in hand).
        scene["shot"] = suggestion["shot"]!.DeepClone();
        if (suggestion["call"] is JsonObject call)
        {
            scene["game"]!["call"] = call.DeepClone();
        }
        if (suggestion["place"] is JsonArray place)
        {
            var cue = scene["balls"]!.AsArray().Single(b => b!["id"]!.GetValue<string>() == "cue")!;
            cue["position"] = new JsonArray(place[0]!.GetValue<double>(), place[1]!.GetValue<double>());
        }
        string played = Path.Combine(_dir, file);
        File.WriteAllText(played, scene.ToJsonString());
        (code, stdout, stderr) = CliRun.Run("simulate", played);
        Assert.True(code == 0, stderr);

        using var result = JsonDocument.Parse(stdout);
        var ruling = result.RootElement.GetProperty("ruling");
        string[] pocketed = [.. ruling.GetProperty("pocketed").EnumerateArray().Select(b => b.GetString()!)];
        Assert.True(ruling.GetProperty("legal").GetBoolean(), ruling.GetProperty("message").GetString());
        Assert.True(ruling.GetProperty("continue").GetBoolean(), ruling.GetProperty("message").GetString());
        Assert.NotEmpty(pocketed);
        if (called is not null)
        {
            Assert.Contains(called, pocketed);
        }
    }

    [Fact]
    public void APositionsShotIsIgnored()
    {
        string position = AssetFolder.Scene(Path.Combine("positions", "nine-ball-side-pocket.json"));
        var scene = JsonNode.Parse(File.ReadAllText(position))!.AsObject();
        scene["shot"] = new JsonObject { ["speed"] = 9.0, ["aim_deg"] = -90.0 };
        string withShot = Path.Combine(_dir, "with-shot.json");
        File.WriteAllText(withShot, scene.ToJsonString());

        var (code, plain, stderr) = CliRun.Run("suggest", position, "--budget-ms", "600000");
        Assert.True(code == 0, stderr);
        (code, string ignored, stderr) = CliRun.Run("suggest", withShot, "--budget-ms", "600000");
        Assert.True(code == 0, stderr);
        Assert.Equal(Decision(plain), Decision(ignored));
    }

    // The suggestion without its wall-clock time.
    private static string Decision(string json)
    {
        var node = JsonNode.Parse(json)!.AsObject();
        node.Remove("ms");
        return node.ToJsonString();
    }

    [Fact]
    public void SimulateRefusesAPositionWithOneLine()
    {
        string position = AssetFolder.Scene(Path.Combine("positions", "nine-ball-side-pocket.json"));
        var (code, stdout, stderr) = CliRun.Run("simulate", position);
        Assert.Equal(2, code);
        Assert.Empty(stdout);
        Assert.Equal($"{position}: $.game: a game block judges the scene's shot, and the scene has none (suggest plays such a position)", stderr.TrimEnd('\n'));
    }
}
