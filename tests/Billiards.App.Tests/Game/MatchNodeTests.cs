using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;

namespace Billiards.App.Tests.Game;

/// <summary>
/// The match on the real physics and Core's referee, driven by keys through a fake window (no GL):
/// the App carries out rulings and never decides a rule itself.
/// </summary>
public class MatchNodeTests
{
    private static readonly Seat[] TwoPeople = [new("Player 1"), new("Player 2")];

    private sealed class RealGame : IDisposable
    {
        public RealGame(string scenePath, GameRules rules)
        {
            Scene = SceneLoader.Load(scenePath);
            Host = new GameHost(Scene, SimulationFactory.Create, Window, Clock, new MatchSetup(rules, TwoPeople));
            Match = Host.Tree.Root.GetInTree<MatchNode>();
        }

        public Scene Scene { get; }
        public FakeWindow Window { get; } = new();
        public ManualClock Clock { get; } = new();
        public GameHost Host { get; }
        public MatchNode Match { get; }

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
            Clock.Advance(1.0 / 60);
            Host.RunFrame();
        }

        public void RunUntilRest()
        {
            Frame();
            for (int i = 0; i < 60 * 60 && Host.World.Physics.IsRolling; i++)
            {
                Frame();
            }
            Assert.False(Host.World.Physics.IsRolling, "the balls never came to rest");
        }

        public void Dispose() => Host.Dispose();
    }

    [Fact]
    public void ASceneSOwnShotIsJudgedAsSimulateJudgesItAndTheGameReplaysFromTheScene()
    {
        string path = AssetFolder.Scene(Path.Combine("rules", "nine-ball-push-out.json"));
        using var game = new RealGame(path, GameRules.NineBall);
        Assert.True(game.Host.World.Physics.IsRolling, "the scene's shot plays at once");
        game.RunUntilRest();
        var ruling = Assert.Single(game.Match.Session.Rulings);
        Assert.Equal([RefereeOption.Shoot, RefereeOption.PassBack], game.Match.Session.PendingOptions);

        var (code, stdout, stderr) = Cli.CliRun.Run("simulate", path);
        Assert.True(code == 0, stderr);
        var simulated = System.Text.Json.Nodes.JsonNode.Parse(stdout)!["ruling"];
        var played = System.Text.Json.Nodes.JsonNode.Parse(GameBlockWriter.RulingToUtf8(ruling));
        Assert.True(System.Text.Json.Nodes.JsonNode.DeepEquals(simulated, played), $"{simulated} != {played}");

        // The record starts from the scene's position, not a rack, and replays.
        game.Press(Key.D2); // pass back
        var record = GameRecordFile.Parse(System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(game.Match.Session.Game!)), "w.json");
        Assert.Equal(6, record.Setup.Position!.Count);
        Assert.Equal(RefereeOption.PassBack, record.Shots[0].Choice);
        Assert.Null(GameRecordFile.Verify(record, out _).FirstDifference);
    }

    [Fact]
    public void ASoftBreakIsAFoulWhoseOptionsAreChosenByNumberAndTheTurnPasses()
    {
        using var game = new RealGame(AssetFolder.Scene("eight-ball.json"), GameRules.EightBall);
        Assert.True(game.Host.World.Physics.BallInHand);
        Assert.Equal(PlacementRegion.Kitchen, game.Host.World.Physics.HandRegion);
        game.Press(Key.Q, 8); // 3.0 - 8 x 0.25 = 1 m/s: too soft to drive four balls to a cushion
        game.Press(Key.Space);
        game.RunUntilRest();
        var ruling = Assert.Single(game.Match.Session.Rulings);
        Assert.Contains(Foul.BadBreak, ruling.Fouls);
        Assert.Equal(ruling.Options, game.Match.Session.PendingOptions);
        Assert.Equal(1, game.Match.Session.State.Shooter);
        // Space does nothing while a choice is pending.
        game.Press(Key.Space);
        Assert.False(game.Host.World.Physics.IsRolling);
        int rerack = ruling.Options.ToList().IndexOf(RefereeOption.Rerack);
        Assert.True(rerack >= 0);
        game.Press(Key.D1 + rerack);
        Assert.Empty(game.Match.Session.PendingOptions);
        Assert.Equal(0, game.Match.Session.State.Shot);
        Assert.Equal(PlacementRegion.Kitchen, game.Host.World.Physics.HandRegion);
    }
}

public class MatchHudTests
{
    [Fact]
    public void TheOptionsAreButtonsAClickTakesAndTheHudShowsEachPlayersBallsAsIcons()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball.json"));
        var window = new FakeWindow { FramebufferSize = (1280, 720) };
        var clock = new ManualClock();
        using var host = new GameHost(scene, SimulationFactory.Create, window, clock, new MatchSetup(GameRules.EightBall, [new("Anna"), new("Ben")]));
        var match = host.Tree.Root.GetInTree<MatchNode>();
        void Frame()
        {
            clock.Advance(1.0 / 30);
            host.RunFrame();
        }
        for (int i = 0; i < 8; i++)
        {
            window.Press(Key.Q);
        }
        window.Press(Key.Space);
        for (int i = 0; i < 30 * 120 && host.World.Physics.IsRolling; i++)
        {
            Frame();
        }
        clock.Advance(1.0 / 30);
        var frame = host.RunFrame();
        Assert.NotEmpty(match.Session.PendingOptions);
        var buttons = frame.Hud!.Buttons!;
        Assert.Equal(match.Session.PendingOptions.Select((o, i) => $"{o.ToName()} [{i + 1}]"), buttons.Select(b => b.Label));
        Assert.Equal("Ben chooses:", frame.Hud.Title);

