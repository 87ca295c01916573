using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

public class TargetViewTests
{
    // The 8 lies nearest the cue ball, but on an open table it is not a legal target: the 2 is the nearest that is.
    private const string Json = """
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
          "balls": [ { "id": "cue", "position": [-0.635, 0.0] }, { "id": "8", "position": [-0.5, 0.1] },
                     { "id": "2", "position": [-0.2, -0.3] }, { "id": "1", "position": [0.635, 0.3] } ] }
        """;

    private static double AimTo(TestGame game, BallId id)
    {
        var sim = game.World.Physics.Simulation;
        var to = sim.Balls[sim.IndexOf(id)].Position - game.World.Physics.CueBallPosition;
        return Math.Atan2(to.Y, to.X) * 180 / Math.PI;
    }

    [Fact]
    public void The_view_turns_to_the_nearest_legal_ball_at_the_start_and_after_every_shot()
    {
        // After the break (shot 1), so that a miss is a foul and not a bad break with options.
        var scene = SceneLoader.Parse(Json, "t.json") with { Game = new GameState(GameRules.EightBall) { Shot = 1, Players = new PerPlayer<string>("Anna", "Ben") } };
        using var game = new TestGame(scene, new MatchSetup(GameRules.EightBall, [new MatchPlayer("Anna"), new MatchPlayer("Ben")]));
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        var view = game.World.Tree.Root.GetInTree<TargetViewNode>();
        game.Frame();
        Assert.Equal(new BallId(2), view.LastTarget);
        Assert.Equal(AimTo(game, new BallId(2)), match.AimDegrees, 9);

        // Aim away at the far rail and play it: the fake physics rolls the cue ball along without touching a ball.
        match.AimAt(150);
        for (int i = 0; i < 10; i++)
        {
            game.Window.Press(Key.Q);                   // 0.5 m/s: 6 cm on the fake cloth
        }
        game.Window.Press(Key.Space);
        game.RunUntilRest();
        game.Frame();
        game.Frame();
        Assert.Equal(1, match.State.Shooter);            // a foul: Ben to shoot
        var nearest = TargetViewNode.NearestTarget(match, game.World.Physics)!.Value;
        Assert.NotEqual(new BallId(8), nearest.Id);
        Assert.Equal(nearest.Id, view.LastTarget);
        Assert.Equal(AimTo(game, nearest.Id), match.AimDegrees, 9);
    }

    [Fact]
    public void On_a_rematch_the_view_turns_to_the_new_racks_nearest_legal_ball()
    {
        var scene = SceneLoader.Parse(Json, "t.json") with { Game = new GameState(GameRules.EightBall) { Shot = 1, Players = new PerPlayer<string>("Anna", "Ben") } };
        using var game = new TestGame(scene, new MatchSetup(GameRules.EightBall, [new MatchPlayer("Anna"), new MatchPlayer("Ben")]));
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        var view = game.World.Tree.Root.GetInTree<TargetViewNode>();
        game.Frame();
        // The 8 goes down early: Anna loses, the game is over.
        game.Window.Press(Key.Space);
        game.Frame();
        game.Simulation.Pocket(new BallId(8));
        game.RunUntilRest();
        game.Frame();
        Assert.True(match.IsOver);
        match.AimAt(150);
        match.Rematch();
        game.Frame();
        game.Frame();
        Assert.False(match.IsOver);
        Assert.Equal(0, match.State.Shot);
        var nearest = TargetViewNode.NearestTarget(match, game.World.Physics)!.Value;
        Assert.Equal(nearest.Id, view.LastTarget);
        Assert.Equal(AimTo(game, nearest.Id), match.AimDegrees, 9);
        Assert.Equal(15, game.World.Physics.Simulation.Ids.Count(id => !PoolBalls.IsCue(id)));
    }
}
