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
/// </remarks>
public static class GameBlockReader
{
    /// <summary>The fields a game block may have.</summary>
    public static IReadOnlyList<string> Fields { get; } =
        ["rules", "players", "shooter", "shot", "groups", "call", "push_out", "fouls_in_row", "score", "target", "ball_in_hand", "ball_on", "free_ball", "misses_in_row",
         "cue_balls", "innings", "equalizing", "breaker", "run"];

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
        foreach (var p in element.EnumerateObject())
        {
            if (!Fields.Contains(p.Name))
            {
                throw Error($"{path}.{p.Name}", $"unknown field (expected one of {Quote(Fields)})");
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
        if (f.TryGetValue("groups", out var groups) && groups.ValueKind != JsonValueKind.Null)
        {
            if (!Ruleset.For(rules).HasGroups)
            {
                throw Error($"{path}.groups", $"{rules.ToName()} has no groups (only eight-ball has; leave \"groups\" out or null)");
            }
            if (groups.ValueKind != JsonValueKind.Array || groups.GetArrayLength() != 2
                || !RuleNames.TryParseGroup(groups[0].ValueKind == JsonValueKind.String ? groups[0].GetString() : null, out var g0)
                || !RuleNames.TryParseGroup(groups[1].ValueKind == JsonValueKind.String ? groups[1].GetString() : null, out var g1)
                || g0 == g1)
            {
                throw Error($"{path}.groups", "expected null (an open table) or each player's group: [\"solids\", \"stripes\"] or [\"stripes\", \"solids\"]");
            }
            state = state with { Groups = new(g0, g1) };
        }
        if (f.TryGetValue("call", out var call) && call.ValueKind != JsonValueKind.Null)
        {
            state = state with { Call = ReadCall(call, rules, pockets, $"{path}.call", Error) };
        }
        if (f.TryGetValue("push_out", out var push))
        {
            if (push.ValueKind is not (JsonValueKind.True or JsonValueKind.False))
            {
                throw Error($"{path}.push_out", "expected true or false");
            }
            bool pushOut = push.GetBoolean();
            if (pushOut && !Ruleset.For(rules).HasPushOut)
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
            if (Ruleset.For(rules).HasThreeFouls && (pair.First > 2 || pair.Second > 2))
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
        bool snooker = Ruleset.For(rules).HasBallOn;
        if (f.TryGetValue("ball_on", out var ballOn) && ballOn.ValueKind != JsonValueKind.Null)
        {
            string name = Text(ballOn, $"{path}.ball_on");
            if (!snooker || name is not (SnookerRuleset.Red or SnookerRuleset.Colour) && !BallSet.Colours.Contains(name))
            {
                throw Error($"{path}.ball_on", snooker
                    ? $"unknown ball on \"{name}\" (expected \"red\", \"colour\" or a colour: {Quote(BallSet.Colours)})"
                    : $"{rules.ToName()} has no ball on (only snooker has)");
            }
            state = state with { BallOn = name };
        }
        if (f.TryGetValue("free_ball", out var free))
        {
            if (free.ValueKind is not (JsonValueKind.True or JsonValueKind.False))
            {
                throw Error($"{path}.free_ball", "expected true or false");
            }
            if (free.GetBoolean() && !snooker)
            {
                throw Error($"{path}.free_ball", $"{rules.ToName()} has no free ball (only snooker has)");
            }
            state = state with { FreeBall = free.GetBoolean() };
        }
        if (f.TryGetValue("misses_in_row", out var misses))
        {
            var pair = Pair(misses, $"{path}.misses_in_row");
            // Misses without a full ball view go on counting past two (rules.md: only the third with a view loses).
            if (pair.First < 0 || pair.Second < 0)
            {
                throw Error($"{path}.misses_in_row", "each count must be 0 or more");
            }
            state = state with { MissesInRow = pair };
        }
        return ReadCarom(f, state, path, Error);

        string Text(JsonElement e, string at) =>
            e.ValueKind == JsonValueKind.String ? e.GetString()! : throw Error(at, $"expected a string, found {e.GetRawText()}");

        int Whole(JsonElement e, string at) =>
            e.ValueKind == JsonValueKind.Number && e.TryGetInt32(out int v) ? v : throw Error(at, $"expected a whole number, found {e.GetRawText()}");

        PerPlayer<int> Pair(JsonElement e, string at) =>
            e.ValueKind == JsonValueKind.Array && e.GetArrayLength() == 2
                ? new(Whole(e[0], $"{at}[0]"), Whole(e[1], $"{at}[1]"))
                : throw Error(at, $"expected one whole number per player, e.g. [0, 0], found {e.GetRawText()}");
    }

    // Three-cushion's fields (scene-format.md): cue_balls, innings, equalizing, breaker, and run
    // (ours: the shooter's points in the inning so far, which the ruling's run continues).
    private static GameState ReadCarom(Dictionary<string, JsonElement> f, GameState state, string path, Func<string, string, SceneException> error)
    {
        var ruleset = Ruleset.For(state.Rules);
        foreach (string name in new[] { "cue_balls", "innings", "equalizing", "breaker", "run" })
        {
            if (f.ContainsKey(name) && !ruleset.HasInnings)
            {
                throw error($"{path}.{name}", $"{state.Rules.ToName()} has no \"{name}\" (only three-cushion has)");
            }
        }
        if (f.TryGetValue("cue_balls", out var cue))
        {
            var set = ruleset.BallSet;
            string? Name(int i) => cue[i].ValueKind == JsonValueKind.String ? cue[i].GetString() : null;
            if (cue.ValueKind != JsonValueKind.Array || cue.GetArrayLength() != 2
                || !set.TryParse(Name(0), out var a) || !set.TryParse(Name(1), out var b) || a == b || !set.IsCueBall(a) || !set.IsCueBall(b))
            {
                throw error($"{path}.cue_balls", "expected each player's cue ball: [\"white\", \"yellow\"] or [\"yellow\", \"white\"]");
            }
            state = state with { CueBalls = new(a, b) };
        }
        if (f.TryGetValue("innings", out var innings))
        {
            if (innings.ValueKind != JsonValueKind.Array || innings.GetArrayLength() != 2
                || innings.EnumerateArray().Any(x => x.ValueKind != JsonValueKind.Number || !x.TryGetInt32(out int v) || v < 0))
            {
                throw error($"{path}.innings", $"expected each player's innings, two whole numbers of 0 or more, found {innings.GetRawText()}");
            }
            state = state with { Innings = new(innings[0].GetInt32(), innings[1].GetInt32()) };
        }
        if (f.TryGetValue("equalizing", out var eq))
        {
            state = eq.ValueKind is JsonValueKind.True or JsonValueKind.False
                ? state with { Equalizing = eq.GetBoolean() }
                : throw error($"{path}.equalizing", "expected true or false");
        }
        if (f.TryGetValue("breaker", out var breaker))
        {
            state = breaker.ValueKind == JsonValueKind.Number && breaker.TryGetInt32(out int b) && b is 0 or 1
                ? state with { Breaker = b }
                : throw error($"{path}.breaker", $"expected the breaker's index, 0 or 1, found {breaker.GetRawText()}");
        }
        if (f.TryGetValue("run", out var run))
        {
            state = run.ValueKind == JsonValueKind.Number && run.TryGetInt32(out int r) && r >= 0
                ? state with { Run = r }
                : throw error($"{path}.run", $"expected the shooter's points in this inning, a whole number of 0 or more, found {run.GetRawText()}");
        }
        return state;
    }

    private static Call ReadCall(JsonElement e, GameRules rules, PocketSet pockets, string path, Func<string, string, SceneException> error)
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
        if (Ruleset.For(rules).HasBallOn)
        {
            return Nomination(e, path, error);
        }
        if (!e.TryGetProperty("ball", out var ball) || !e.TryGetProperty("pocket", out var pocket))
        {
            throw error(path, "a call needs both \"ball\" and \"pocket\" (or {\"safety\": true})");
        }
        string? ballName = ball.ValueKind == JsonValueKind.String ? ball.GetString() : ball.GetRawText();
        var ruleset = Ruleset.For(rules);
        var set = ruleset.BallSet;
        var objectBalls = ruleset.Balls.Where(b => !set.IsCueBall(b)).ToList();
        if (!set.TryParse(ballName, out var id) || !objectBalls.Contains(id))
        {
            throw error($"{path}.ball", $"\"{ballName}\" is not an object ball of {rules.ToName()} (expected \"{set.NameOf(objectBalls[0])}\" .. \"{set.NameOf(objectBalls[^1])}\")");
        }
        string? pocketName = pocket.ValueKind == JsonValueKind.String ? pocket.GetString() : pocket.GetRawText();
        if (!pockets.TryParse(pocketName, out var pocketId))
        {
            throw error($"{path}.pocket", pockets.Count == 0
                ? $"unknown pocket \"{pocketName}\" (this table has no pockets)"
                : $"unknown pocket \"{pocketName}\" (expected one of {pockets.Describe()})");
        }
        return new Call(id, pocketId);
    }

    // Snooker's call names a ball (a colour after a red, or a free ball) and no pocket.
    private static Call Nomination(JsonElement e, string path, Func<string, string, SceneException> error)
    {
        if (e.TryGetProperty("pocket", out _) || !e.TryGetProperty("ball", out var ball))
        {
            throw error(path, "a snooker call nominates a ball and no pocket: {\"ball\": \"blue\"}");
        }
        string? name = ball.ValueKind == JsonValueKind.String ? ball.GetString() : ball.GetRawText();
        if (!BallSet.Snooker.TryParse(name, out var id) || BallSet.Snooker.IsCueBall(id))
        {
            throw error($"{path}.ball", $"\"{name}\" is not an object ball of snooker (expected \"red-1\" .. \"red-15\" or a colour)");
        }
        return Call.Nominate(id);
    }

    private static string Quote(IEnumerable<string> values) => string.Join(", ", values.Select(v => $"\"{v}\""));
}
