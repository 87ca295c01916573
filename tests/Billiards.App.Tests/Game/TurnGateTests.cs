using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// "May this shot be struck now?" asked for every way a shot arrives, through the window as a
/// player meets it: a mouse stroke on the computer's turn, with an option pending and after the
/// game is over is refused with a message (nothing is struck, nothing throws); and the menu's
/// Restart while the computer aims drops the computer's plan, so the new rack is not struck with a
/// plan made for the old one.
/// </summary>
public class TurnGateTests
{
    // A mouse stroke of 2.5 m/s (InputModeNodeTests' stroke): S, then the pull back and the push.
    private static void MouseStroke(FakeWindow window, ManualClock clock)
    {
        window.Press(Key.S);
        double start = clock.Now;
        window.MoveTo(400, 300);
        window.Down();
        (double t, float y)[] path = [(0.010, 320), (0.030, 360), (0.100, 350), (0.120, 320), (0.150, 290)];
        foreach (var (t, y) in path)
        {
            clock.Now = start + t;
            window.MoveTo(400, y);
        }
        window.Up();
    }

    [Fact]
    public void AMouseStrokeOnTheComputersTurnIsRefusedWithAMessage()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball.json"));
        var window = new FakeWindow();
        var clock = new ManualClock();
        using var host = new GameHost(scene, SimulationFactory.Create, window, clock,
            new MatchSetup(GameRules.EightBall, [new Seat("Computer L1", 1), new Seat("Anna")]));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        host.Tree.Root.GetInTree<ComputerPlayerNode>().BudgetMs = 120_000;
        string? before = match.Session.Message;
        MouseStroke(window, clock);
        clock.Advance(1.0 / 60);
        host.RunFrame();
        Assert.False(host.World.Physics.IsRolling, "the person's stroke was played on the computer's turn");
        Assert.Empty(match.Session.Game!.Shots);
        Assert.NotEqual(before, match.Session.Message);
        Assert.Contains("turn", match.Session.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AMouseStrokeWithAnOptionPendingIsRefusedWithAMessage()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball.json"));
        var window = new FakeWindow();
        var clock = new ManualClock();
        using var host = new GameHost(scene, SimulationFactory.Create, window, clock,
            new MatchSetup(GameRules.EightBall, [new Seat("Anna"), new Seat("Ben")]));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        void Frame()
        {
            clock.Advance(1.0 / 60);
            host.RunFrame();
        }
        Frame();
        for (int i = 0; i < 8; i++)
        {
            window.Press(Key.Q); // 1 m/s: a bad break, whose options the incoming player chooses from
            Frame();
        }
        window.Press(Key.Space);
        Frame();
        for (int i = 0; i < 3600 && host.World.Physics.IsRolling; i++)
        {
            Frame();
        }
        Assert.NotEmpty(match.Session.PendingOptions);
        string? before = match.Session.Message;
        MouseStroke(window, clock);
        Frame();
        Assert.False(host.World.Physics.IsRolling, "a stroke was played with an option pending");
        Assert.Single(match.Session.Game!.Shots);
        Assert.NotEmpty(match.Session.PendingOptions);
        Assert.NotEqual(before, match.Session.Message);
        Assert.Contains("option", match.Session.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AMouseStrokeAfterTheGameIsOverIsRefusedWithAMessage()
    {
        using var game = FourBallGames.EightBall();
        FourBallGames.PotTheEightEarly(game);
        var match = game.World.Tree.Find<MatchNode>()!;
        Assert.True(match.Session.IsOver);
        string? before = match.Session.Message;
        int strikes = game.Simulation.Strikes.Count;
        MouseStroke(game.Window, game.Clock);
        game.Frame();
        Assert.False(game.World.Physics.IsRolling, "a stroke was played after the game was over");
        Assert.Equal(strikes, game.Simulation.Strikes.Count);
        Assert.NotEqual(before, match.Session.Message);
        Assert.Contains("over", match.Session.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void RestartWhileTheComputerAimsStrikesTheNewRackWithANewPlan()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball.json"));
        var window = new FakeWindow();
        var clock = new ManualClock();
        using var host = new GameHost(scene, SimulationFactory.Create, window, clock,
            new MatchSetup(GameRules.EightBall, [new Seat("Computer L1", 1), new Seat("Computer L2", 2)]));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        var computer = host.Tree.Root.GetInTree<ComputerPlayerNode>();
        computer.BudgetMs = 120_000; // never cut short: the same decisions every run
        void RunUntil(Func<bool> done, string what)
        {
            var limit = DateTime.UtcNow.AddSeconds(120);
            while (!done() && DateTime.UtcNow < limit)
            {
                clock.Advance(1.0 / 30);
                host.RunFrame();
                if (!host.World.Physics.IsRolling)
                {
                    Thread.Sleep(5);
                }
            }
            Assert.True(done(), what);
        }
        var first = match.Session.Game!;
        RunUntil(() => first.Shots.Count == 1 && !host.World.Physics.IsRolling, "the computer never broke");
        // The second shot aimed: its plan is for the table the break left.
        RunUntil(() => computer.Status?.Contains(" aims", StringComparison.Ordinal) == true, "the computer never aimed its second shot");
        Assert.Single(first.Shots);
        window.Press(Key.Escape);
        window.Press(Key.R);
        var second = match.Session.Game!;
        Assert.NotSame(first, second);
        RunUntil(() => second.Shots.Count >= 1, "the computer never broke the new rack");
        // The same rack and the same seeds as the first game: a plan made for the new rack is the
        // first game's break, bit for bit; the old plan was for the second shot of the old rack.
        Assert.Equal(first.Shots[0].Input.Shot, second.Shots[0].Input.Shot);
    }

    [Fact]
    public void APushOutDeclaredInTheWindowIsShownAndIsTheStruckShots()
    {
        using var game = FourBallGames.Start(new GameState(GameRules.NineBall) { Shot = 1, Players = new PerPlayer<string>("Anna", "Ben") });
        var match = game.World.Tree.Find<MatchNode>()!;
        game.Frame();
        game.Window.Press(Key.O);
        Assert.True(match.PushOut);
        Assert.Contains("declares a push-out", match.Session.Message, StringComparison.Ordinal);
        Assert.Contains("PUSH-OUT", game.Frame().Hud!.Board!.Status, StringComparison.Ordinal);
        game.Window.Press(Key.Space);
        Assert.True(match.Session.Shots[^1].Before.PushOut, "the strike was not judged as the declared push-out");
        Assert.False(match.PushOut);
    }
}
