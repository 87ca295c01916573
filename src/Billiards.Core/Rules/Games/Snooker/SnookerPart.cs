using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Scenes;

namespace Billiards.Core.Rules;

/// <summary>
/// Snooker's own part of the game state (scene-format.md): the ball on ("ball_on"), a free ball
/// ("free_ball") and each player's fouls-and-misses in a row ("misses_in_row").
/// </summary>
public sealed record SnookerPart : GameStatePart
{
    /// <summary>The game-block fields of the part.</summary>
    public static IReadOnlyList<string> Fields { get; } = ["ball_on", "free_ball", "misses_in_row"];

    /// <summary>
    /// The ball on, as files write it: "red", "colour" (after a potted red: the colour nominated in
    /// the call) or a colour's name once the reds are gone; null for the start of a frame ("red").
    /// </summary>
    public string? BallOn { get; init; }

    /// <summary>The shooter was awarded a free ball (and may nominate any ball in the call as the ball on).</summary>
    public bool FreeBall { get; init; }

    /// <summary>Consecutive fouls and misses of each player.</summary>
    public PerPlayer<int> MissesInRow { get; init; }

    /// <summary>No free ball: it was the next shot's.</summary>
    public override GameStatePart AtEnd => this with { FreeBall = false };

    /// <summary>The snooker part of <paramref name="state"/> (the start of a frame where it has none).</summary>
    public static SnookerPart Of(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return state.PartOf<SnookerPart>();
    }

    /// <summary>Reads "ball_on", "free_ball" and "misses_in_row".</summary>
    /// <exception cref="SceneException">When one is invalid.</exception>
    public static SnookerPart Read(GameBlockFields block)
    {
        ArgumentNullException.ThrowIfNull(block);
        var part = new SnookerPart();
        if (block.TryGet("ball_on", out var ballOn) && ballOn.ValueKind != JsonValueKind.Null)
        {
            string name = block.Text("ball_on", ballOn);
            if (name is not (SnookerRuleset.Red or SnookerRuleset.Colour) && !BallSet.Colours.Contains(name))
            {
                throw block.Error("ball_on", $"unknown ball on \"{name}\" (expected \"red\", \"colour\" or a colour: {string.Join(", ", BallSet.Colours.Select(c => $"\"{c}\""))})");
            }
            part = part with { BallOn = name };
        }
        if (block.TryGet("free_ball", out var free))
        {
            part = part with { FreeBall = block.Flag("free_ball", free) };
        }
        if (block.TryGet("misses_in_row", out var misses))
        {
            var pair = block.Pair("misses_in_row", misses);
            // Misses without a full ball view go on counting past two (rules.md: only the third with a view loses).
            if (pair.First < 0 || pair.Second < 0)
            {
                throw block.Error("misses_in_row", "each count must be 0 or more");
            }
            part = part with { MissesInRow = pair };
        }
        return part;
    }

    /// <summary>Snooker's call: a ball nominated with no pocket, <c>{"ball": "blue"}</c> (a colour after a red, or a free ball).</summary>
    /// <exception cref="SceneException">When it names a pocket or no object ball of snooker.</exception>
    public static Call ReadNomination(JsonElement call, GameBlockFields block)
    {
        ArgumentNullException.ThrowIfNull(block);
        if (call.TryGetProperty("pocket", out _) || !call.TryGetProperty("ball", out var ball))
        {
            throw block.Error("call", "a snooker call nominates a ball and no pocket: {\"ball\": \"blue\"}");
        }
        string? name = ball.ValueKind == JsonValueKind.String ? ball.GetString() : ball.GetRawText();
        if (!BallSet.Snooker.TryParse(name, out var id) || BallSet.Snooker.IsCueBall(id))
        {
            throw block.Error("call.ball", $"\"{name}\" is not an object ball of snooker (expected \"red-1\" .. \"red-15\" or a colour)");
        }
        return Call.Nominate(id);
    }

    /// <summary>Writes "ball_on", "free_ball" and "misses_in_row" at the end of the block.</summary>
    public void Write(Utf8JsonWriter writer, GameBlockSlot slot)
    {
        ArgumentNullException.ThrowIfNull(writer);
        if (slot != GameBlockSlot.AtEnd)
        {
            return;
        }
        writer.WriteString("ball_on", BallOn ?? SnookerRuleset.Red);
        writer.WriteBoolean("free_ball", FreeBall);
        GameBlockWriter.WritePair(writer, "misses_in_row", MissesInRow);
    }
}
