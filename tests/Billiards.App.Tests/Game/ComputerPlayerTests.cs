using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Ai;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>The computer at the table and the hint, on the real physics and Core's planner, through a fake window.</summary>
public class ComputerPlayerTests
{
    private sealed class Game : IDisposable
    {
        public Game(params Seat[] players)
        {
            var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball.json"));
            Host = new GameHost(scene, SimulationFactory.Create, Window, Clock, new MatchSetup(GameRules.EightBall, players));
            Match = Host.Tree.Root.GetInTree<MatchNode>();
            Computer = Host.Tree.Root.GetInTree<ComputerPlayerNode>();
            Computer.BudgetMs = 120_000; // never cut short: the same decisions every run
        }

        public FakeWindow Window { get; } = new();
        public ManualClock Clock { get; } = new();
        public GameHost Host { get; }
        public MatchNode Match { get; }
        public ComputerPlayerNode Computer { get; }

        public void Press(Key key, int times = 1)
        {
            for (int i = 0; i < times; i++)
            {
                Window.Press(key);
                Frame();
            }
        }

        public void Frame()
        {
            Clock.Advance(1.0 / 30);
            Host.RunFrame();
        }

        // Frames until the condition holds; the planner's background search takes wall-clock time.
        public void RunUntil(Func<bool> done, string what)
        {
            var limit = DateTime.UtcNow.AddSeconds(120);
            while (!done() && DateTime.UtcNow < limit)
            {
                Frame();
                if (!Host.World.Physics.IsRolling)
                {
                    Thread.Sleep(5);
                }
            }
            Assert.True(done(), what);
        }

        public void Dispose() => Host.Dispose();
    }

    // Game-clock seconds from the computer's aim (its decision taken) to its stroke.
    private static double AimToStroke(bool fast)
    {
        using var game = new Game(new Seat("Computer L1", 1), new Seat("Computer L2", 2));
        game.Computer.Fast = fast;
        game.RunUntil(() => game.Computer.Status?.Contains(" aims", StringComparison.Ordinal) == true, "the computer never aimed");
        double aimed = game.Clock.Now;
        game.RunUntil(() => game.Match.Session.Shots.Count >= 1, "the computer never struck");
        return game.Clock.Now - aimed;
    }

    [Fact]
    public void WhileItAimsTheComputerSaysWhichBallItPlaysIntoWhichPocket()
    {
        var shot = new Billiards.Core.Cue.ShotSpec(2.5, 10);
        Decision Planned(Billiards.Core.Ai.ShotKind kind) => new(shot, null, null, false, kind, new Billiards.Core.Balls.BallId(9), new Billiards.Core.Table.PocketId(1, "head-right"), 0.8, 0.8, 100, 5);
        Assert.Equal("Computer L3 aims: 9 in head-right.", ComputerPlayerNode.AimStatus("Computer L3", Planned(Billiards.Core.Ai.ShotKind.Direct)));
        Assert.Equal("Computer L3 aims a safety on the 9.", ComputerPlayerNode.AimStatus("Computer L3", Planned(Billiards.Core.Ai.ShotKind.Safety)));
        Assert.Equal("Computer L3 aims its break.", ComputerPlayerNode.AimStatus("Computer L3", Planned(Billiards.Core.Ai.ShotKind.Break)));
    }

    [Fact]
    public void TheComputerHoldsItsAimAboutOneAndAHalfSecondsBeforeTheStrokeAndAQuarterOfThatWhenFast()
    {
        const double Frame = 1.0 / 30;
        double normal = AimToStroke(fast: false);
        Assert.InRange(normal, ComputerPlayerNode.StrokeSeconds - Frame, ComputerPlayerNode.StrokeSeconds + (2 * Frame));
        double fast = AimToStroke(fast: true);
        double share = ComputerPlayerNode.StrokeSeconds * ComputerPlayerNode.FastShare;
        Assert.InRange(fast, share - Frame, share + (2 * Frame));
    }

    private static List<(GameState Before, Billiards.Core.Cue.ShotSpec Shot)> ComputerTurnAfterASoftBreak()
    {
        using var game = new Game(new Seat("Anna"), new Seat("Computer L1", 1));
        game.Press(Key.Q, 8); // 1 m/s: a bad break, the computer chooses accept or rerack
        game.Press(Key.Space);
        game.RunUntil(() => game.Match.Session.Rulings.Count >= 1 && !game.Host.World.Physics.IsRolling, "the break never ended");
        Assert.NotEmpty(game.Match.Session.PendingOptions);
        Assert.True(game.Match.Session.IsComputerActing);
        // Anna's keys do nothing on the computer's turn.
        game.Press(Key.D1);
        game.Press(Key.Space);
        Assert.False(game.Host.World.Physics.IsRolling);
        // The computer chooses, then shoots (after turning its cue), and the referee rules.
        game.RunUntil(() => game.Match.Session.Shots.Count >= 2 && !game.Host.World.Physics.IsRolling && game.Match.Session.Rulings.Count >= 2, "the computer never played");
        Assert.Empty(game.Match.Session.PendingOptions);
        var shot = game.Match.Session.Shots[1];
        Assert.Equal(1, shot.Before.Shooter);
        Assert.True(game.Match.Session.Rulings.Count == game.Match.Session.Shots.Count);
        return [.. game.Match.Session.Shots];
    }