        // The instant replay of that break shows the shot, not the choice over it; leaving it
        // brings the choice back.
        window.Press(InstantReplayNode.ReplayKey);
        clock.Advance(1.0 / 30);
        Assert.True(host.Tree.Root.GetInTree<InstantReplayNode>().IsActive);
        Assert.Null(host.RunFrame().Hud!.Buttons);
        window.Press(InstantReplayNode.ReplayKey);
        clock.Advance(1.0 / 30);
        Assert.False(host.Tree.Root.GetInTree<InstantReplayNode>().IsActive);
        Assert.Equal(buttons.Select(b => b.Label), host.RunFrame().Hud!.Buttons!.Select(b => b.Label));

        var rerack = buttons.Single(b => b.Label.StartsWith("rerack", StringComparison.Ordinal));
        window.MoveTo(rerack.X + 2, rerack.Y + 2);
        window.Down();
        window.Up();
        Assert.Empty(match.Session.PendingOptions);
        Assert.Equal(0, match.Session.State.Shot);
        Assert.Null(host.RunFrame().Hud!.Buttons);

        // Groups taken (a scene's game block at shot 4, the 3 down): each player's line is followed by the balls still needed.
        var lines = new List<string>();
        var icons = new List<HudIcon>();
        var taken = new GameState(GameRules.EightBall) { Players = new PerPlayer<string>("Anna", "Ben"), Shot = 4, Part = new EightBallPart { Groups = new PerPlayer<BallGroup>(BallGroup.Stripes, BallGroup.Solids) } };
        var later = scene with { Game = taken, Balls = [.. scene.Balls.Where(b => b.Id != new BallId(3))] };
        using var grouped = new GameHost(later, SimulationFactory.Create, window, clock, new MatchSetup(GameRules.EightBall, [new("Anna"), new("Ben")]));
        Billiards.App.Hud.MatchLines.Add(lines, grouped.Tree.Root.GetInTree<MatchNode>(), grouped.World.Physics, icons: icons);
        int anna = lines.FindIndex(l => l.Contains("Anna: stripes", StringComparison.Ordinal));
        int ben = lines.FindIndex(l => l.Contains("Ben: solids", StringComparison.Ordinal));
        Assert.Equal([9, 10, 11, 12, 13, 14, 15], icons.Where(i => i.Line == anna).Select(i => i.Number));
        Assert.Equal([1, 2, 4, 5, 6, 7], icons.Where(i => i.Line == ben).Select(i => i.Number));
    }
}

public class SeatTests
{
    [Theory]
    [InlineData("human", 1, "Player 2", null)]
    [InlineData("Anna", 0, "Anna", null)]
    [InlineData(" Ben ", 1, "Ben", null)]
    [InlineData("computer:3", 0, "Computer L3", 3)]
    [InlineData("cpu:1", 1, "Computer L1", 1)]
    [InlineData("CPU:5", 0, "Computer L5", 5)]
    public void ASeatIsAPersonByNameOrTheComputerAtALevel(string text, int seat, string name, int? level)
    {
        var player = Seat.Parse(text, seat)!;
        Assert.Equal(name, player.Name);
        Assert.Equal(level, player.ComputerLevel);
        Assert.Equal(level is null, player.IsHuman);
    }

    [Theory]
    [InlineData("")]
    [InlineData("   ")]
    [InlineData("computer:0")]
    [InlineData("computer:6")]
    [InlineData("cpu:x")]
    [InlineData("a name far longer than twenty-four characters")]
    [InlineData("tab\there")]
    public void AnythingElseIsRefused(string text) => Assert.Null(Seat.Parse(text, 0));

    [Fact]
    public void ASceneGameBlockWithoutNamesTakesThePlayersNamesAndOneWithNamesKeepsThem()
    {
        // FourBallGames seats Anna and Ben (play --players Anna,Ben).
        using (var unnamed = FourBallGames.Start(new GameState(GameRules.StraightPool) { Shot = 5, Score = new PerPlayer<int>(99, 40) }))
        {
            var match = unnamed.World.Tree.Root.GetInTree<MatchNode>();
            Assert.Equal(new PerPlayer<string>("Anna", "Ben"), match.Session.State.Players);
            Assert.Equal(new PerPlayer<int>(99, 40), match.Session.State.Score);
            Assert.StartsWith("Anna", unnamed.Frame().Hud!.Board!.Players[0].Name, StringComparison.Ordinal);
        }
        using var named = FourBallGames.Start(new GameState(GameRules.StraightPool) { Shot = 5, Players = new PerPlayer<string>("Cleo", "Dan") });
        Assert.Equal(new PerPlayer<string>("Cleo", "Dan"), named.World.Tree.Root.GetInTree<MatchNode>().Session.State.Players);
    }

    [Theory]
    [InlineData("eight-ball", 0, MatchNode.DefaultPower)]
    [InlineData("eight-ball", 3, MatchNode.MaxPower)]
    [InlineData("snooker", 0, MatchNode.MaxPower)]
    public void APowerBreakLeavesTheNextShotAtTheStartingPowerAndOtherShotsKeepTheirs(GameRules rules, int shot, double after)
    {
        // FourBallGames' pool table; snooker's break-off is not a power break, whatever the table.
        using var game = FourBallGames.Start(new GameState(rules) { Shot = shot, Players = new PerPlayer<string>("Anna", "Ben") });
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.Frame();
        while (match.Power < MatchNode.MaxPower)
        {
            game.Window.Press(Key.W);
        }
        game.Window.Press(Key.Space);
        game.Frame();
        Assert.Equal(MatchNode.MaxPower, game.Simulation.Strikes[^1].Speed, 12);
        Assert.Equal(after, match.Power);
    }
}
