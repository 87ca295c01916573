using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

public class TargetViewTests
{
    private static double AimTo(TestGame game, BallId id)
    {
        var sim = game.World.Physics.Simulation;
        var to = sim.Balls[sim.IndexOf(id)].Position - game.World.Physics.CueBallPosition;
        return Math.Atan2(to.Y, to.X) * 180 / Math.PI;
    }

    [Fact]
    public void TheViewTurnsToTheNearestLegalBallAtTheStartAndAfterEveryShot()
    {
        // After the break (shot 1), so that a miss is a foul and not a bad break with options.
        using var game = FourBallGames.EightBall();
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
        Assert.Equal(1, match.Session.State.Shooter);            // a foul: Ben to shoot
        var nearest = TargetViewNode.NearestTarget(match, game.World.Physics)!.Value;
        Assert.NotEqual(new BallId(8), nearest.Id);
        Assert.Equal(nearest.Id, view.LastTarget);
        Assert.Equal(AimTo(game, nearest.Id), match.AimDegrees, 9);
    }

    [Fact]
    public void OnARematchTheViewTurnsToTheNewRacksNearestLegalBall()
    {
        using var game = FourBallGames.EightBall();
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        var view = game.World.Tree.Root.GetInTree<TargetViewNode>();
        // The 8 goes down early: Anna loses, the game is over.
        FourBallGames.PotTheEightEarly(game);
        Assert.True(match.Session.IsOver);
        match.AimAt(150);
        match.Rematch();
        game.Frame();
        game.Frame();
        Assert.False(match.Session.IsOver);
        Assert.Equal(0, match.Session.State.Shot);
        var nearest = TargetViewNode.NearestTarget(match, game.World.Physics)!.Value;
        Assert.Equal(nearest.Id, view.LastTarget);
        Assert.Equal(AimTo(game, nearest.Id), match.AimDegrees, 9);
        Assert.Equal(15, game.World.Physics.Simulation.Ids.Count(id => !PoolBalls.IsCue(id)));
    }
}

/// <summary>Snooker's view: the colours on their spots hide reds, so the view aims at a contact the cue ball makes first.</summary>
public class SnookerTargetViewTests
{
    [Fact]
    public void AtTheBreakOffTheViewAimsThinOnARedTheCueBallMeetsFirstNotThroughThePink()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("snooker.json"));
        using var game = new TestGame(scene, new MatchSetup(GameRules.Snooker, [new Seat("Anna"), new Seat("Ben")]), create: SimulationFactory.Create);
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        var physics = game.World.Physics;
        game.Frame();
        // The nearest red is the pack's apex, straight behind the pink: aimed at its centre the cue ball meets the pink.
        var apex = TargetViewNode.NearestTarget(match, physics)!.Value;
        var toApex = apex.Position - physics.CueBallPosition;
        var sim = physics.Simulation;
        Assert.Equal("pink", sim.BallSet.NameOf(AimPreview.Compute(sim.Balls, sim.Ids, sim.IndexOf(physics.CueBall), toApex, physics.BallRadius, [], physics.Table.Pockets).Ball!.Value));
        // The view aims where the first ball met is a red.
        var first = AimPreview.Compute(sim.Balls, sim.Ids, sim.IndexOf(physics.CueBall), game.World.Tree.Root.GetInTree<CueNode>().AimDirection, physics.BallRadius, [], physics.Table.Pockets).Ball;
        Assert.NotNull(first);
        Assert.StartsWith("red-", sim.BallSet.NameOf(first!.Value), StringComparison.Ordinal);
        Assert.Equal(first, game.World.Tree.Root.GetInTree<TargetViewNode>().LastTarget);
    }
}
