using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.App.Tests.Game;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Hud;

public class ScoreboardTests
{
    [Fact]
    public void TheResultPanelCountsEachPlayersGameAndRematchClearsTheLastGamesRulings()
    {
        using var game = FourBallGames.EightBall();
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        FourBallGames.PotTheEightEarly(game);
        Assert.True(match.Session.IsOver);
        var hud = game.Frame().Hud!;
        var result = hud.Result!;
        Assert.Equal("Ben wins the 8-ball game", result.Title);
        Assert.Equal(1, result.Stats.First.Shots);
        Assert.Equal(0, result.Stats.Second.Shots);
        Assert.Equal(1, result.Games.Second);
        Assert.Contains(hud.Buttons!, b => b.Label == "Rematch [Enter]");
        Assert.Contains(hud.Buttons!, b => b.Label == $"Menu [{MenuNode.MenuKey}]");
        string lastRuling = match.Session.Game!.LastRuling!.Message;
        Assert.Equal(lastRuling, hud.Board!.Message);

        // M opens the start menu over the game, without the result panel; Escape keeps the game and brings it back.
        game.Window.Press(MenuNode.MenuKey);
        Assert.Equal(MenuPage.Start, game.World.Menu.Page);
        Assert.Null(game.Frame().Hud!.Result);
        game.Window.Press(Key.Escape);
        Assert.Equal(MenuPage.None, game.World.Menu.Page);
        Assert.NotNull(game.Frame().Hud!.Result);

        // A click on Rematch starts the next game: no result, no ruling of the last game on the board.
        var centre = game.World.Menu.CentreOf("Rematch")!.Value;
        game.Window.MoveTo(centre.X, centre.Y);
        game.Window.Down();
        game.Window.Up();
        hud = game.Frame().Hud!;
        Assert.False(match.Session.IsOver);
        Assert.Null(hud.Result);
        Assert.Empty(hud.Board!.Log);
        Assert.NotEqual(lastRuling, hud.Board.Message);
        Assert.DoesNotContain(hud.Lines, l => l.Contains(lastRuling, StringComparison.Ordinal));

        // The session's record keeps the first game; the rematch joins it once it has a shot, a line each.
        Assert.Equal(2, match.Session.Games.Count);
        Assert.Equal([match.Session.Games[0]], match.Session.RecordedGames);
        FourBallGames.PotTheEightEarly(game);
        Assert.Equal(match.Session.Games, match.Session.RecordedGames);
        string[] lines = System.Text.Encoding.UTF8.GetString(GameRecordFile.ToJsonLines(match.Session.RecordedGames)).Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(2, lines.Length);
        Assert.All(lines, l => Assert.Single(GameRecordFile.Parse(l, "session.json").Shots));
        Assert.NotEqual(GameRecordFile.Parse(lines[0], "session.json").Setup.Seed, GameRecordFile.Parse(lines[1], "session.json").Setup.Seed);
    }

    [Fact]
    public void EightBallShowsNoFoulsInARowAndNineBallShowsThreeAfterTheThird()
    {
        using (var eight = FourBallGames.Start(new GameState(GameRules.EightBall) { Shot = 3, FoulsInRow = new PerPlayer<int>(2, 0), Players = new PerPlayer<string>("Anna", "Ben") }))
        {
            var board = eight.Frame().Hud!.Board!;
            Assert.DoesNotContain("fouls", board.Players[0].Detail, StringComparison.Ordinal);
        }
        // Nine-ball, Anna on two fouls: a miss is her third, and the game is lost on it.
        const string Nine = """
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
              "balls": [ { "id": "cue", "position": [-0.635, 0.0] }, { "id": "1", "position": [0.5, 0.3] }, { "id": "9", "position": [0.8, -0.3] } ] }
            """;
        var scene = SceneLoader.Parse(Nine, "n.json") with
        {
            Game = new GameState(GameRules.NineBall) { Shot = 5, FoulsInRow = new PerPlayer<int>(2, 0), Players = new PerPlayer<string>("Anna", "Ben") },
        };
        using var nine = new TestGame(scene, new MatchSetup(GameRules.NineBall, [new Seat("Anna"), new Seat("Ben")]));
        var match = nine.World.Tree.Root.GetInTree<MatchNode>();
        Assert.Contains("fouls in a row 2", nine.Frame().Hud!.Board!.Players[0].Detail, StringComparison.Ordinal);
        match.AimAt(180); // away from every ball: no first contact, a foul
        for (int i = 0; i < 10; i++)
        {
            nine.Window.Press(Key.Q);
        }
        nine.Window.Press(Key.Space);
        nine.RunUntilRest();
        nine.Frame();
        Assert.True(match.Session.IsOver);
        Assert.Contains("fouls in a row 3", nine.Frame().Hud!.Board!.Players[0].Detail, StringComparison.Ordinal);
    }

