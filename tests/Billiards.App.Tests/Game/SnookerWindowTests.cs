using Billiards.App.Game;
using Billiards.App.Hud;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Game;

/// <summary>Snooker in the window: the start menu, ball in hand in the D, nominating, the options as buttons, and the scoreboard's figures.</summary>
public class SnookerWindowTests
{
    // The cue ball in baulk, one red, the blue and the black: a red on, 8 + 27 = 35 points remaining.
    private const string Json = """
        { "format": "billiards-scene/1", "table": { "preset": "snooker-12ft" }, "physics": { "dt": 0.00390625 },
          "balls": [ { "id": "cue", "position": [-1.2, 0.1] }, { "id": "red-1", "position": [0.6, 0.3] },
                     { "id": "blue", "position": [0.0, 0.0] }, { "id": "black", "position": [1.46, 0.0] } ] }
        """;

    private static readonly BallId Blue = BallSet.Colour("blue");
    private static readonly BallId Black = BallSet.Colour("black");

    private static TestGame Start(GameState state)
    {
        var scene = SceneLoader.Parse(Json, "s.json") with { Game = state with { Players = new PerPlayer<string>("Anna", "Ben") } };
        return new TestGame(scene, new MatchSetup(GameRules.Snooker, [new Seat("Anna"), new Seat("Ben")]));
    }

    [Fact]
    public void SnookerIsAGameOfTheStartMenu()
    {
        using var game = new TestGame();
        game.World.Menu.ShowStart(Billiards.App.Hud.MenuPage.Play);
        game.Frame();
        var centre = game.World.Menu.CentreOf("Snooker");
        Assert.NotNull(centre);
        game.Window.MoveTo(centre!.Value.X, centre.Value.Y);
        game.Window.Down();
        game.Window.Up();
        Assert.Equal(GameRules.Snooker, game.World.Menu.StartGame);
        Assert.True(File.Exists(Billiards.App.Cli.PlayCommand.FindRulesScene(GameRules.Snooker)));
    }

    [Fact]
    public void TheBreakOffIsPlayedFromTheDAndTheCueBallCannotLeaveIt()
    {
        using var game = Start(new GameState(GameRules.Snooker));
        game.Frame();
        var physics = game.World.Physics;
        Assert.True(physics.BallInHand);
        Assert.Equal(PlacementRegion.D, physics.HandRegion);
        Assert.True(SnookerTable.InD(physics.Table, physics.CueBallPosition), $"the cue ball starts at {physics.CueBallPosition}");
        double baulk = SnookerTable.BaulkLineX(physics.Table), r = physics.BallRadius;
        // In the D (behind the line, within its radius of the brown spot); just in front of the line, and beside the arc, refused.
        Assert.True(physics.TryPlaceCueBall(new Vec3(baulk - 0.1, -0.2, r)));
        Assert.False(physics.TryPlaceCueBall(new Vec3(baulk + 0.02, 0, r)));
        Assert.False(physics.TryPlaceCueBall(new Vec3(baulk - 0.1, 0.29, r)));
        Assert.Equal(new Vec3(baulk - 0.1, -0.2, r), physics.CueBallPosition);
        Assert.Contains("in the D", game.Frame().Hud!.Board!.Status, StringComparison.Ordinal);
    }

    [Fact]
    public void AfterARedBAndAClickNominateAColourAndTheStrikeCarriesTheNomination()
    {
        using var game = Start(new GameState(GameRules.Snooker) { Shot = 3, Score = new PerPlayer<int>(1, 0), Part = new SnookerPart { BallOn = SnookerRuleset.Colour } });
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.Frame();
        Assert.True(match.NeedsNomination);
        Assert.False(match.NeedsCall);
        // B goes round the colours on the table only (never the red): the blue, then the black.
        game.Window.Press(Key.B);
        var first = match.Call.CurrentNomination!.Ball;
        game.Window.Press(Key.B);
        var second = match.Call.CurrentNomination!.Ball;
        Assert.Equal(new HashSet<BallId> { Blue, Black }, new HashSet<BallId> { first, second });
        Assert.Contains($"Nominate: {BallSet.NameOfAny(second)}", game.Frame().Hud!.Board!.Status, StringComparison.Ordinal);
        // A click on the red nominates nothing (a red is not a colour); a click on a colour does.
        match.Call.CallBall(BallSet.Snooker.Ids.First(SnookerRuleset.IsRed));
        Assert.Equal(second, match.Call.CurrentNomination!.Ball);
        match.Call.CallBall(first);
        Assert.Equal(first, match.Call.CurrentNomination!.Ball);
        game.Window.Press(Key.Space);
        Assert.Equal(Call.Nominate(first), match.Session.Shots[^1].Before.Call);
    }

