using System.Text.Json;
using Billiards.Core.Scenes;

namespace Billiards.Core.Rules;

/// <summary>8-ball's own part of the game state: each player's group (scene-format.md "groups").</summary>
public sealed record EightBallPart : GameStatePart
{
    /// <summary>The game-block fields of the part.</summary>
    public static IReadOnlyList<string> Fields { get; } = ["groups"];

    /// <summary>Each player's group, or null while the table is open.</summary>
    public PerPlayer<BallGroup>? Groups { get; init; }

    /// <summary>The 8-ball part of <paramref name="state"/> (an open table where it has none).</summary>
    public static EightBallPart Of(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return state.PartOf<EightBallPart>();
    }

    /// <summary>Reads "groups": null (an open table) or each player's group.</summary>
    /// <exception cref="SceneException">When it is neither.</exception>
    public static EightBallPart Read(GameBlockFields block)
    {
        ArgumentNullException.ThrowIfNull(block);
        if (!block.TryGet("groups", out var groups) || groups.ValueKind == JsonValueKind.Null)
        {
            return new EightBallPart();
        }
        if (groups.ValueKind != JsonValueKind.Array || groups.GetArrayLength() != 2
            || !RuleNames.TryParseGroup(groups[0].ValueKind == JsonValueKind.String ? groups[0].GetString() : null, out var g0)
            || !RuleNames.TryParseGroup(groups[1].ValueKind == JsonValueKind.String ? groups[1].GetString() : null, out var g1)
            || g0 == g1)
        {
            throw block.Error("groups", "expected null (an open table) or each player's group: [\"solids\", \"stripes\"] or [\"stripes\", \"solids\"]");
        }
        return new EightBallPart { Groups = new(g0, g1) };
    }

    /// <summary>Writes "groups" after "shot", null while the table is open.</summary>
    public void Write(Utf8JsonWriter writer, GameBlockSlot slot)
    {
        ArgumentNullException.ThrowIfNull(writer);
        if (slot != GameBlockSlot.AfterShot)
        {
            return;
        }
        if (Groups is { } g)
        {
            GameBlockWriter.WriteNames(writer, "groups", [g.First.ToName(), g.Second.ToName()]);
        }
        else
        {
            writer.WriteNull("groups");
        }
    }
}
