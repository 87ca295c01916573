using System.Text.Json;
using Billiards.App.Cli;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Cli;

/// <summary>simulate on a scene with a game block: the ruling in the result, or one line and exit 2.</summary>
public sealed class SimulateRulingTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-ruling-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = CommandLine.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    [Fact]
    public void SimulatingARulesScenePrintsItsRuling()
    {
        var (code, stdout, stderr) = Run("simulate", AssetFolder.Scene(Path.Combine("rules", "nine-ball-push-out.json")));
        Assert.Equal(0, code);
        Assert.Equal("", stderr);
        using var doc = JsonDocument.Parse(stdout);
        var ruling = doc.RootElement.GetProperty("ruling");
        // A legal push-out by Ben (1): Anna (0) chooses to shoot or pass back.
        Assert.True(ruling.GetProperty("legal").GetBoolean());
        Assert.Equal(["shoot", "pass-back"], ruling.GetProperty("options").EnumerateArray().Select(o => o.GetString()));
        Assert.Equal(0, ruling.GetProperty("next").GetProperty("shooter").GetInt32());
    }

    [Fact]
    public void ABadGameBlockExitsWithTwoAndOneLine()
    {
        string scene = Path.Combine(_dir, "bad-game.json");
        File.WriteAllText(scene, """
            { "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ],
              "shot": { "speed": 1, "aim_deg": 0 }, "game": { "rules": "nine-ball", "shooter": 5 } }
            """);
        var (code, stdout, stderr) = Run("simulate", scene);
        Assert.Equal(CommandLine.BadInput, code);
        Assert.Equal(2, code);
        Assert.Equal("", stdout);
        Assert.Equal($"{scene}: $.game.shooter: player index 5 is out of range (the game has players 0 and 1)", stderr.TrimEnd('\n'));
    }
}
