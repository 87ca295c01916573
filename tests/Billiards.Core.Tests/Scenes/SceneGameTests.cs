using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Scenes;

/// <summary>Which game a scene is, decided in one place (<see cref="SceneGame"/>).</summary>
public class SceneGameTests
{
    [Fact]
    public void TheGameBlocksRulesComeBeforeTheScenesRulesAndAnUnknownNameIsNoGame()
    {
        Assert.Equal(GameRules.Snooker, SceneGame.Of("snooker", "eight-ball"));
        Assert.Equal(GameRules.NineBall, SceneGame.Of(null, "nine-ball"));
        Assert.Equal(GameRules.TenBall, SceneGame.Of("no-such-game", "ten-ball"));
        Assert.Null(SceneGame.Of(null, null));
        Assert.Null(SceneGame.Of("no-such-game", null));
    }

    [Fact]
    public void ASceneOfNoGameTakesTheBallsOfItsRacksGameElseOfTheGamePlayedOnItsTable()
    {
        Assert.Same(BallSet.Snooker, SceneGame.BallSetOf("snooker", null));
        Assert.Same(BallSet.Carom, SceneGame.BallSetOf("three-cushion", "pool-9ft"));
        Assert.Same(BallSet.Carom, SceneGame.BallSetOf(null, CaromTable.Preset));
        Assert.Same(BallSet.Snooker, SceneGame.BallSetOf(null, SnookerTable.Preset));
        Assert.Same(BallSet.Pool, SceneGame.BallSetOf(null, "pool-9ft"));
        Assert.Same(BallSet.Pool, SceneGame.BallSetOf(null, null));
    }

    public static TheoryData<string> RuleScenes => new(Directory.GetFiles(AssetFolder.Scene("rules"), "*.json").Select(Path.GetFileName)!);

    [Theory]
    [MemberData(nameof(RuleScenes))]
    public void AShippedRulesSceneIsPlayedAsTheGameItsFileNames(string file)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(Path.Combine("rules", file)));
        var game = Assert.NotNull(scene.PlayedAs);
        Assert.StartsWith(game.Name, file, StringComparison.Ordinal);
        Assert.Same(Ruleset.For(game).BallSet, scene.BallSet);
    }
}
