using Billiards.App.Game;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions.BallCushion;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

public class GameSettingsTests
{
    [Fact]
    public void TheFileLivesUnderTheUsersConfigFolder()
    {
        Assert.Equal(Path.Combine("/x/cfg", "billiards", "settings.json"), GameSettings.DefaultPath(v => v == "XDG_CONFIG_HOME" ? "/x/cfg" : null));
        if (!OperatingSystem.IsWindows())
        {
            Assert.Equal(Path.Combine("/home/anna", ".config", "billiards", "settings.json"), GameSettings.DefaultPath(v => v == "HOME" ? "/home/anna" : null));
        }
    }

    [Fact]
    public void SettingsRoundTripAndABrokenFileGivesTheDefaultsWithOneLine()
    {
        string dir = Directory.CreateTempSubdirectory("billiards-settings-").FullName;
        try
        {
            string path = Path.Combine(dir, "billiards", "settings.json");
            Assert.Equal(GameSettings.Default, GameSettings.Load(path));
            var chosen = new GameSettings(Mathavan2010.Instance, Cloth.Slow);
            chosen.Save(path);
            Assert.Equal(chosen, GameSettings.Load(path));
            foreach (string broken in new[] { "{ not json", """{ "ball_cushion": "han-2006", "cloth": "fast" }""", "[]" })
            {
                File.WriteAllText(path, broken);
                var warnings = new StringWriter();
                Assert.Equal(GameSettings.Default, GameSettings.Load(path, warnings));
                Assert.Single(warnings.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries));
            }
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }

    [Fact]
    public void ApplyingSetsTheCushionAndTheClothOfAStandardSceneOnly()
    {
        var standard = SceneLoader.Load(AssetFolder.Scene("eight-ball.json"));
        var applied = new GameSettings(StrongeCompliant.Instance, Cloth.Fast).Apply(standard);
        Assert.Same(StrongeCompliant.Instance, applied.Physics.Models.BallCushion);
        Assert.Equal((Cloth.Fast.MuS, Cloth.Fast.MuR), (applied.Physics.Params.MuS, applied.Physics.Params.MuR));
        Assert.Equal(standard.Physics.Params with { MuS = Cloth.Fast.MuS, MuR = Cloth.Fast.MuR }, applied.Physics.Params);
        Assert.Equal(standard.Physics, GameSettings.Default.Apply(standard).Physics);
        var thesis = SceneLoader.Load(AssetFolder.Scene("thesis-eight-ball-break.json"));
        Assert.Same(thesis, new GameSettings(StrongeCompliant.Instance, Cloth.Fast).Apply(thesis));
    }

    [Fact]
    public void TheStandardClothLeavesACaromScenesHeatedClothAndAPickedClothReplacesIt()
    {
        var carom = SceneLoader.Load(AssetFolder.Scene("three-cushion.json"));
        Assert.Equal(Cloth.Heated.MuR, carom.Physics.Params.MuR);
        Assert.Equal(carom.Physics.Params, GameSettings.Default.Apply(carom).Physics.Params);
        Assert.Equal(Cloth.Fast.MuR, new GameSettings(StrongeCompliant.Instance, Cloth.Fast).Apply(carom).Physics.Params.MuR);
    }
}
