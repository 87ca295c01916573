using System.Text.Json;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Cli;

/// <summary>A stroke past the miscue limit is a miscue in <c>simulate</c>; the hint (level 3) and the computer (every level) never play one.</summary>
public class NoMiscueTests
{
    [Fact]
    public void SimulateReportsAMiscueForATipAtEightTenths()
    {
        string dir = Directory.CreateTempSubdirectory("billiards-miscue-").FullName;
        try
        {
            string scene = Path.Combine(dir, "miscue.json");
            File.WriteAllText(scene, """
                { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
                  "balls": [ { "id": "cue", "position": [-0.6, 0] } ],
                  "shot": { "speed": 3, "aim_deg": 0, "tip": [0, 0.8], "elevation_deg": 0 } }
                """);
            var (code, stdout, stderr) = CliRun.Run("simulate", scene);
            Assert.True(code == 0, stderr);
            using var result = JsonDocument.Parse(stdout);
            var types = result.RootElement.GetProperty("events").EnumerateArray().Select(e => e.GetProperty("type").GetString()).ToList();
            Assert.Equal(["cue-strike", "miscue"], types.Take(2));
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }

    [Theory]
    [InlineData("positions/eight-ball-open-table.json", 3)]
    [InlineData("positions/eight-ball-in-hand.json", 3)]
    [InlineData("positions/nine-ball-side-pocket.json", 5)]
    [InlineData("positions/eight-ball-stripes.json", 1)]
    public void NeitherTheHintNorTheComputerPlaysAMiscue(string position, int level)
    {
        var (code, stdout, stderr) = CliRun.Run("suggest", AssetFolder.Scene(position), "--level", level.ToString(System.Globalization.CultureInfo.InvariantCulture), "--budget-ms", "300");
        Assert.True(code == 0, stderr);
        using var result = JsonDocument.Parse(stdout);
        var tip = result.RootElement.GetProperty("shot").GetProperty("tip");
        var shot = new ShotSpec(1, 0, tip[0].GetDouble(), tip[1].GetDouble());
        Assert.False(CueStrike.IsMiscue(shot, PhysicsParams.Pool), $"{position} at level {level}: tip [{shot.TipSide}, {shot.TipHeight}]");
    }
}