    [Fact]
    public void AMissOffersPlayPutBackAndReplaceAsButtonsAndReplacePutsTheBallsBack()
    {
        using var game = Start(new GameState(GameRules.Snooker) { Shot = 3, Part = new SnookerPart { BallOn = SnookerRuleset.Red } });
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.Frame();
        var before = game.World.Physics.CueBallPosition;
        match.AimAt(180); // away from every ball: no contact, a foul and a miss
        game.Window.Press(Key.Space);
        game.RunUntilRest();
        var hud = game.Frame().Hud!;
        Assert.Equal([RefereeOption.Play, RefereeOption.PutBack, RefereeOption.Replace], match.Session.PendingOptions);
        Assert.Contains(hud.Buttons!, b => b.Label == "play [1]");
        Assert.Contains(hud.Buttons!, b => b.Label == "put-back [2]");
        Assert.Contains(hud.Buttons!, b => b.Label == "replace [3]");
        Assert.Equal(1, match.Session.State.Shooter);
        Assert.Equal(4, match.Session.State.Score[1]);

        var centre = game.World.Menu.CentreOf("replace")!.Value;
        game.Window.MoveTo(centre.X, centre.Y);
        game.Window.Down();
        game.Window.Up();
        game.Frame();
        Assert.Empty(match.Session.PendingOptions);
        Assert.Equal(0, match.Session.State.Shooter);
        Assert.Equal(before, game.World.Physics.CueBallPosition);
    }

    [Fact]
    public void TheScoreboardShowsTheBreakThePointsRemainingTheBallOnAndWhoNeedsSnookers()
    {
        using var game = Start(new GameState(GameRules.Snooker) { Shot = 9, Score = new PerPlayer<int>(0, 60), Part = new SnookerPart { BallOn = SnookerRuleset.Red } });
        var board = game.Frame().Hud!.Board!;
        Assert.Contains("remaining 35", board.Title, StringComparison.Ordinal);
        Assert.Contains("on a red", board.Players[0].Target, StringComparison.Ordinal);
        Assert.Contains("0", board.Players[0].Target, StringComparison.Ordinal);
        Assert.Contains("60", board.Players[1].Target, StringComparison.Ordinal);
        Assert.Contains("break 0", board.Players[0].Detail, StringComparison.Ordinal);
        // 60 behind with 35 on the table: Anna needs snookers, Ben does not.
        Assert.Contains("needs snookers", board.Players[0].Detail, StringComparison.Ordinal);
        Assert.DoesNotContain("needs snookers", board.Players[1].Detail, StringComparison.Ordinal);
    }

    [Fact]
    public void TheBreakIsThePointsOfTheVisitAtTheTable()
    {
        var state = new GameState(GameRules.Snooker);
        MatchShot Shot(int shooter, int points, bool go) => new(state with { Shooter = shooter }, new GameShot(new Billiards.Core.Cue.ShotSpec(1, 0, 0, 0)),
            new Ruling(true, [], [], go, BallInHand.None, [], [], false, null, "", state) { Points = points }, []);
        // Ben's visit ended; Anna then potted a red (1) and the black (7) and is still at the table.
        var shots = new[] { Shot(1, 1, true), Shot(1, 0, false), Shot(0, 1, true), Shot(0, 7, true) };
        var snooker = Ruleset.For(GameRules.Snooker);
        Assert.Equal(8, ScoreboardBuilder.CurrentBreak(snooker, shots, 0));
        Assert.Equal(0, ScoreboardBuilder.CurrentBreak(snooker, shots, 1));
        Assert.Equal(0, ScoreboardBuilder.CurrentBreak(snooker, [.. shots, Shot(0, 0, false)], 0));
    }
}
