using System.Text;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Rules;

/// <summary>
/// Whole games played from shot lists through the physics and the referee, written as
/// "billiards-game/1" records and replayed ruling for ruling.
/// </summary>
public class MatchTests
{
    private static readonly PerPlayer<string> Players = new("Anna", "Ben");

    private static bool IsTarget(Match game, BallId ball) =>
        game.Ruleset.LegalTargets(game.State, game.Balls.Ids.Where(b => !PoolBalls.IsCue(b))).Contains(ball);

    private static Match PlayOut(GameSetup setup, int maxShots = 200)
    {
        var game = new Match(setup);
        bool calls = setup.Ruleset.CallsShots;
        while (!game.IsOver && game.Shots.Count < maxShots)
        {
            var shot = setup.Rules == GameRules.StraightPool && game.State.Shot == 0
                ? Aimer.Break(game, Call.Safety)
                : Aimer.Next(game, b => IsTarget(game, b), calls);
            game.Play(shot);
        }
        return game;
    }

    /// <summary>Every ruling's next state is the state the next shot was judged in (its call, push-out and placement aside).</summary>
    private static void AssertChained(Match game)
    {
        for (int k = 1; k < game.Shots.Count; k++)
        {
            var previous = game.Shots[k - 1];
            var judged = game.Shots[k].Before with { Call = null, PushOut = false, Placement = null };
            if (previous.Ruling.Options.Count == 0 && previous.Ruling.Rerack.Count == 0)
            {
                Assert.Equal(previous.Ruling.Next with { Placement = null }, judged);
            }
        }
    }

    private static void AssertReplays(Match game)
    {
        byte[] written = GameRecordFile.ToUtf8(game);
        var record = GameRecordFile.Parse(Encoding.UTF8.GetString(written), "game.json");
        Assert.Equal(game.Shots.Count, record.Shots.Count);
        Assert.Equal(-1, GameRecordFile.Replay(record, out var replayed));
        Assert.Equal(written, GameRecordFile.ToUtf8(replayed));
    }

    [Theory]
    [InlineData("eight-ball", 3)]
    [InlineData("nine-ball", 4)]
    [InlineData("ten-ball", 3)]
    public void AGamePlayedFromItsShotsEndsInAWinAndReplaysBitForBit(GameRules rules, int seed)
    {
        var game = PlayOut(GameSetup.Of(rules, seed, Players));
        Assert.True(game.IsOver, $"no winner after {game.Shots.Count} shots");
        Assert.True(game.Shots.Count > 5, "a whole game, not a break and a win");
        var last = game.Shots[^1].Ruling;
        // Won by a legal shot on the game ball, not by the opponent's loss.
        Assert.True(last.Legal);
        Assert.Equal(game.Shots[^1].Before.Shooter, last.Winner);
        var gameBall = rules == GameRules.EightBall ? 8 : rules == GameRules.NineBall ? 9 : 10;
        Assert.Contains(new BallId(gameBall), last.Pocketed);
        AssertChained(game);
        AssertReplays(game);
    }

    [Fact]
    public void AStraightPoolGameToTwentyPointsEndsInAWinAndReplaysBitForBit()
    {
        var game = PlayOut(GameSetup.Of(GameRules.StraightPool, 2, Players, target: 20), maxShots: 400);
        Assert.True(game.IsOver, $"no winner after {game.Shots.Count} shots");
        var last = game.Shots[^1].Ruling;
        int winner = last.Winner!.Value;
        Assert.True(last.Legal);
        // The winner's points before the last shot plus one per ball it pocketed reach the target.
        var lastShot = game.Shots[^1];
        Assert.Equal(lastShot.Before.Shooter, winner);
        Assert.True(lastShot.Before.Score[winner] < 20);
        Assert.True(lastShot.Before.Score[winner] + last.Pocketed.Count >= 20);
        // Every shot was judged in the state the ruling before it left (scores, fouls, shooter).
        AssertChained(game);
        AssertReplays(game);
    }

