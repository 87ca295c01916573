using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The diamond aid in the window (F4) and the tracking lines' cushion count, on a three-cushion
/// game with the real physics: the aid's contacts are those of the shot the window then plays.
/// </summary>
public class DiamondAidNodeTests
{
    private static Scene Carom => SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "three-cushion.json"));

    private static TestGame Game(Scene scene, string rules) =>
        new(scene, new MatchSetup(rules, [new Seat("Anna"), new Seat("Ben")]), create: SimulationFactory.Create);

    [Fact]
    public void TheAidShowsThePathToTheThirdCushionThatTheShotThenTakes()
    {
        using var game = Game(Carom, "three-cushion");
        game.Frame();
        game.Frame();
        var aid = game.World.Tree.Root.GetInTree<DiamondAidNode>();
        Assert.Null(aid.Path);
        // A cut on the red, a little faster than the default.
        game.Window.Press(Key.W);
        for (int i = 0; i < 12; i++)
        {
            game.Window.Press(Key.Left);
        }
        game.Window.Press(DiamondAidNode.ToggleKey);
        var frame = game.Frame();
        Assert.True(aid.Visible);
        var path = Assert.IsType<DiamondPath>(aid.Path);
        Assert.Equal(DiamondAid.Cushions, path.Contacts.Count);
        // On the screen: the path, a ring at each contact, and each contact's count and diamond number.
        Assert.Equal(DiamondAid.Cushions, frame.Hud!.Aids!.Count(s => s.Radius > 0));
        var labels = frame.Hud.Labels!.Select(l => l.Text).ToList();
        Assert.All(path.Contacts, k => Assert.Contains(DiamondAidNode.ContactLabel(k), labels));

        // The shot the window plays: the same cushions at the same times, on the same rails.
        var planned = aid.Shot!;
        game.Window.Press(Key.Space);
        game.Frame();
        Assert.Null(aid.Path);
        // The shot's events as they come, frame by frame (the table is laid out afresh once it rests).
        var events = new List<SimEvent>();
        for (int i = 0; i < 10_000 && game.World.Physics.IsRolling; i++)
        {
            var log = game.World.Physics.Simulation.Events.AsSpan();
            if (log.Length > events.Count)
            {
                events = [.. log];
            }
            game.Frame();
        }
        Assert.False(game.World.Physics.IsRolling);
        var whites = events.Where(e => e.Kind == EventKind.BallCushion && e.A == BallSet.White).ToList();
        var cushions = whites.Take(DiamondAid.Cushions).ToList();
        Assert.Equal(path.Contacts.Select(k => k.Time), cushions.Select(e => e.Time));
        var played = game.World.Tree.Root.GetInTree<MatchNode>().Session.Game.Shots[^1];
        Assert.Equal(planned, played.Input.Shot);

        // The tracking lines (K) count the struck ball's cushions: 1, 2, 3 ... at its contacts (the aid off).
        game.Window.Press(DiamondAidNode.ToggleKey);
        game.Window.Press(InstantReplayNode.TracksKey);
        // The lines come from the shot's replay, made in the background: frames until it is there.
        RenderFrame last;
        for (int i = 0; !((last = game.Frame()).Hud!.Labels ?? []).Any() && i < 3000; i++)
        {
            Thread.Sleep(5);
        }
        var counts = last.Hud!.Labels!.Select(l => l.Text).ToList();
        Assert.Equal(Enumerable.Range(1, whites.Count), counts.Select(int.Parse).Order());
    }

    [Fact]
    public void TheAidIsForTheCaromTableOnly()
    {
        using var game = Game(SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "eight-ball.json")), "eight-ball");
        game.Frame();
        game.Window.Press(DiamondAidNode.ToggleKey);
        game.Frame();
        var aid = game.World.Tree.Root.GetInTree<DiamondAidNode>();
        Assert.False(aid.Visible);
        Assert.Null(aid.Path);
    }
}
