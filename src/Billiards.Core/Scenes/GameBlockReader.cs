using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Scenes;

/// <summary>
/// Reads a scene's optional "game" block (scene-format.md): the state of a game before the
/// scene's shot. Every problem becomes a <see cref="SceneException"/> naming the JSON path, and
/// unknown fields are refused, as everywhere in a scene.
/// </summary>
/// <remarks>
/// Besides the contract's fields the block may carry "ball_in_hand" ("table", "kitchen" or "d"): the
/// previous ruling's ball in hand, which the referee needs to judge the placement. Rulings write
/// it into their "next" block, so that "next" is all the next shot needs.
/// This reader knows only the fields every game shares (<see cref="CommonFields"/>); a game's own
/// fields (8-ball's groups, snooker's ball on, three-cushion's innings) and the words of its call
/// are read by its ruleset (<see cref="IGameStateRules"/>). Another game's field is refused unless
/// it says "none" (null, false or zeros), as an 8-ball block may say "push_out": false.
/// </remarks>
public static class GameBlockReader
{
    /// <summary>The fields of every game's block.</summary>
    public static IReadOnlyList<string> CommonFields { get; } =
        ["rules", "players", "shooter", "shot", "call", "push_out", "fouls_in_row", "score", "target", "ball_in_hand"];

    /// <summary>The fields a game block may have: <see cref="CommonFields"/> and every registered game's own (<see cref="IGameStateRules.PartFields"/>).</summary>
    public static IReadOnlyList<string> Fields => [.. CommonFields, .. Ruleset.All.SelectMany(r => r.PartFields).Distinct()];

    /// <summary>Reads a game block.</summary>
    /// <param name="element">The block.</param>
    /// <param name="pockets">The table's pockets, which a call names.</param>
    /// <param name="file">The file, for errors.</param>
    /// <param name="path">The block's JSON path, for errors (normally <c>$.game</c>).</param>
    /// <exception cref="SceneException">When the block is invalid.</exception>
    public static GameState Read(JsonElement element, PocketSet pockets, string file, string path = "$.game")
    {
        ArgumentNullException.ThrowIfNull(pockets);
        SceneException Error(string at, string problem) => new(file, at, problem);
        if (element.ValueKind != JsonValueKind.Object)
        {
            throw Error(path, $"expected an object, found {element.ValueKind.ToString().ToLowerInvariant()}");
        }
        var f = new Dictionary<string, JsonElement>(StringComparer.Ordinal);
        var fields = Fields;
        foreach (var p in element.EnumerateObject())
        {
            if (!fields.Contains(p.Name))
            {
                throw Error($"{path}.{p.Name}", $"unknown field (expected one of {Quote(fields)})");
            }
            if (!f.TryAdd(p.Name, p.Value))
            {
                throw Error($"{path}.{p.Name}", "field appears twice");
            }
        }
        if (!f.TryGetValue("rules", out var rulesElement))
        {
            throw Error(path, "missing \"rules\"");
        }
        string rulesName = Text(rulesElement, $"{path}.rules");
        if (!RuleNames.TryParseGame(rulesName, out var rules))
        {
            throw Error($"{path}.rules", $"unknown rules \"{rulesName}\" (expected one of {Quote(RuleNames.GameNames)})");
        }
        var state = new GameState(rules);
        var ruleset = Ruleset.For(rules);

        if (f.TryGetValue("players", out var players))
        {
            if (players.ValueKind != JsonValueKind.Array || players.GetArrayLength() != 2
                || players.EnumerateArray().Any(x => x.ValueKind != JsonValueKind.String || string.IsNullOrWhiteSpace(x.GetString())))
            {
                throw Error($"{path}.players", "expected the names of the two players, e.g. [\"Anna\", \"Ben\"]");
            }
            state = state with { Players = new(players[0].GetString()!, players[1].GetString()!) };
        }
        if (f.TryGetValue("shooter", out var shooter))
        {
            int index = Whole(shooter, $"{path}.shooter");
            if (index is < 0 or > 1)
            {
                throw Error($"{path}.shooter", $"player index {index} is out of range (the game has players 0 and 1)");
            }
            state = state with { Shooter = index };
        }
        if (f.TryGetValue("shot", out var shot))
        {
            int n = Whole(shot, $"{path}.shot");
            if (n < 0)
            {
                throw Error($"{path}.shot", $"shot number {n} is negative (0 is the break)");
            }
            state = state with { Shot = n };
        }
        if (f.TryGetValue("push_out", out var push))
        {
            if (push.ValueKind is not (JsonValueKind.True or JsonValueKind.False))
            {
                throw Error($"{path}.push_out", "expected true or false");
            }
            bool pushOut = push.GetBoolean();
            if (pushOut && !ruleset.HasPushOut)
            {
                throw Error($"{path}.push_out", $"{rules.ToName()} has no push-out (only nine-ball and ten-ball have)");
            }
            if (pushOut && state.Shot != 1)
            {
                throw Error($"{path}.push_out", $"a push-out is only allowed on the shot after the break (shot 1), not on shot {state.Shot}");
            }
            state = state with { PushOut = pushOut };
        }
        if (f.TryGetValue("fouls_in_row", out var fouls))
        {
            var pair = Pair(fouls, $"{path}.fouls_in_row");
            if (pair.First < 0 || pair.Second < 0)
            {
                throw Error($"{path}.fouls_in_row", "each count must be 0 or more");
            }
            if (ruleset.HasThreeFouls && (pair.First > 2 || pair.Second > 2))
            {
                throw Error($"{path}.fouls_in_row", "each count must be 0, 1 or 2 (a third foul ends the count)");
            }
            state = state with { FoulsInRow = pair };
        }
        if (f.TryGetValue("score", out var score))
        {
            state = state with { Score = Pair(score, $"{path}.score") };
        }
        if (f.TryGetValue("target", out var target))
        {
            int t = Whole(target, $"{path}.target");
            if (t < 1)
            {
                throw Error($"{path}.target", $"target score {t} must be at least 1");
            }
            state = state with { Target = t };
        }
        if (f.TryGetValue("ball_in_hand", out var hand) && hand.ValueKind != JsonValueKind.Null)
        {
            string name = Text(hand, $"{path}.ball_in_hand");
            if (!RuleNames.TryParseBallInHand(name, out var bih))
            {
                throw Error($"{path}.ball_in_hand", $"unknown value \"{name}\" (expected \"table\", \"kitchen\", \"d\" or null)");
            }
            state = state with { BallInHand = bih };
        }
        var block = new GameBlockFields(f, state, pockets, file, path);
        foreach (string name in f.Keys.Where(n => !CommonFields.Contains(n) && !ruleset.PartFields.Contains(n)))
        {
            if (!SaysNone(f[name]))
            {
                string owner = Ruleset.All.First(r => r.PartFields.Contains(name)).Name;
                throw Error($"{path}.{name}", $"{rules.ToName()} has no {name.Replace('_', ' ')} (only {owner} has; leave \"{name}\" out)");
            }
        }
        state = state with { Part = ruleset.ReadPart(block) };
        if (f.TryGetValue("call", out var call) && call.ValueKind != JsonValueKind.Null)
        {
            state = state with { Call = ReadCall(call, ruleset, block, $"{path}.call", Error) };
        }
        return state;

        string Text(JsonElement e, string at) =>
            e.ValueKind == JsonValueKind.String ? e.GetString()! : throw Error(at, $"expected a string, found {e.GetRawText()}");

        int Whole(JsonElement e, string at) =>
            e.ValueKind == JsonValueKind.Number && e.TryGetInt32(out int v) ? v : throw Error(at, $"expected a whole number, found {e.GetRawText()}");

        PerPlayer<int> Pair(JsonElement e, string at) =>
            e.ValueKind == JsonValueKind.Array && e.GetArrayLength() == 2
                ? new(Whole(e[0], $"{at}[0]"), Whole(e[1], $"{at}[1]"))
                : throw Error(at, $"expected one whole number per player, e.g. [0, 0], found {e.GetRawText()}");
    }

