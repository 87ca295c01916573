using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.App.Practice;
using Billiards.App.Tests.Game;
using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Practice;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Hud;

/// <summary>The defects a new player met (issue 34's list), each pinned by the behaviour it broke.</summary>
public class ListedDefectTests
{
    private static TestGame EightBall(string second = "Player 2", int? level = null)
    {
        var scene = SceneLoader.Load(PlayCommand.FindRulesScene(GameRules.EightBall));
        return new TestGame(scene, new MatchSetup(GameRules.EightBall, [new Seat("Player 1"), new Seat(second, level)]));
    }

    [Fact]
    public void TwoComputersOfOneLevelGetDistinctNames()
    {
        var scene = SceneLoader.Load(PlayCommand.FindRulesScene(GameRules.EightBall));
        var setup = PlayCommand.MatchFor(scene, GameRules.EightBall, "computer:3,computer:3")!;
        Assert.Equal(["Computer L3 (1)", "Computer L3 (2)"], setup.Players.Select(p => p.Name));
        Assert.All(setup.Players, p => Assert.Equal(3, p.ComputerLevel));
        // Different names stay as they are.
        Assert.Equal(["Anna", "Computer L3"], PlayCommand.MatchFor(scene, GameRules.EightBall, "Anna,computer:3")!.Players.Select(p => p.Name));
    }

    [Fact]
    public void AMissJustOutsideTheZoneIsTheBestDistanceSoFar()
    {
        // The cue ball stopped 2.6 cm outside a 5 cm zone: 7.6 cm from its centre, the attempt failed.
        var record = DrillRecord.None.With(new DrillOutcome(false, 1, 0.076, "the cue ball stopped 2.6 cm outside the zone"));
        Assert.Equal(0.076, record.BestDistance);
        Assert.Equal((1, 0), (record.Attempts, record.Successes));
        // A closer attempt betters it; a farther one does not.
        Assert.Equal(0.03, record.With(new DrillOutcome(true, 1, 0.03, "")).BestDistance);
        Assert.Equal(0.076, record.With(new DrillOutcome(false, 1, 0.2, "")).BestDistance);
    }