    [Fact]
    public void ANineBallGameThroughAPushOutEndsInAThreeFoulLoss()
    {
        var game = new Match(GameSetup.Of(GameRules.NineBall, 5, Players));
        var opening = game.Play(Aimer.Break(game, null));
        Assert.True(opening.Ruling.Legal, opening.Ruling.Message);
        Assert.Equal(1, game.State.Shot);
        int pusher = game.State.Shooter;
        int other = 1 - pusher;

        // The push-out touches nothing and is legal; the incoming player passes the table back.
        var push = game.Play(Aimer.Roll(game, pushOut: true, choice: RefereeOption.PassBack));
        Assert.True(push.Ruling.Legal);
        Assert.Equal([RefereeOption.Shoot, RefereeOption.PassBack], push.Ruling.Options);
        Assert.Equal(other, push.Ruling.Next.Shooter);
        Assert.Equal(pusher, game.State.Shooter); // passed back

        // Now both roll without contact in turn: the pusher's third foul in a row comes first.
        var fouls = new List<MatchShot>();
        while (!game.IsOver)
        {
            fouls.Add(game.Play(Aimer.Roll(game)));
        }
        Assert.Equal(5, fouls.Count);
        Assert.All(fouls, f => Assert.Contains(Foul.NoContact, f.Ruling.Fouls));
        Assert.Equal([pusher, other, pusher, other, pusher], fouls.Select(f => f.Before.Shooter));
        Assert.Contains("Warning", fouls[2].Ruling.Message, StringComparison.Ordinal);
        Assert.Contains("Warning", fouls[3].Ruling.Message, StringComparison.Ordinal);
        var last = fouls[^1].Ruling;
        Assert.Contains(Foul.ThreeFouls, last.Fouls);
        Assert.True(last.GameOver);
        Assert.Equal(other, last.Winner);
        AssertReplays(game);
    }

    [Fact]
    public void APlacementWithoutBallInHandIsRefused()
    {
        var game = new Match(GameSetup.Of(GameRules.NineBall, 1, Players));
        game.Play(Aimer.Break(game, null));
        if (game.State.BallInHand == BallInHand.None)
        {
            var shot = Aimer.Roll(game) with { Place = new Billiards.Core.Mathematics.Vec3(-1, 0, 0) };
            Assert.Throws<InvalidOperationException>(() => game.Play(shot));
        }
        else
        {
            Assert.Contains(game.Shots[0].Ruling.Fouls, f => f is Foul.CueBallPocketed or Foul.BadBreak);
        }
    }

    [Fact]
    public void ARulingWithOptionsWaitsForTheIncomingPlayerAndTheRecordKeepsTheChoice()
    {
        var game = new Match(GameSetup.Of(GameRules.NineBall, 5, Players));
        game.Play(Aimer.Break(game, null));
        int pusher = game.State.Shooter;

        // Struck, run and judged step by step, as the window does: no option chosen yet.
        var sim = game.Strike(Aimer.Roll(game, pushOut: true));
        Assert.True(game.IsShotRunning);
        Match.RunToRest(sim);
        var push = game.Judge(sim);
        Assert.Equal([RefereeOption.Shoot, RefereeOption.PassBack], game.PendingOptions);
        Assert.Null(push.Input.Choice);
        Assert.Equal(1 - pusher, game.State.Shooter);
        Assert.Throws<InvalidOperationException>(() => game.Strike(Aimer.Roll(game)));
        Assert.Throws<ArgumentException>(() => game.Choose(RefereeOption.Rerack));

        game.Choose(RefereeOption.PassBack);
        Assert.Empty(game.PendingOptions);
        Assert.Equal(pusher, game.State.Shooter);
        Assert.Equal(RefereeOption.PassBack, game.Shots[^1].Input.Choice);
        AssertReplays(game);
    }

    [Fact]
    public void AnEightBallGameWithThreeFoulsInARowReplays()
    {
        // 8-ball has no three-foul rule: the count goes on, and its record still reads.
        var game = new Match(GameSetup.Of(GameRules.EightBall, 3, Players));
        game.Play(Aimer.Break(game, null));
        for (int k = 0; k < 6 && !game.IsOver; k++)
        {
            game.Play(Aimer.Roll(game) with { Call = Call.Safety });
        }
        Assert.False(game.IsOver);
        Assert.True(Math.Max(game.State.FoulsInRow[0], game.State.FoulsInRow[1]) >= 3);
        AssertReplays(game);
    }

