using System.Numerics;
using Billiards.App.Game;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

public class DefaultCallTests
{
    // Anna has the solids; the 14 lies straight ahead of the cue ball and nearest it, the 3 and 5 farther off.
    private const string Json = """
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
          "balls": [ { "id": "cue", "position": [-0.635, 0.0] }, { "id": "14", "position": [-0.3, 0.0] },
                     { "id": "3", "position": [0.4, 0.35] }, { "id": "5", "position": [0.6, -0.3] }, { "id": "8", "position": [0.9, 0.0] } ] }
        """;

    private static (TestGame Game, MatchNode Match) Start(int shooter, PerPlayer<BallGroup> groups)
    {
        var scene = SceneLoader.Parse(Json, "t.json") with
        {
            Game = new GameState(GameRules.EightBall) { Shot = 5, Shooter = shooter, Players = new PerPlayer<string>("Anna", "Ben"), Part = new EightBallPart { Groups = groups } },
        };
        var game = new TestGame(scene, new MatchSetup(GameRules.EightBall, [new Seat("Anna"), new Seat("Ben")]));
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.Frame();
        return (game, match);
    }

    [Fact]
    public void OnSolidsTheDefaultCallIsASolidEvenWhenTheCueAimsAtAStripe()
    {
        var (game, match) = Start(0, new PerPlayer<BallGroup>(BallGroup.Solids, BallGroup.Stripes));
        using var _ = game;
        match.AimAt(0); // straight at the 14
        Assert.Equal(new BallId(14), match.Aim!.Ball);
        Assert.True(match.NeedsCall);
        var call = match.Call.CurrentCall!;
        Assert.True(call.Ball.Value is >= 1 and <= 7, $"the default call is the {call.Ball}");
        // The nearest legal ball is the 3.
        Assert.Equal(new BallId(3), call.Ball);
    }

    [Fact]
    public void OnStripesTheAimedStripeIsTheDefaultCall()
    {
        var (game, match) = Start(0, new PerPlayer<BallGroup>(BallGroup.Stripes, BallGroup.Solids));
        using var _ = game;
        match.AimAt(0);
        Assert.Equal(new BallId(14), match.Call.CurrentCall!.Ball);
    }

    // An open table: the 3 lies nearest the cue ball but straight behind the 8, which blocks every
    // line from the cue ball to a ghost ball of the 3; the 5 off to the side is open.
    private const string Blocked = """
        { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" }, "physics": { "dt": 0.00390625 },
          "balls": [ { "id": "cue", "position": [-0.8, 0.0] }, { "id": "8", "position": [-0.4, 0.0] },
                     { "id": "3", "position": [0.0, 0.0] }, { "id": "5", "position": [0.3, 0.5] } ] }
        """;

    [Fact]
    public void TheDefaultCallIsAPotNoBallBlocks()
    {
        var scene = SceneLoader.Parse(Blocked, "t.json") with
        {
            Game = new GameState(GameRules.EightBall) { Shot = 5, Shooter = 0, Players = new PerPlayer<string>("Anna", "Ben") },
        };
        using var game = new TestGame(scene, new MatchSetup(GameRules.EightBall, [new Seat("Anna"), new Seat("Ben")]));
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.Frame();
        foreach (double aim in new[] { 0.0, 24.4 }) // at the 8 (illegal first on an open table), then at the 5
        {
            match.AimAt(aim);
            var call = match.Call.CurrentCall!;
            Assert.Equal(new BallId(5), call.Ball);
            // Independently of the call: no ball within two radii of the 5's line to the pocket or of the cue ball's line to the ghost ball.
            var table = scene.Table;
            double r = scene.BallRadius;
            var balls = scene.Balls.ToDictionary(b => b.Id, b => new Vector2((float)b.Position.X, (float)b.Position.Y));
            var mouth = table.Pockets[call.Pocket.Index].MouthMiddle(table);
            var pocket = new Vector2((float)mouth.X, (float)mouth.Y);
            var five = balls[new BallId(5)];
            var ghost = five - ((float)(2 * r) * Vector2.Normalize(pocket - five));
            foreach (var (id, at) in balls)
            {
                if (id == new BallId(5))
                {
                    continue;
                }
                Assert.True(Distance(at, five, pocket) >= 2 * r - 1e-3, $"aim {aim}: the {id.Value} blocks the 5's line to pocket {call.Pocket.Index}");
                if (id != scene.CueBall)
                {
                    Assert.True(Distance(at, balls[scene.CueBall], ghost) >= 2 * r - 1e-3, $"aim {aim}: the {id.Value} blocks the cue ball's line to the ghost ball");
                }
            }
        }
    }

    private static double Distance(Vector2 p, Vector2 a, Vector2 b)
    {
        var ab = b - a;
        float t = Math.Clamp(Vector2.Dot(p - a, ab) / ab.LengthSquared(), 0, 1);
        return (p - (a + (t * ab))).Length();
    }
}

public class FreeBallNominationTests
{
    [Fact]
    public void AFreeBallWhileOnTheRedsDefaultsToAColour()
    {
        const string Json = """
            { "format": "billiards-scene/1", "table": { "preset": "snooker-12ft" },
              "balls": [ { "id": "cue", "position": [-1.2, 0.0] }, { "id": "red-1", "position": [-0.9, 0.1] },
                         { "id": "red-2", "position": [0.8, 0.3] }, { "id": "pink", "position": [0.9, 0.0] }, { "id": "black", "position": [1.46, 0.0] } ],
              "game": { "rules": "snooker", "players": ["Anna", "Ben"], "shooter": 0, "shot": 3 } }
            """;
        var scene = SceneLoader.Parse(Json, "t.json");
        scene = scene with { Game = scene.Game! with { Part = SnookerPart.Of(scene.Game!) with { FreeBall = true } } };
        using var game = new TestGame(scene, new MatchSetup(GameRules.Snooker, [new Seat("Anna"), new Seat("Ben")]));
        var match = game.World.Tree.Root.GetInTree<MatchNode>();
        game.Frame();
        Assert.True(SnookerPart.Of(match.Session.State).FreeBall && match.NeedsNomination);
        foreach (double aim in new[] { 0.0, 18.0 }) // at nothing in particular, then at the nearest red
        {
            match.AimAt(aim);
            var ball = match.Call.CurrentNomination!.Ball;
            Assert.True(SnookerRuleset.IsColour(ball), $"aim {aim}: the free ball defaults to the {ball.Value}, not a colour");
        }
    }
}