    [Fact]
    public void RestartWhileTheBallsRollRestartsOnceTheyRest()
    {
        using var game = EightBall();
        game.Frame();
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.World.Physics.Strike(new ShotSpec(2, 0));
        game.Frame();
        Assert.True(game.World.Physics.IsRolling);
        game.Window.Press(Key.Escape);
        game.Frame();
        game.Window.Press(Key.R);
        game.Frame();
        Assert.Equal(MenuPage.None, game.World.Menu.Page);
        Assert.True(game.World.Menu.RestartPending);
        game.RunUntilRest();
        game.Frame();
        Assert.False(game.World.Menu.RestartPending);
        Assert.Equal(0, match.Session.State.Shot);
        Assert.StartsWith("Restart", match.Session.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ARestartClearsTheComputersStatusAndWhatItWasDoing()
    {
        using var game = EightBall();
        game.Frame();
        var computer = game.World.Tree.Root.GetInTree<ComputerPlayerNode>();
        game.Window.Press(ComputerPlayerNode.HintKey);
        game.Frame();
        Assert.Equal("Looking for a shot...", computer.Status);
        game.Window.Press(Key.Escape);
        game.Frame();
        game.Window.Press(Key.R);
        game.Frame();
        Assert.Null(computer.Status);
        Assert.StartsWith("Restart", game.World.Tree.Root.GetInTree<MatchNode>().Session.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AHintsElevationIsForItsShotOnly()
    {
        using var game = EightBall();
        game.Frame();
        var cue = game.World.Tree.Root.GetInTree<CueNode>();
        double own = cue.ElevationDegrees;
        cue.Take(new ShotSpec(3, 0, 0, 0, 19)); // a hint's rail shot
        Assert.Equal(19, cue.ElevationDegrees);
        game.World.Physics.Strike(cue.MakeShot(3));
        Assert.Equal(own, cue.ElevationDegrees);
        game.RunUntilRest();
        Assert.Equal(own, cue.ElevationDegrees);
    }

    [Fact]
    public void ThePlayersOwnElevationAfterAHintStays()
    {
        using var game = EightBall();
        game.Frame();
        var cue = game.World.Tree.Root.GetInTree<CueNode>();
        cue.Take(new ShotSpec(3, 0, 0, 0, 19));
        cue.ChangeElevation(1); // the player raises the hint's cue: their elevation now
        game.World.Physics.Strike(cue.MakeShot(3));
        Assert.Equal(20, cue.ElevationDegrees);
    }

    [Fact]
    public void SnookerHintsAndAimsSayBallsAsAPlayerDoes()
    {
        Assert.True(BallSet.Snooker.TryParse("green", out var green));
        Assert.True(BallSet.Snooker.TryParse("red-11", out var red));
        var nominated = new Decision(new ShotSpec(2, 10), null, Call.Nominate(green), false, ShotKind.Direct, green, PocketId.None, 0.4, 0.6, 100, 5);
        string hint = ComputerPlayerNode.HintLine(nominated);
        Assert.DoesNotContain("none", hint, StringComparison.Ordinal);
        Assert.Contains("the green", hint, StringComparison.Ordinal);
        var safety = nominated with { Call = null, Kind = ShotKind.Safety, Target = red };
        string aim = ComputerPlayerNode.AimStatus("Computer L3", safety);
        Assert.Equal("Computer L3 aims a safety on the red.", aim);
        Assert.DoesNotContain("red-", ComputerPlayerNode.HintLine(safety), StringComparison.Ordinal);
    }

    [Fact]
    public void TheDeveloperLinesInSnookerSayFramesAndNoScoreToReach()
    {
        var scene = SceneLoader.Load(PlayCommand.FindRulesScene(GameRules.Snooker));
        using var game = new TestGame(scene, new MatchSetup(GameRules.Snooker, [new Seat("Anna"), new Seat("Ben")]));
        game.Window.Press(SystemKeysNode.DeveloperKey);
        var hud = game.Frame().Hud!;
        Assert.True(hud.Developer);
        Assert.Contains(hud.Lines, l => l.Contains("frames 0-0", StringComparison.Ordinal));
        Assert.DoesNotContain(hud.Lines, l => l.Contains("games 0-0", StringComparison.Ordinal) || l.Contains("score 0/", StringComparison.Ordinal));
    }

    [Fact]
    public void PracticeShowsThePowerBarAndTheScoreboardNotTheDeveloperPanel()
    {
        var drill = DrillLibrary.Load("stop-shot");
        string data = Path.Combine(Path.GetTempPath(), $"data-{Guid.NewGuid():N}");
        using var game = new TestGame(drill.Scene with { Shot = null }, practice: new PracticeSetup(Path.Combine(data, "p.json"), drill));
        var hud = game.Frame().Hud!;
        Assert.NotNull(hud.Gauges!.Power);
        Assert.Equal("Drill: Stop shot", hud.Board!.Title);
        Assert.Equal("Drill: Stop shot", hud.Board.Players[0].Name);
        Assert.Contains(drill.Goal, hud.Board.Message!, StringComparison.Ordinal);
        Assert.False(hud.Developer);
    }

    // A window that opens under a resting pointer (on Settings, say) reports where the pointer is:
    // that is not a choice, and Enter still opens Play; once the pointer moves, the focus follows it.
    [Fact]
    public void ThePointerWhereTheWindowOpenedDoesNotTakeTheStartMenusFocusUntilItMoves()
    {
        using var game = EightBall("Computer L3", 3);
        game.World.Menu.ShowStart();
        var settings = game.Frame().Hud!.Buttons!.Single(b => b.Label == "Settings");
        game.Window.MoveTo(settings.X + (settings.Width / 2), settings.Y + (settings.Height / 2));
        game.Frame();
        Assert.Equal("Play", game.World.Menu.FocusedLabel);
        game.Window.MoveTo(settings.X + (settings.Width / 2) + 3, settings.Y + (settings.Height / 2));
        game.Frame();
        Assert.Equal("Settings", game.World.Menu.FocusedLabel);
        var play = game.Frame().Hud!.Buttons!.Single(b => b.Label == "Play");
        game.Window.MoveTo(play.X + 5, play.Y + 5);
        game.Frame();
        game.Window.Press(Key.Enter);
        game.Frame();
        Assert.Equal(MenuPage.Play, game.World.Menu.Page);
    }

    [Fact]
    public void TheStartMenuWorksFromTheKeyboardAlone()
    {
        using var game = EightBall("Computer L3", 3);
        string? practice = "none";
        GameRules? started = null;
        game.World.Menu.DrillGallery = DrillLibrary.All();
        game.World.Menu.PracticeRequested += d => practice = d;
        game.World.Menu.StartRequested += (rules, _) => started = rules;
        game.World.Menu.ShowStart();
        game.Frame();
        Assert.Equal("Play", game.World.Menu.FocusedLabel);
        // Drills (after Play online and Practice): down three times, Enter; the first card has the focus; Right, Enter plays the second drill.
        foreach (var key in new[] { Key.Down, Key.Down, Key.Down, Key.Enter, Key.Right, Key.Enter })
        {
            game.Window.Press(key);
            game.Frame();
        }
        Assert.Equal(DrillLibrary.All()[1].Name, practice);
        // Play: Enter, the focus on Start; Up to the opponents, Up to the games (one line or more,
        // as the window's width and the registered games make it), Left to the first game, Right
        // to 9-ball, Enter chooses it; Down to Start, Enter starts.
        game.World.Menu.ShowStart();
        game.Frame();
        game.Window.Press(Key.Enter);
        game.Frame();
        Assert.Equal(MenuPage.Play, game.World.Menu.Page);
        Assert.Equal("Start", game.World.Menu.FocusedLabel);
        void Press(Key key)
        {
            game.Window.Press(key);
            game.Frame();
        }
        Press(Key.Up);
        Assert.Matches("^(Person|Computer [1-5])$", game.World.Menu.FocusedLabel);
        Press(Key.Up);
        for (int i = 0; i < Ruleset.All.Count; i++)
        {
            Press(Key.Left);
        }
        Assert.Equal("8-ball", game.World.Menu.FocusedLabel);
        Press(Key.Right);
        Assert.Equal("9-ball", game.World.Menu.FocusedLabel);
        Press(Key.Enter);
        for (int i = 0; i < 4 && game.World.Menu.FocusedLabel is not ("Start" or "Back"); i++)
        {
            Press(Key.Down);
        }
        if (game.World.Menu.FocusedLabel == "Back")
        {
            Press(Key.Left);
        }
        Assert.Equal("Start", game.World.Menu.FocusedLabel);
        Press(Key.Enter);
        Assert.Equal(GameRules.NineBall, started);
    }
}