    private static Call ReadCall(JsonElement e, Ruleset ruleset, GameBlockFields block, string path, Func<string, string, SceneException> error)
    {
        if (e.ValueKind != JsonValueKind.Object)
        {
            throw error(path, "expected {\"ball\": \"3\", \"pocket\": \"foot-left\"} or {\"safety\": true}");
        }
        var names = e.EnumerateObject().Select(p => p.Name).ToList();
        if (names.SequenceEqual(["safety"]))
        {
            return e.GetProperty("safety").ValueKind == JsonValueKind.True ? Call.Safety : throw error($"{path}.safety", "expected true");
        }
        foreach (string name in names.Where(n => n is not ("ball" or "pocket")))
        {
            throw error($"{path}.{name}", "unknown field (expected \"ball\" and \"pocket\", or \"safety\" alone)");
        }
        return ruleset.ReadCall(e, block);
    }

    /// <summary>
    /// Pool's call of a ball and a pocket, <c>{"ball": "3", "pocket": "foot-left"}</c>, of one of
    /// <paramref name="ruleset"/>'s object balls (the default of <see cref="IGameStateRules.ReadCall"/>).
    /// </summary>
    /// <exception cref="SceneException">When the call names no such ball or pocket.</exception>
    public static Call ReadPocketCall(JsonElement e, Ruleset ruleset, GameBlockFields block)
    {
        ArgumentNullException.ThrowIfNull(ruleset);
        ArgumentNullException.ThrowIfNull(block);
        if (!e.TryGetProperty("ball", out var ball) || !e.TryGetProperty("pocket", out var pocket))
        {
            throw block.Error("call", "a call needs both \"ball\" and \"pocket\" (or {\"safety\": true})");
        }
        string? ballName = ball.ValueKind == JsonValueKind.String ? ball.GetString() : ball.GetRawText();
        var set = ruleset.BallSet;
        var objectBalls = ruleset.Balls.Where(b => !set.IsCueBall(b)).ToList();
        if (!set.TryParse(ballName, out var id) || !objectBalls.Contains(id))
        {
            throw block.Error("call.ball", $"\"{ballName}\" is not an object ball of {ruleset.Name} (expected \"{set.NameOf(objectBalls[0])}\" .. \"{set.NameOf(objectBalls[^1])}\")");
        }
        string? pocketName = pocket.ValueKind == JsonValueKind.String ? pocket.GetString() : pocket.GetRawText();
        var pockets = block.Pockets;
        if (!pockets.TryParse(pocketName, out var pocketId))
        {
            throw block.Error("call.pocket", pockets.Count == 0
                ? $"unknown pocket \"{pocketName}\" (this table has no pockets)"
                : $"unknown pocket \"{pocketName}\" (expected one of {pockets.Describe()})");
        }
        return new Call(id, pocketId);
    }

    // Another game's field that says "none": null, false or all zeros.
    private static bool SaysNone(JsonElement e) => e.ValueKind switch
    {
        JsonValueKind.Null or JsonValueKind.False => true,
        JsonValueKind.Array => e.EnumerateArray().All(x => x.ValueKind == JsonValueKind.Number && x.TryGetInt32(out int v) && v == 0),
        _ => false,
    };

    private static string Quote(IEnumerable<string> values) => string.Join(", ", values.Select(v => $"\"{v}\""));
}
