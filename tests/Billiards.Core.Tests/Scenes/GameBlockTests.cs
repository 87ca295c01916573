using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Scenes;

/// <summary>The scene's "game" block and the result's "ruling" (scene-format.md).</summary>
public class GameBlockTests
{
    private const string Head = "\"format\": \"billiards-scene/1\", \"balls\": [ { \"id\": \"cue\", \"position\": [-0.8, 0] }, { \"id\": \"1\", \"position\": [0.5, 0] } ], \"shot\": { \"speed\": 2, \"aim_deg\": 0 }";

    private static Scene Parse(string game) => SceneLoader.Parse($$"""{ {{Head}}, "game": {{game}} }""", "g.json");

    private static SceneException Refused(string game) => Assert.Throws<SceneException>(() => Parse(game));

    [Fact]
    public void TheContractsExampleBlockReads()
    {
        var state = Parse("""
            { "rules": "eight-ball", "players": ["Anna", "Ben"], "shooter": 0, "shot": 3,
              "groups": ["solids", "stripes"], "call": { "ball": "8", "pocket": "foot-left" },
              "push_out": false, "fouls_in_row": [0, 1], "score": [0, 0], "target": 100 }
            """).Game!;
        var expected = new GameState(GameRules.EightBall)
        {
            Players = new("Anna", "Ben"),
            Shot = 3,
            Call = new Call(new BallId(8), PoolPockets.FootLeft),
            FoulsInRow = new(0, 1),
            Part = new EightBallPart { Groups = new(BallGroup.Solids, BallGroup.Stripes) },
        };
        Assert.Equal(expected, state);
    }

    [Fact]
    public void EveryFieldButRulesDefaultsToTheStartOfAGame()
    {
        var state = Parse("""{ "rules": "straight-pool" }""").Game!;
        Assert.Equal(new GameState(GameRules.StraightPool), state);
        Assert.Equal(("Player 1", "Player 2"), (state.Players.First, state.Players.Second));
        Assert.Equal((0, 0, 100), (state.Shooter, state.Shot, state.Target));
    }

    [Fact]
    public void EightBallCountsFoulsInARowPastTwoForItHasNoThreeFoulRule() =>
        Assert.Equal(new PerPlayer<int>(4, 0), Parse("""{ "rules": "eight-ball", "shot": 9, "fouls_in_row": [4, 0] }""").Game!.FoulsInRow);

    [Fact]
    public void ASafetyCallReads() =>
        Assert.Equal(Call.Safety, Parse("""{ "rules": "ten-ball", "shot": 2, "call": { "safety": true } }""").Game!.Call);