    [Fact]
    public void ACardWhoseTargetAndDetailDoNotFitShowsTheDetailBesideTheNameOrTheTargetInTheEmptyBallRowUncut()
    {
        var card = new PlayerCard("Ben", true, "71, free ball: black", [], "break 12");
        var (name, beside, ballRow, info) = Billiards.App.Rendering.HudRenderer.CardRows(card, 24);
        Assert.Equal(("Ben", "break 12", null, "71, free ball: black"), (name, beside, ballRow, info));
        // Where both fit they share the row under the balls.
        Assert.Equal(("Ben", null, null, "71, on a red  break 12"), Billiards.App.Rendering.HudRenderer.CardRows(card with { Target = "71, on a red" }, 24));
        // Where the name leaves no room: a card without balls puts the target in the balls' row (14.1's score stays whole) ...
        var pool = new PlayerCard("Player 2", false, "3 balls on the table", [], "score 99 of 100  run 4");
        Assert.Equal(("Player 2", null, "3 balls on the table", "score 99 of 100  run 4"), Billiards.App.Rendering.HudRenderer.CardRows(pool, 24));
        // ... and one with balls cuts the row as before.
        var crowded = Billiards.App.Rendering.HudRenderer.CardRows(card with { Name = "Computer L5 (thinking)", Balls = [7] }, 24);
        Assert.Null(crowded.BesideName);
        Assert.Null(crowded.BallRow);
        Assert.Equal(24, crowded.Info.Length);
        Assert.EndsWith("...", crowded.Info, StringComparison.Ordinal);
    }

    [Fact]
    public void TheResultPanelsHighestRunIsTheBestVisitInBallsThatStayedDownAndSnookersIsInPoints()
    {
        var state = new GameState(GameRules.StraightPool);
        MatchShot Shot(int shooter, bool legal, bool go, int[] pocketed, int[] spotted, int points = 0) => new(state with { Shooter = shooter },
            new GameShot(new Billiards.Core.Cue.ShotSpec(1, 0, 0, 0)),
            new Ruling(legal, [], [.. pocketed.Select(b => new BallId(b))], go, BallInHand.None, [.. spotted.Select(b => new BallId(b))], [], false, null, "", state) { Points = points }, []);
        // Anna: 3 balls in a visit, then 1; Ben: 2 pocketed of which 1 spotted, then a foul that pockets 2.
        MatchShot[] shots =
        [
            Shot(0, true, true, [1, 2], [], 2), Shot(0, true, true, [3], [], 1), Shot(0, true, false, [], []),
            Shot(1, true, true, [4, 5], [5], 1), Shot(1, false, false, [6, 7], []),
            Shot(0, true, true, [8], [], 1),
        ];
        var pool = PlayerStats.Of(Ruleset.For(GameRules.StraightPool), shots);
        Assert.Equal(new PlayerStats(4, 4, 0, 3) { BreakSum = 4, Visits = 2 }, pool.First);
        Assert.Equal(new PlayerStats(2, 2, 1, 1) { BreakSum = 1, Visits = 1 }, pool.Second);
        // Snooker's break is the visit's points: Anna's 3, Ben's 1 (a foul's points are the opponent's).
        Assert.Equal((3, 1), (PlayerStats.Of(Ruleset.For(GameRules.Snooker), shots).First.HighestBreak, PlayerStats.Of(Ruleset.For(GameRules.Snooker), shots).Second.HighestBreak));
        var panel = new ResultPanel("Anna wins the 14.1 game 100-62", new PerPlayer<string>("Anna", "Ben"), pool, new PerPlayer<int>(1, 0));
        Assert.Contains(("Highest run", "3", "1"), panel.Rows);
        Assert.Contains(("Games won", "1", "0"), panel.Rows);
        Assert.Contains(("Frames won", "1", "0"), (panel with { GameWord = "frame" }).Rows);
    }

    [Fact]
    public void AThreeCushionResultPanelIsTheScoreSheetPointsInningsAverageAndHighestRun()
    {
        var stats = new PerPlayer<PlayerStats>(new PlayerStats(15, 0, 0, 4) { BreakSum = 8, Visits = 7 }, new PlayerStats(9, 0, 1, 2) { BreakSum = 3, Visits = 7 });
        var panel = new ResultPanel("Anna wins the 3-cushion game 8-3", new PerPlayer<string>("Anna", "Ben"), stats, new PerPlayer<int>(1, 0)) { ScoreSheet = true };
        Assert.Equal(["Points", "Innings", "Average", "Highest run", "Games won"], panel.Rows.Select(r => r.Label));
        Assert.Contains(("Average", "1.143", "0.429"), panel.Rows);
        Assert.Contains(("Innings", "7", "7"), panel.Rows);
    }

    [Fact]
    public void A141GameWonOnItsLastBallShowsTheWinningScoreOnTheCardsAndThePanel()
    {
        using var game = FourBallGames.Start(new GameState(GameRules.StraightPool) { Shot = 5, Target = 100, Score = new PerPlayer<int>(99, 40), Players = new PerPlayer<string>("Anna", "Ben") });
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.Frame();
        var call = Assert.IsType<Call>(match.Call.CurrentCall);
        game.Window.Press(Key.Space);
        game.Frame();
        // The cue ball hits the called ball, which drops in the called pocket: a legal pot, the 100th point.
        game.Simulation.Hit(PoolBalls.Cue, call.Ball);
        game.Simulation.Pocket(call.Ball, call.Pocket.Index);
        game.RunUntilRest();
        var hud = game.Frame().Hud!;
        Assert.True(match.Session.IsOver);
        Assert.Equal("Anna wins the 14.1 game 100-40", hud.Result!.Title);
        Assert.StartsWith("score 100 of 100", hud.Board!.Players[0].Detail, StringComparison.Ordinal);
        Assert.StartsWith("score 40 of 100", hud.Board.Players[1].Detail, StringComparison.Ordinal);
        Assert.Contains(("Highest run", "1", "0"), hud.Result.Rows);
    }
}