    [Fact]
    public void AMatchFromASetPositionStartsThereAndItsRecordReplaysFromIt()
    {
        var start = GameSetup.Of(GameRules.NineBall, 3, Players);
        double r = start.BallRadius;
        var setup = start with
        {
            Position = [(PoolBalls.Cue, new Vec3(-0.5, 0, r)), (new BallId(1), new Vec3(0.2, 0.1, r)), (new BallId(9), new Vec3(0.6, -0.2, r))],
        };
        var game = new Match(setup);
        Assert.Equal(3, game.Balls.Count);
        Assert.Equal(new Vec3(0.2, 0.1, r), game.Balls[new BallId(1)]);
        game.Play(Aimer.Next(game, b => IsTarget(game, b), callShots: false));
        game.Play(Aimer.Roll(game));
        AssertReplays(game);
        Assert.Contains("\"balls\"", Encoding.UTF8.GetString(GameRecordFile.ToUtf8(game)), StringComparison.Ordinal);
    }

    [Fact]
    public void AReplayNamesTheFirstShotWhoseAimWasChangedByTwoDegrees()
    {
        var game = PlayOut(GameSetup.Of(GameRules.NineBall, 4, Players));
        var record = GameRecordFile.Parse(Encoding.UTF8.GetString(GameRecordFile.ToUtf8(game)), "game.json");
        Assert.True(record.Shots.Count > 4);
        const int changed = 3;
        var shots = record.Shots.ToList();
        shots[changed] = shots[changed] with { Shot = shots[changed].Shot with { AimDeg = shots[changed].Shot.AimDeg + 2 } };
        var report = GameRecordFile.Verify(record with { Shots = shots }, out _);
        Assert.Equal(record.Shots.Count, report.Shots);
        Assert.Equal(changed, report.Same);
        Assert.Equal(changed, report.FirstDifference!.Shot);
        Assert.NotEqual(report.FirstDifference.Recorded, report.FirstDifference.Replayed);
        Assert.Null(GameRecordFile.Verify(record, out _).FirstDifference);
    }

    [Fact]
    public void AShotTheReplayCannotPlayIsTheFirstDifference()
    {
        var game = PlayOut(GameSetup.Of(GameRules.NineBall, 4, Players));
        Assert.True(game.IsOver);
        var record = GameRecordFile.Parse(Encoding.UTF8.GetString(GameRecordFile.ToUtf8(game)), "game.json");
        // One shot more than the game had: the replayed game is over by then.
        var longer = record with
        {
            Shots = [.. record.Shots, record.Shots[^1]],
            Rulings = [.. record.Rulings, record.Rulings[^1]],
            Balls = [.. record.Balls, record.Balls[^1]],
        };
        var report = GameRecordFile.Verify(longer, out _);
        Assert.Equal(record.Shots.Count, report.Same);
        Assert.Equal(record.Shots.Count, report.FirstDifference!.Shot);
        Assert.Equal("shot", report.FirstDifference.Field);
    }

    [Fact]
    public void AReplayComparesTheBallsAtRestNotOnlyTheRuling()
    {
        var game = PlayOut(GameSetup.Of(GameRules.EightBall, 3, Players));
        var root = System.Text.Json.Nodes.JsonNode.Parse(GameRecordFile.ToUtf8(game))!;
        var invariant = System.Globalization.CultureInfo.InvariantCulture;
        string Balls(double bump) => "[" + string.Join(", ", game.Shots[1].After.Select((b, i) =>
            string.Create(invariant, $$"""{ "id": "{{b.Id}}", "position": [{{(b.Position.X + (i == 0 ? bump : 0)).ToString("R", invariant)}}, {{b.Position.Y.ToString("R", invariant)}}] }"""))) + "]";
        root["shots"]![1]!["balls"] = System.Text.Json.Nodes.JsonNode.Parse(Balls(0));
        Assert.Null(GameRecordFile.Verify(GameRecordFile.Parse(root.ToJsonString(), "game.json"), out _).FirstDifference);
        // Shot 1's balls at rest, moved by a tenth of a millimetre: the ruling alone would not tell.
        root["shots"]![1]!["balls"] = System.Text.Json.Nodes.JsonNode.Parse(Balls(1e-4));
        var report = GameRecordFile.Verify(GameRecordFile.Parse(root.ToJsonString(), "game.json"), out _);
        Assert.Equal(1, report.FirstDifference!.Shot);
        Assert.Equal("balls", report.FirstDifference.Field);
    }