    [Fact]
    public void TheComputerChoosesItsOptionThenPlaysItsShotAndTheSameGamePlaysItTheSameWay()
    {
        var first = ComputerTurnAfterASoftBreak();
        var second = ComputerTurnAfterASoftBreak();
        // Seeds derive from the match, the game and the shot: the computer's shot is the same to the last bit.
        Assert.Equal(first[1].Shot, second[1].Shot);
        Assert.Equal(first[1].Before, second[1].Before);
    }

    // The scene's own shot pots the called 8 and wins: the game is over once the balls stop.
    private static (GameHost Host, MatchNode Match, Action Frame) GameWonByTheScenesShot(params Seat[] players)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("rules/eight-ball-on-the-eight.json"));
        var clock = new ManualClock();
        var host = new GameHost(scene, SimulationFactory.Create, new FakeWindow(), clock, new MatchSetup(GameRules.EightBall, players));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        void Frame()
        {
            clock.Advance(1.0 / 30);
            host.RunFrame();
        }
        for (int i = 0; i < 30 * 60 && !match.Session.IsOver; i++)
        {
            Frame();
        }
        Assert.True(match.Session.IsOver, "the scene's shot did not end the game");
        return (host, match, Frame);
    }

    [Fact]
    public void TwoComputersStartTheNextGameByThemselvesAFewSecondsAfterOneEnds()
    {
        var (host, match, frame) = GameWonByTheScenesShot(new Seat("Computer A", 1), new Seat("Computer B", 1));
        using (host)
        {
            Assert.Equal(0, match.Session.Winner);
            Assert.InRange(match.Session.RematchIn!.Value, Session.AutoRematchSeconds - 0.1, Session.AutoRematchSeconds);
            for (int i = 0; i < 30 * (Session.AutoRematchSeconds - 1); i++)
            {
                frame();
            }
            Assert.True(match.Session.IsOver, "the next game started before its time");
            for (int i = 0; i < 60 && match.Session.IsOver; i++)
            {
                frame();
            }
            Assert.False(match.Session.IsOver, "the next game never started");
            Assert.Null(match.Session.RematchIn);
            Assert.Equal(0, match.Session.State.Shot);
            Assert.Equal(1, match.Session.State.Shooter); // the other player breaks
        }
    }

    [Fact]
    public void WithAPersonAtTheTableTheNextGameWaitsForEnter()
    {
        var (host, match, frame) = GameWonByTheScenesShot(new Seat("Anna"), new Seat("Computer", 1));
        using (host)
        {
            Assert.Null(match.Session.RematchIn);
            for (int i = 0; i < 30 * (Session.AutoRematchSeconds + 2); i++)
            {
                frame();
            }
            Assert.True(match.Session.IsOver);
        }
    }

    [Fact]
    public void APausedGameHoldsTheComputerUntilItResumes()
    {
        using var game = new Game(new Seat("Anna"), new Seat("Computer L1", 1));
        game.Press(Key.Q, 8);
        game.Press(Key.Space);
        game.RunUntil(() => game.Match.Session.Rulings.Count >= 1 && !game.Host.World.Physics.IsRolling, "the break never ended");
        game.Press(Key.P);
        for (int i = 0; i < 100; i++)
        {
            game.Frame();
            Thread.Sleep(2);
        }
        Assert.NotEmpty(game.Match.Session.PendingOptions);
        Assert.Single(game.Match.Session.Shots);
        game.Press(Key.P);
        game.RunUntil(() => game.Match.Session.Shots.Count >= 2, "the computer never played after the pause");
    }

    [Fact]
    public void TheHintKeyAsksThePlannerAndTakesItsAimPowerSpinElevationAndCall()
    {
        using var game = new Game(new Seat("Anna"), new Seat("Ben"));
        game.Frame();
        game.Press(ComputerPlayerNode.HintKey);
        Assert.True(game.Computer.IsHinting);
        game.RunUntil(() => game.Computer.LastHint is not null, "no hint came");
        var hint = game.Computer.LastHint!;
        Assert.Equal(hint.Shot.AimDeg, game.Match.AimDegrees, 9);
        Assert.Equal(Math.Clamp(hint.Shot.Speed, MatchNode.MinPower, MatchNode.MaxPower), game.Match.Power, 12);
        Assert.StartsWith("Hint: ", game.Match.Session.Message, StringComparison.Ordinal);
        if (hint.Place is { } place)
        {
            Assert.Equal(place.X, game.Host.World.Physics.CueBallPosition.X, 9);
            Assert.Equal(place.Y, game.Host.World.Physics.CueBallPosition.Y, 9);
        }
        // The break's planned draw and its elevation over the head rail, not the cue's centre and level.
        var cue = game.Host.Tree.Root.GetInTree<CueNode>();
        Assert.NotEqual(0, hint.Shot.TipHeight);
        Assert.True(hint.Shot.ElevationDeg > 1, $"{hint.Shot.ElevationDeg} deg");
        Assert.Equal(hint.Shot.TipSide, cue.Tip.SideFraction, 9);
        Assert.Equal(hint.Shot.TipHeight, cue.Tip.HeightFraction, 9);
        Assert.Equal(hint.Shot.ElevationDeg, cue.ElevationDegrees, 9);
        // Space plays it as a person's shot: the hint's aim, spin and elevation.
        game.Press(Key.Space);
        var played = game.Match.Session.Shots[0].Shot;
        Assert.Equal(hint.Shot.AimDeg, played.AimDeg, 9);
        Assert.Equal(hint.Shot.TipHeight, played.TipHeight, 9);
        Assert.Equal(hint.Shot.ElevationDeg, played.ElevationDeg, 9);
        Assert.Equal(0, game.Match.Session.Shots[0].Before.Shooter);
    }
}
