using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Scenes;

namespace Billiards.Core.Rules;

/// <summary>
/// Three-cushion's own part of the game state (scene-format.md): each player's cue ball
/// ("cue_balls"), innings ("innings"), the equalizing inning ("equalizing"), the breaker
/// ("breaker") and the run so far (ours: "run", which the ruling's run continues).
/// </summary>
public sealed record ThreeCushionPart : GameStatePart
{
    /// <summary>The game-block fields of the part.</summary>
    public static IReadOnlyList<string> Fields { get; } = ["cue_balls", "innings", "equalizing", "breaker", "run"];

    /// <summary>Each player's cue ball, or null for the default (white for player 0, yellow for player 1).</summary>
    public PerPlayer<BallId>? CueBalls { get; init; }

    /// <summary>Each player's innings, the visits to the table begun (the one at the table counts once it has begun).</summary>
    public PerPlayer<int> Innings { get; init; }

    /// <summary>The player who did not break gets a last inning once the breaker reaches the target (default true).</summary>
    public bool Equalizing { get; init; } = true;

    /// <summary>The player who broke the game, 0 or 1.</summary>
    public int Breaker { get; init; }

    /// <summary>The shooter's points in the inning at the table before this shot.</summary>
    public int Run { get; init; }

    /// <summary>The three-cushion part of <paramref name="state"/> (a game's start where it has none).</summary>
    public static ThreeCushionPart Of(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return state.PartOf<ThreeCushionPart>();
    }

    /// <summary>Reads the part's fields; <paramref name="set"/> names the cue balls.</summary>
    /// <exception cref="SceneException">When one is invalid.</exception>
    public static ThreeCushionPart Read(GameBlockFields block, BallSet set)
    {
        ArgumentNullException.ThrowIfNull(block);
        ArgumentNullException.ThrowIfNull(set);
        var part = new ThreeCushionPart();
        if (block.TryGet("cue_balls", out var cue))
        {
            string? Name(int i) => cue[i].ValueKind == JsonValueKind.String ? cue[i].GetString() : null;
            if (cue.ValueKind != JsonValueKind.Array || cue.GetArrayLength() != 2
                || !set.TryParse(Name(0), out var a) || !set.TryParse(Name(1), out var b) || a == b || !set.IsCueBall(a) || !set.IsCueBall(b))
            {
                throw block.Error("cue_balls", "expected each player's cue ball: [\"white\", \"yellow\"] or [\"yellow\", \"white\"]");
            }
            part = part with { CueBalls = new(a, b) };
        }
        if (block.TryGet("innings", out var innings))
        {
            if (innings.ValueKind != JsonValueKind.Array || innings.GetArrayLength() != 2
                || innings.EnumerateArray().Any(x => x.ValueKind != JsonValueKind.Number || !x.TryGetInt32(out int v) || v < 0))
            {
                throw block.Error("innings", $"expected each player's innings, two whole numbers of 0 or more, found {innings.GetRawText()}");
            }
            part = part with { Innings = new(innings[0].GetInt32(), innings[1].GetInt32()) };
        }
        if (block.TryGet("equalizing", out var eq))
        {
            part = part with { Equalizing = block.Flag("equalizing", eq) };
        }
        if (block.TryGet("breaker", out var breaker))
        {
            part = breaker.ValueKind == JsonValueKind.Number && breaker.TryGetInt32(out int b) && b is 0 or 1
                ? part with { Breaker = b }
                : throw block.Error("breaker", $"expected the breaker's index, 0 or 1, found {breaker.GetRawText()}");
        }
        if (block.TryGet("run", out var run))
        {
            part = run.ValueKind == JsonValueKind.Number && run.TryGetInt32(out int r) && r >= 0
                ? part with { Run = r }
                : throw block.Error("run", $"expected the shooter's points in this inning, a whole number of 0 or more, found {run.GetRawText()}");
        }
        return part;
    }

    /// <summary>Writes the part's fields at the end of the block; <paramref name="set"/> names the cue balls.</summary>
    public void Write(Utf8JsonWriter writer, GameBlockSlot slot, BallSet set)
    {
        ArgumentNullException.ThrowIfNull(writer);
        ArgumentNullException.ThrowIfNull(set);
        if (slot != GameBlockSlot.AtEnd)
        {
            return;
        }
        var cueBalls = CueBalls ?? ThreeCushionRuleset.DefaultCueBalls;
        GameBlockWriter.WriteNames(writer, "cue_balls", [set.NameOf(cueBalls.First), set.NameOf(cueBalls.Second)]);
        GameBlockWriter.WritePair(writer, "innings", Innings);
        writer.WriteBoolean("equalizing", Equalizing);
        writer.WriteNumber("breaker", Breaker);
        writer.WriteNumber("run", Run);
    }
}
