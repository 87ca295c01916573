using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The take-back (Z) from the shipped script <c>assets/scripts/take-back.json</c> (a break, then Z
/// once the balls rest), played headless through <c>play</c>: in a game that allows take-backs the
/// table and the game come back bit for bit; in one that does not, nothing changes; in practice
/// it always works; against the computer the computer's shot is taken back and played again.
/// </summary>
public class TakeBackTests
{
    private static string Script => Path.Combine(AssetFolder.Assets, "scripts", "take-back.json");

    private sealed class Run
    {
        public GameHost? Host;
        public BallState[]? First;
        public GameState? FirstState;
        public List<(int Shot, int Shooter)> Strikes { get; } = [];

        public PhysicsNode Physics => Host!.Tree.Root.GetInTree<PhysicsNode>();

        public MatchNode? Match => Host!.Tree.Root.FindInTree<MatchNode>();
    }

    private static Run Play(string scene, string? players, bool takeBacks, bool fast = false)
    {
        var clock = new ManualClock();
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var run = new Run();
        var renderer = new WatchingRenderer(_ =>
        {
            // The table as the first frame shows it, before any input.
            run.First ??= run.Physics.Simulation.Balls.ToArray();
            run.FirstState ??= run.Match?.Session.State;
        });
        int code = PlayCommand.Play(AssetFolder.Scene(scene), _ => new GamePlatform(window, new UntilClosedLoop(clock, window, 1.0 / 60), renderer), SimulationFactory.Create, clock,
            new PlayCommand.PlayOptions(Script, null)
            {
                Players = players,
                TakeBacks = takeBacks,
                FastComputer = fast,
                Started = h =>
                {
                    run.Host = h;
                    var physics = h.Tree.Root.GetInTree<PhysicsNode>();
                    var match = h.Tree.Root.FindInTree<MatchNode>();
                    physics.Struck += _ => run.Strikes.Add((match?.Session.State.Shot ?? 0, match?.Session.State.Shooter ?? 0));
                },
            });
        Assert.Equal(0, code);
        Assert.True(window.Closed, "the script never ended");
        return run;
    }

    private static void AssertSameTable(BallState[] expected, ReadOnlySpan<BallState> actual)
    {
        Assert.Equal(expected.Length, actual.Length);
        for (int i = 0; i < expected.Length; i++)
        {
            // Bit for bit: every field of every ball (position, velocity, spin, orientation, state).
            Assert.True(expected[i].Equals(actual[i]), $"ball {i}: {expected[i].Position} against {actual[i].Position}");
            Assert.Equal(BitConverter.DoubleToInt64Bits(expected[i].Position.X), BitConverter.DoubleToInt64Bits(actual[i].Position.X));
            Assert.Equal(BitConverter.DoubleToInt64Bits(expected[i].Position.Y), BitConverter.DoubleToInt64Bits(actual[i].Position.Y));
        }
    }

    [Fact]
    public void InAGameThatAllowsTakeBacksTheScriptTakesTheBreakBackAndTheBallsAreWhereTheyWereBitForBit()
    {
        var run = Play("eight-ball.json", "Anna,Ben", takeBacks: true);
        var match = run.Match!;
        Assert.Single(run.Strikes);
        Assert.Equal(1, match.Session.TakeBackCount);
        Assert.Empty(match.Session.Game!.Shots);
        Assert.Empty(match.Session.Rulings);
        Assert.Equal(run.FirstState, match.Session.State);
        AssertSameTable(run.First!, run.Physics.Simulation.Balls);
        // The rack really moved in between: the break was struck and judged.
        Assert.True(run.Physics.LastShot is not null);
    }

    [Fact]
    public void TakeBacksAreOffByDefaultAndZThenChangesNothing()
    {
        var run = Play("eight-ball.json", "Anna,Ben", takeBacks: false);
        var match = run.Match!;
        Assert.False(match.Session.TakeBacks);
        Assert.Single(match.Session.Game!.Shots);
        Assert.Equal(0, match.Session.TakeBackCount);
        Assert.StartsWith("Take-backs are off", run.Host!.Tree.Root.GetInTree<TakeBackNode>().Refusal, StringComparison.Ordinal);
        Assert.False(run.First!.AsSpan().SequenceEqual(run.Physics.Simulation.Balls));
    }

    [Fact]
    public void InPracticeTheScriptTakesTheScenesBreakBackToTheSceneBitForBit()
    {
        // A scene without rules has no referee: its own break plays at once, and Z takes it back.
        var run = Play("eight-ball-break.json", null, takeBacks: false);
        Assert.Null(run.Match);
        var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball-break.json"));
        var fresh = SimulationFactory.Create(scene);
        fresh.TrackOrientation = true;
        AssertSameTable(fresh.Balls.ToArray(), run.Physics.Simulation.Balls);
        Assert.Equal(0, run.Physics.Simulation.Time);
        // The break went through the scene's session without a referee, and was taken back on its timeline: nothing is left.
        var session = run.Host!.Tree.Root.GetInTree<FreeTableNode>().Session!;
        Assert.Equal(1, session.TakeBackCount);
        Assert.Empty(session.Game.Shots);
        Assert.False(session.CanTakeBack);
    }

    [Fact]
    public void AgainstTheComputerItsShotIsTakenBackTooAndItPlaysThatShotAgain()
    {
        // The computer breaks (the script's stroke meets its turn and strikes nothing); once the
        // turn has passed, Z takes the computer's last shot back and it plays that shot again.
        var run = Play("eight-ball.json", "computer:1,Anna", takeBacks: true, fast: true);
        var match = run.Match!;
        Assert.Equal(1, match.Session.TakeBackCount);
        Assert.All(run.Strikes, s => Assert.Equal(0, s.Shooter));
        int again = Enumerable.Range(1, run.Strikes.Count - 1).Single(k => run.Strikes[k] == run.Strikes[k - 1]);
        // The game's record holds that shot once: the second try.
        Assert.Equal(1, match.Session.Game!.Shots.Count(s => s.Before.Shot == run.Strikes[again].Shot));
        Assert.Equal(run.Strikes.Count - 1, match.Session.Game.Shots.Count);
    }
}