    [Fact]
    public void ARecordHoldsOnlyTheContractsFieldsAndTheOptionTakenIsTheOneThatLeadsToTheNextShot()
    {
        // A bad break (seed 375811699, found with selfplay): the incoming player may accept or rerack.
        var game = new Match(GameSetup.Of(GameRules.EightBall, 375811699, Players));
        var breakShot = new GameShot(new Billiards.Core.Cue.ShotSpec(6.47982420001081, -0.0843483203892596, -0.06654588027415695, -0.25294621533079914, 3.2887587689229236), Place: new Vec3(-0.69215, 0, 0));
        var sim = game.Strike(breakShot);
        Match.RunToRest(sim);
        var ruling = game.Judge(sim).Ruling;
        Assert.Equal([RefereeOption.Accept, RefereeOption.Rerack], ruling.Options);
        // Not the first option: a replay that took the first would break again from the wrong state.
        game.Choose(RefereeOption.Rerack);
        Assert.Equal(0, game.State.Shot);
        game.Play(breakShot with { Place = new Vec3(-0.7, 0.1, 0) });

        string json = Encoding.UTF8.GetString(GameRecordFile.ToUtf8(game));
        using (var doc = System.Text.Json.JsonDocument.Parse(json))
        {
            Assert.Equal(["format", "table", "physics", "rack", "shots"], doc.RootElement.EnumerateObject().Select(p => p.Name));
            foreach (var shot in doc.RootElement.GetProperty("shots").EnumerateArray())
            {
                // The contract's fields, the option taken where one was offered, and the balls at rest that replay --verify compares.
                Assert.Equal(shot.GetProperty("ruling").GetProperty("options").GetArrayLength() > 0
                    ? ["game", "place", "call", "shot", "choice", "ruling", "balls"]
                    : ["game", "place", "call", "shot", "ruling", "balls"], shot.EnumerateObject().Select(p => p.Name));
            }
        }
        var record = GameRecordFile.Parse(json, "rerack.json");
        Assert.Equal(RefereeOption.Rerack, record.ChoiceAfter(0, ruling));
        // Without the named choice, the next shot's block tells it.
        Assert.Equal(RefereeOption.Rerack, (record with { Shots = [.. record.Shots.Select(x => x with { Choice = null })] }).ChoiceAfter(0, ruling));
        var report = GameRecordFile.Verify(record, out var replayed);
        Assert.Null(report.FirstDifference);
        Assert.Equal(2, report.Same);
        Assert.Equal(RefereeOption.Rerack, replayed.Shots[0].Input.Choice);
    }

    [Fact]
    public void SeveralGamesAreOneRecordALineEachReplayingOnItsOwn()
    {
        var first = PlayOut(GameSetup.Of(GameRules.NineBall, 1, Players), maxShots: 6);
        var second = PlayOut(GameSetup.Of(GameRules.NineBall, 2, Players), maxShots: 4);
        string[] lines = Encoding.UTF8.GetString(GameRecordFile.ToJsonLines([first, second])).Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(2, lines.Length);
        Assert.Equal(first.Shots.Count, GameRecordFile.Parse(lines[0], "session.jsonl").Shots.Count);
        var record = GameRecordFile.Parse(lines[1], "session.jsonl");
        Assert.Equal(2, record.Setup.Seed);
        Assert.Null(GameRecordFile.Verify(record, out _).FirstDifference);
    }
}

/// <summary>A game record that cannot be read says where and why.</summary>
public class GameRecordFileTests
{
    [Fact]
    public void AnotherFormatIsRefused()
    {
        var e = Assert.Throws<SceneException>(() => GameRecordFile.Parse("""{ "format": "billiards-scene/1" }""", "g.json"));
        Assert.Equal("$.format", e.JsonPath);
    }

    [Fact]
    public void ARackOfAnotherGameIsRefused()
    {
        var e = Assert.Throws<SceneException>(() => GameRecordFile.Parse("""
            { "format": "billiards-game/1", "table": { "preset": "pool-9ft" }, "physics": { "model": "standard" },
              "rack": { "game": "eight-ball", "seed": 1 }, "game": { "rules": "nine-ball" }, "shots": [] }
            """, "g.json"));
        Assert.Equal("$.rack.game", e.JsonPath);
    }

    [Fact]
    public void ABadGameBlockInAShotNamesTheShot()
    {
        var e = Assert.Throws<SceneException>(() => GameRecordFile.Parse("""
            { "format": "billiards-game/1", "table": { "preset": "pool-9ft" }, "physics": { "model": "standard" },
              "rack": { "game": "nine-ball", "seed": 1 }, "game": { "rules": "nine-ball" },
              "shots": [ { "game": { "rules": "nine-ball", "shooter": 4 }, "shot": { "speed": 1, "aim_deg": 0 }, "ruling": {} } ] }
            """, "g.json"));
        Assert.Equal("$.shots[0].game.shooter", e.JsonPath);
    }

}
