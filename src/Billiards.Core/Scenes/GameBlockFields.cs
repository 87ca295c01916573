using System.Text.Json;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Scenes;

/// <summary>
/// The fields of one game block being read, for a ruleset reading its own part
/// (<see cref="IGameStateRules.ReadPart"/>): each field by name, and readers that turn a wrong
/// value into a <see cref="SceneException"/> naming the field's JSON path.
/// </summary>
public sealed class GameBlockFields
{
    private readonly IReadOnlyDictionary<string, JsonElement> _fields;
    private readonly string _file;
    private readonly string _path;

    internal GameBlockFields(IReadOnlyDictionary<string, JsonElement> fields, GameState common, PocketSet pockets, string file, string path)
    {
        _fields = fields;
        Common = common;
        Pockets = pockets;
        _file = file;
        _path = path;
    }

    /// <summary>The block's common fields as read (players, shooter, shot, scores, ...), with the ruleset's start part.</summary>
    public GameState Common { get; }

    /// <summary>The table's pockets, which a call names.</summary>
    public PocketSet Pockets { get; }

    /// <summary>True, with its value, when the block has the field <paramref name="name"/>.</summary>
    public bool TryGet(string name, out JsonElement value) => _fields.TryGetValue(name, out value);

    /// <summary>The JSON path of field <paramref name="name"/>, e.g. <c>$.game.ball_on</c>.</summary>
    public string PathOf(string name) => $"{_path}.{name}";

    /// <summary>An error at field <paramref name="name"/> (a JSON path below it may follow, e.g. "[0]").</summary>
    public SceneException Error(string name, string problem) => new(_file, PathOf(name), problem);

    /// <summary>Field <paramref name="name"/> as a string.</summary>
    /// <exception cref="SceneException">When it is not one.</exception>
    public string Text(string name, JsonElement value) =>
        value.ValueKind == JsonValueKind.String ? value.GetString()! : throw Error(name, $"expected a string, found {value.GetRawText()}");

    /// <summary>Field <paramref name="name"/> as true or false.</summary>
    /// <exception cref="SceneException">When it is neither.</exception>
    public bool Flag(string name, JsonElement value) =>
        value.ValueKind is JsonValueKind.True or JsonValueKind.False ? value.GetBoolean() : throw Error(name, "expected true or false");

    /// <summary>Field <paramref name="name"/> as one whole number per player, e.g. <c>[0, 0]</c>.</summary>
    /// <exception cref="SceneException">When it is not two whole numbers.</exception>
    public PerPlayer<int> Pair(string name, JsonElement value)
    {
        int Whole(JsonElement e, string at) =>
            e.ValueKind == JsonValueKind.Number && e.TryGetInt32(out int v) ? v : throw new SceneException(_file, at, $"expected a whole number, found {e.GetRawText()}");
        return value.ValueKind == JsonValueKind.Array && value.GetArrayLength() == 2
            ? new(Whole(value[0], $"{PathOf(name)}[0]"), Whole(value[1], $"{PathOf(name)}[1]"))
            : throw Error(name, $"expected one whole number per player, e.g. [0, 0], found {value.GetRawText()}");
    }
}
