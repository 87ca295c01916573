using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Balls;

/// <summary>
/// The one position type: a layout is immutable, keeps its order, holds a ball once, and is the
/// same value through the match, its shot records, its snapshots, scenes and simulations.
/// </summary>
public sealed class BallLayoutTests
{
    private const double R = 0.028575;
    private static readonly BallId Cue = new(0), One = new(1), Two = new(2), Nine = new(9);
    private static readonly Vec3 A = new(-0.5, 0, R), B = new(0.2, 0.1, R), C = new(0.6, -0.2, R);

    [Fact]
    public void ChangesMakeANewLayoutAndLeaveTheOldOneAsItWas()
    {
        BallLayout layout = [(Cue, A), (One, B)];
        var moved = layout.With(Cue, C);
        var added = layout.With(Nine, C);
        var removed = layout.Without(Cue);
        Assert.Equal([(Cue, A), (One, B)], layout);
        // A ball moved keeps its place in the order; a new ball comes last; a removed one is gone.
        Assert.Equal([(Cue, C), (One, B)], moved);
        Assert.Equal([(Cue, A), (One, B), (Nine, C)], added);
        Assert.Equal([(One, B)], removed);
        Assert.Same(layout, layout.Without(Nine));
        Assert.Equal(C, moved[Cue]);
        Assert.Null(removed.PositionOf(Cue));
        Assert.Throws<KeyNotFoundException>(() => removed[Cue]);
    }

    [Fact]
    public void ABallListedTwiceIsRefused()
    {
        var e = Assert.Throws<ArgumentException>(() => new BallLayout([(One, A), (Two, B), (One, C)]));
        Assert.Contains("ball 1 appears twice", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void LayoutsAreEqualWhenTheirBallsPositionsAndOrderAre()
    {
        BallLayout layout = [(Cue, A), (One, B)];
        Assert.Equal(layout, new BallLayout([(Cue, A), (One, B)]));
        Assert.True(layout.Equals(new BallLayout([(Cue, A), (One, B)])));
        Assert.Equal(layout.GetHashCode(), new BallLayout([(Cue, A), (One, B)]).GetHashCode());
        Assert.False(layout.Equals(new BallLayout([(One, B), (Cue, A)])));
        Assert.False(layout.Equals(layout.With(One, B with { X = Math.BitIncrement(B.X) })));
    }

    [Fact]
    public void OrderingByABallSetPutsItsBallsInItsOrderAndKeepsAnOrderedLayout()
    {
        BallLayout layout = [(Nine, C), (Cue, A), (One, B)];
        var ordered = layout.OrderedBy(BallSet.Pool.Ids);
        Assert.Equal([(Cue, A), (One, B), (Nine, C)], ordered);
        Assert.Same(ordered, ordered.OrderedBy(BallSet.Pool.Ids));
    }

    [Fact]
    public void ASceneAndItsSimulationAreMadeFromALayoutAndGiveItBack()
    {
        var setup = GameSetup.Of(GameRules.NineBall, 3);
        BallLayout layout = [(Cue, A), (One, B), (Nine, C)];
        var scene = Scene.Of(layout, setup.Table, setup.Physics, BallSet.Pool);
        Assert.Equal(layout, scene.Layout);
        var sim = SimulationFactory.Create(scene);
        Assert.Equal(layout, sim.InPlay());
        // A ball taken off the table is not in play.
        sim.RemoveBall(One);
        Assert.Equal(layout.Without(One), sim.InPlay());
    }

    [Fact]
    public void TheMatchItsShotRecordsAndItsSnapshotsShareOneLayoutValue()
    {
        var setup = GameSetup.Of(GameRules.NineBall, 3) with { Position = [(Cue, A), (One, B), (Nine, C)] };
        var game = new Match(setup);
        Assert.Same(setup.Position, game.Balls);
        // A soft shot that pockets nothing: the record's balls are the table at rest, the same value.
        var shot = game.Play(new GameShot(new ShotSpec(1, 10, 0, 0)));
        Assert.Equal(3, shot.After.Count);
        Assert.Same(shot.After, game.Balls);
        var snapshot = game.Snapshot();
        Assert.Same(game.Balls, snapshot.Balls);
        game.Play(new GameShot(new ShotSpec(3, -60, 0, 0)));
        game.Restore(snapshot);
        Assert.Same(snapshot.Balls, game.Balls);
    }

    [Fact]
    public void AGameRecordWithABallListedTwiceIsRefusedWithItsPath()
    {
        var setup = GameSetup.Of(GameRules.NineBall, 3) with { Position = [(Cue, A), (One, B), (Nine, C)] };
        var game = new Match(setup);
        game.Play(new GameShot(new ShotSpec(2, 40, 0, 0)));
        var root = System.Text.Json.Nodes.JsonNode.Parse(GameRecordFile.ToUtf8(game))!;
        root["balls"]![2]!["id"] = "1";
        var e = Assert.Throws<SceneException>(() => GameRecordFile.Parse(root.ToJsonString(), "game.json"));
        Assert.Equal("$.balls[2].id", e.JsonPath);
        Assert.Contains("ball \"1\" is listed twice", e.Message, StringComparison.Ordinal);
    }
}
