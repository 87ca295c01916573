using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Game;

/// <summary>Lines the game showed wrongly or stale: the window's title, the help, the hint's rate, the cue's settings while balls roll.</summary>
public class StaleLineTests
{
    [Theory]
    [InlineData("nine-ball", "Anna", "cpu:3", "Billiards: 9-ball, Anna vs Computer L3")]
    [InlineData("straight-pool", "human", "human", "Billiards: 14.1 straight pool, Player 1 vs Player 2")]
    [InlineData("eight-ball", "computer:2", "Ben", "Billiards: 8-ball, Computer L2 vs Ben")]
    public void TheWindowTitleNamesTheGameAndPlayersNotTheScenesName(GameRules rules, string a, string b, string expected)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball.json"));
        Assert.Equal("8-ball for two players", scene.Name);
        var setup = new MatchSetup(rules, [Seat.Parse(a, 0)!, Seat.Parse(b, 1)!]);
        Assert.Equal(expected, PlayCommand.TitleFor(scene, setup));
        Assert.Equal("Billiards: 8-ball for two players", PlayCommand.TitleFor(scene, null));
    }

    [Fact]
    public void TheHelpSpeaksThePlayersLanguageNotTheThesisSections()
    {
        Assert.DoesNotContain(HelpText.Lines, l => l.Contains("seed", StringComparison.OrdinalIgnoreCase));
        Assert.DoesNotContain(HelpText.Lines, l => l.Contains("effet", StringComparison.OrdinalIgnoreCase));
        Assert.Contains(HelpText.Lines, l => l.Contains("spin: left-drag moves the tip", StringComparison.Ordinal));
    }

    private static Decision Hint(ShotKind kind, PocketId pocket, double pot, Call? call) =>
        new(new ShotSpec(2.5, 10), null, call, false, kind, new BallId(3), pocket, pot, 0.4, 100, 5);

    [Fact]
    public void ASafetyHintGivesNoPotRateAndAPotHintDoes()
    {
        string safety = ComputerPlayerNode.HintLine(Hint(ShotKind.Safety, PocketId.None, 0, Call.Safety));
        Assert.Equal("Hint: a safety at 2.5 m/s; Space shoots.", safety);
        string pot = ComputerPlayerNode.HintLine(Hint(ShotKind.Direct, PoolPockets.FootRight, 0.83, new Call(new BallId(3), PoolPockets.FootRight)));
        Assert.Equal("Hint: the 3 in the foot-right pocket at 2.5 m/s (pots 83 % of the time); Space shoots.", pot);
        // A three-cushion point (a carom, no pocket) scores; it does not pot.
        var point = Hint(ShotKind.Carom, PocketId.None, 0.6, null) with { Target = BallSet.Red };
        Assert.Equal("Hint: carom on the red at 2.5 m/s (scores 60 % of the time); Space shoots.", ComputerPlayerNode.HintLine(point));
    }

    [Fact]
    public void TheSpinAndElevationAreNotShownWhileTheBallsRoll()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        var rolling = game.Frame().Hud!.Lines;
        Assert.DoesNotContain(rolling, l => l.StartsWith("Elevation", StringComparison.Ordinal) || l.StartsWith("Spin", StringComparison.Ordinal));
        game.RunUntilRest();
        var resting = game.Frame().Hud!.Lines;
        Assert.Contains(resting, l => l.StartsWith("Elevation", StringComparison.Ordinal));
    }
}