    [Theory]
    [InlineData("""{ "players": ["A", "B"] }""", "$.game", "missing \"rules\"")]
    [InlineData("""{ "rules": "carom" }""", "$.game.rules", "unknown rules \"carom\"")]
    [InlineData("""{ "rules": "nine-ball", "shooter": 2 }""", "$.game.shooter", "player index 2 is out of range")]
    [InlineData("""{ "rules": "nine-ball", "shooter": -1 }""", "$.game.shooter", "player index -1 is out of range")]
    [InlineData("""{ "rules": "nine-ball", "groups": ["solids", "stripes"] }""", "$.game.groups", "nine-ball has no groups")]
    [InlineData("""{ "rules": "eight-ball", "groups": ["solids", "solids"] }""", "$.game.groups", "expected null")]
    [InlineData("""{ "rules": "eight-ball", "shot": 2, "call": { "ball": "8", "pocket": "corner" } }""", "$.game.call.pocket", "unknown pocket \"corner\"")]
    [InlineData("""{ "rules": "nine-ball", "shot": 2, "call": { "ball": "12", "pocket": "foot-left" } }""", "$.game.call.ball", "\"12\" is not an object ball of nine-ball")]
    [InlineData("""{ "rules": "eight-ball", "call": { "ball": "cue", "pocket": "foot-left" } }""", "$.game.call.ball", "\"cue\" is not an object ball")]
    [InlineData("""{ "rules": "eight-ball", "call": { "ball": "3" } }""", "$.game.call", "a call needs both")]
    [InlineData("""{ "rules": "eight-ball", "push_out": true, "shot": 1 }""", "$.game.push_out", "eight-ball has no push-out")]
    [InlineData("""{ "rules": "nine-ball", "push_out": true, "shot": 4 }""", "$.game.push_out", "only allowed on the shot after the break")]
    [InlineData("""{ "rules": "nine-ball", "fouls_in_row": [3, 0] }""", "$.game.fouls_in_row", "each count must be 0, 1 or 2")]
    [InlineData("""{ "rules": "eight-ball", "fouls_in_row": [0, -1] }""", "$.game.fouls_in_row", "each count must be 0 or more")]
    [InlineData("""{ "rules": "nine-ball", "fouls_in_row": [1] }""", "$.game.fouls_in_row", "one whole number per player")]
    [InlineData("""{ "rules": "nine-ball", "players": ["Anna"] }""", "$.game.players", "the names of the two players")]
    [InlineData("""{ "rules": "nine-ball", "shot": -1 }""", "$.game.shot", "negative")]
    [InlineData("""{ "rules": "straight-pool", "target": 0 }""", "$.game.target", "at least 1")]
    [InlineData("""{ "rules": "nine-ball", "ball_in_hand": "anywhere" }""", "$.game.ball_in_hand", "unknown value \"anywhere\"")]
    [InlineData("""{ "rules": "nine-ball", "refree": 1 }""", "$.game.refree", "unknown field")]
    [InlineData("""[ "nine-ball" ]""", "$.game", "expected an object")]
    public void ABadGameBlockNamesItsPathAndProblem(string game, string path, string problem)
    {
        var e = Refused(game);
        Assert.Equal(path, e.JsonPath);
        Assert.Contains(problem, e.Problem, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void AGameBlockWithoutAShotIsAPositionThatARunRefuses()
    {
        var position = SceneLoader.Parse(
            """{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ], "game": { "rules": "nine-ball", "shot": 4 } }""", "g.json");
        Assert.Null(position.Shot);
        Assert.Equal((GameRules.NineBall, 4), (position.Game!.Rules, position.Game.Shot));
        var e = Assert.Throws<SceneException>(() => SimulationRunner.Run(position, new RunOptions()));
        Assert.Equal(("g.json", "$.game"), (e.File, e.JsonPath));
    }

    public static TheoryData<string> RuleScenes => new(Directory.GetFiles(AssetFolder.Scene("rules"), "*.json").Select(Path.GetFileName)!);

    [Theory]
    [MemberData(nameof(RuleScenes))]
    public void ARulesSceneGivesARulingWithEveryFieldOfTheContractAndItsNextIsAValidGameBlock(string file)
    {
        var scene = SceneLoader.Load(Path.Combine(AssetFolder.Scene("rules"), file));
        Assert.NotNull(scene.Game);
        using var json = JsonDocument.Parse(ResultWriter.ToUtf8(SimulationRunner.Run(scene, new RunOptions())));
        var ruling = json.RootElement.GetProperty("ruling");
        string[] fields = ["legal", "fouls", "pocketed", "continue", "ball_in_hand", "spot", "options", "game_over", "winner", "message", "next"];
        Assert.Equal(fields, ruling.EnumerateObject().Select(p => p.Name));
        Assert.Equal(JsonValueKind.Array, ruling.GetProperty("fouls").ValueKind);
        Assert.Equal(ruling.GetProperty("legal").GetBoolean(), ruling.GetProperty("fouls").GetArrayLength() == 0);
        Assert.False(string.IsNullOrWhiteSpace(ruling.GetProperty("message").GetString()));

        // "next" is a game block the loader accepts, for the same game: one shot on, or a new rack's break.
        var next = GameBlockReader.Read(ruling.GetProperty("next"), PoolPockets.Set, file, "$.ruling.next");
        Assert.Equal(scene.Game!.Rules, next.Rules);
        Assert.Equal(ruling.GetProperty("game_over").GetBoolean() ? 0 : scene.Game.Shot + 1, next.Shot);
    }

    [Fact]
    public void WritingAStateAndReadingItBackGivesTheSameState()
    {
        GameState[] states =
        [
            new GameState(GameRules.EightBall) { Players = new("A", "B"), Shooter = 1, Shot = 7, Call = new Call(new BallId(12), PoolPockets.SideRight), FoulsInRow = new(2, 1), BallInHand = BallInHand.Table, Part = new EightBallPart { Groups = new(BallGroup.Stripes, BallGroup.Solids) } },
            new GameState(GameRules.NineBall) { Shot = 1, PushOut = true },
            new GameState(GameRules.TenBall) { Shot = 4, Call = Call.Safety, BallInHand = BallInHand.Table },
            new GameState(GameRules.StraightPool) { Shot = 40, Score = new(-3, 57), Target = 75, BallInHand = BallInHand.Kitchen },
        ];
        foreach (var state in states)
        {
            using var stream = new MemoryStream();
            using (var w = new Utf8JsonWriter(stream))
            {
                GameBlockWriter.WriteGame(w, state);
            }
            using var doc = JsonDocument.Parse(stream.ToArray());
            Assert.Equal(state, GameBlockReader.Read(doc.RootElement, PoolPockets.Set, "x.json"));
        }
    }
}
