using System.Text.Json;
using System.Text.Json.Nodes;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.RulesKit;

namespace Billiards.Core.Tests.Rules;

/// <summary>
/// The planner's search judges with a referee without words (<see cref="Referee.Wordless"/>): every
/// field of its ruling is the worded referee's, only the sentence is left out.
/// </summary>
public class WordlessRefereeTests
{
    private static JsonObject Json(Ruling ruling)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            GameBlockWriter.WriteRuling(w, ruling);
        }
        return JsonNode.Parse(stream.ToArray())!.AsObject();
    }

    public static TheoryData<string, int> Shots() => new()
    {
        { "eight-ball", 0 }, { "eight-ball", 1 }, { "eight-ball", 2 },
        { "nine-ball", 0 }, { "nine-ball", 1 }, { "nine-ball", 2 },
        { "straight-pool", 0 }, { "straight-pool", 1 }, { "straight-pool", 2 },
    };

    [Theory]
    [MemberData(nameof(Shots))]
    public void AWordlessRulingIsTheWordedOneWithoutItsSentence(string game, int kind)
    {
        Assert.True(RuleNames.TryParseGame(game, out var rules));
        var before = At(rules, shot: 3);
        var shot = kind switch
        {
            0 => ShotBuilder.Of(rules).Hit(1).Pocket(1, PoolPockets.FootLeft),
            1 => ShotBuilder.Of(rules).Hit(1).Pocket(0, PoolPockets.SideRight),
            _ => ShotBuilder.Of(rules),
        };
        var worded = Referee.For(rules, ShotBuilder.Table, ShotBuilder.R).Judge(before, shot.Record());
        var wordless = Referee.Wordless(rules, ShotBuilder.Table, ShotBuilder.R).Judge(before, shot.Record());
        Assert.NotEqual("", worded.Message);
        Assert.Equal("", wordless.Message);
        var expected = Json(worded);
        expected["message"] = "";
        Assert.Equal(expected.ToJsonString(), Json(wordless).ToJsonString());
    }
}
