using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// What the scoreboard and the view tests share: Anna and Ben at a pool table on fake physics with
/// four balls, the 8 nearest the cue ball (on an open table not a legal target: the 2 is the
/// nearest that is), the 11 far up the table.
/// </summary>
internal static class FourBallGames
{
    private const string Json = """
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
          "balls": [ { "id": "cue", "position": [-0.635, 0.0] }, { "id": "8", "position": [-0.5, 0.1] },
                     { "id": "2", "position": [-0.2, -0.3] }, { "id": "11", "position": [0.635, 0.3] } ] }
        """;

    /// <summary>A game from <paramref name="state"/> (its rules, shot and players) on the four balls.</summary>
    public static TestGame Start(GameState state)
    {
        var scene = SceneLoader.Parse(Json, "t.json") with { Game = state };
        return new TestGame(scene, new MatchSetup(state.Rules, [new Seat("Anna"), new Seat("Ben")]));
    }

    /// <summary>An 8-ball game after the break (shot 1, so that a miss is a foul and not a bad break), Anna to shoot.</summary>
    public static TestGame EightBall() => Start(new GameState(GameRules.EightBall) { Shot = 1, Players = new PerPlayer<string>("Anna", "Ben") });

    /// <summary>The shooter strikes and the fake table pockets the 8 during the shot: an early 8, the shooter loses.</summary>
    public static void PotTheEightEarly(TestGame game)
    {
        game.Frame();
        game.Window.Press(Key.Space);
        game.Frame();
        game.Simulation.Pocket(new BallId(8));
        game.RunUntilRest();
        game.Frame();
    }
}
