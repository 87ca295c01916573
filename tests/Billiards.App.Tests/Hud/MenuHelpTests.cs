using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.App.Tests.Game;
using Billiards.Core.Rules;

namespace Billiards.App.Tests.Hud;

/// <summary>The HUD offers "H or F1: help" under every menu, and the keys open it there.</summary>
public class MenuHelpTests
{
    [Theory]
    [InlineData(Key.H)]
    [InlineData(Key.F1)]
    public void TheHelpKeysOpenAndCloseTheHelpOverTheStartMenu(Key help)
    {
        using var game = new TestGame();
        game.World.Menu.ShowStart();
        var hud = game.Frame().Hud!;
        Assert.Contains(hud.Labels!, l => l.Text.Contains("H: help", StringComparison.Ordinal));
        Assert.False(hud.ShowHelp);

        game.Window.Press(help);
        hud = game.Frame().Hud!;
        Assert.True(hud.ShowHelp);
        // The start menu stays, with its buttons, and took nothing else from the key.
        Assert.Equal(MenuPage.Start, game.World.Menu.Page);
        Assert.Contains(hud.Buttons!, b => b.Label == "Play");

        game.Window.Press(help);
        Assert.False(game.Frame().Hud!.ShowHelp);
        Assert.Equal(MenuPage.Start, game.World.Menu.Page);
    }

    [Fact]
    public void TheHelpOpensOverThePauseMenuTooAndOtherKeysStayWithTheMenu()
    {
        using var game = new TestGame();
        game.Window.Press(Key.Escape);
        game.Window.Press(Key.H);
        Assert.True(game.Frame().Hud!.ShowHelp);
        Assert.Equal(MenuPage.Pause, game.World.Menu.Page);
        game.Window.Press(Key.P);
        Assert.True(game.World.Loop.Paused);
        Assert.Equal(MenuPage.Pause, game.World.Menu.Page);
    }

    [Fact]
    public void TheStartMenuSetsTheComputersPaceInTheGameBehindIt()
    {
        var scene = Billiards.Core.Scenes.SceneLoader.Load(Billiards.App.Cli.PlayCommand.FindRulesScene(Billiards.Core.Rules.GameRules.EightBall));
        using var game = new TestGame(scene, new Billiards.App.Game.MatchSetup(Billiards.Core.Rules.GameRules.EightBall, [new Billiards.Core.Rules.Seat("Anna"), new Billiards.Core.Rules.Seat("Computer L3", 3)]));
        var computer = game.World.Tree.Root.GetInTree<Billiards.App.Game.ComputerPlayerNode>();
        var menu = game.World.Menu;
        Assert.False(computer.Fast);
        menu.ShowStart(MenuPage.Settings);
        game.Frame();
        SystemKeysAndHudTests.Click(game, menu.CentreOf("Computer's pace: watchable")!.Value); // the button switches the pace
        game.Frame();
        Assert.NotNull(menu.CentreOf("Computer's pace: fast"));
        Assert.False(computer.Fast); // not before the settings are left
        SystemKeysAndHudTests.Click(game, menu.CentreOf("Back")!.Value);
        Assert.True(computer.Fast);
        Assert.Equal(MenuPage.Start, menu.Page);
        game.Window.Press(Billiards.App.Platform.Key.Escape); // back to the game behind the menu
        Assert.Equal(MenuPage.None, menu.Page);
        Assert.True(computer.Fast);
        Assert.Same(computer, game.World.Tree.Root.GetInTree<Billiards.App.Game.ComputerPlayerNode>());
    }
}
