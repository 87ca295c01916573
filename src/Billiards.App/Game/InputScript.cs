using System.Globalization;
using System.Numerics;
using System.Text.Json;
using Billiards.App.Cli;
using Billiards.App.Platform;

namespace Billiards.App.Game;

/// <summary>What a scripted input event does.</summary>
public enum ScriptAction
{
    /// <summary>A key goes down.</summary>
    KeyDown,
    /// <summary>A key goes up.</summary>
    KeyUp,
    /// <summary>The cursor moves to a window position (pixels, y down).</summary>
    MouseMove,
    /// <summary>The cursor moves by an offset (pixels, y down) from where it is.</summary>
    MouseMoveBy,
    /// <summary>A mouse button goes down.</summary>
    MouseDown,
    /// <summary>A mouse button goes up.</summary>
    MouseUp,
    /// <summary>The wheel turns (notches, positive away from the user).</summary>
    Wheel,
    /// <summary>
    /// No input: the script's clock stops here until every ball rests (and the referee has ruled),
    /// so the events after it never reach a table still rolling, however slow the machine.
    /// </summary>
    WaitRest,
}

/// <summary>One timed input event of a script.</summary>
/// <param name="Time">When, in seconds after the first frame.</param>
/// <param name="Action">What.</param>
/// <param name="Key">The key of a key event.</param>
/// <param name="Button">The button of a button event.</param>
/// <param name="Vector">The position or offset of a move (pixels).</param>
/// <param name="Amount">The wheel's notches.</param>
public sealed record ScriptEvent(double Time, ScriptAction Action, Key Key = Key.Unknown, MouseButton Button = MouseButton.Left, Vector2 Vector = default, float Amount = 0)
{
    /// <summary>A short description for the stats file, e.g. "key_down F1" or "mouse_move_by 0,-40".</summary>
    public string Describe() => Action switch
    {
        ScriptAction.KeyDown => $"key_down {Key}",
        ScriptAction.KeyUp => $"key_up {Key}",
        ScriptAction.MouseMove => string.Create(CultureInfo.InvariantCulture, $"mouse_move {Vector.X},{Vector.Y}"),
        ScriptAction.MouseMoveBy => string.Create(CultureInfo.InvariantCulture, $"mouse_move_by {Vector.X},{Vector.Y}"),
        ScriptAction.MouseDown => $"mouse_down {Button.ToString().ToLowerInvariant()}",
        ScriptAction.MouseUp => $"mouse_up {Button.ToString().ToLowerInvariant()}",
        ScriptAction.WaitRest => "wait rest",
        _ => string.Create(CultureInfo.InvariantCulture, $"wheel {Amount}"),
    };
}

/// <summary>
/// A timed list of input events for <c>play --script</c> (format <c>billiards-input-script/1</c>):
/// <code>
/// { "format": "billiards-input-script/1",
///   "duration": 60,
///   "events": [
///     { "t": 1.0, "key_down": "S" },  { "t": 1.05, "key_up": "S" },
///     { "t": 1.2, "mouse_move": [640, 360] },
///     { "t": 1.3, "mouse_down": "left" },
///     { "t": 1.4, "mouse_move_by": [0, 40] },
///     { "t": 1.9, "mouse_up": "left" },
///     { "t": 2.0, "wheel": 1 }, { "t": 2.1, "wheel": -1 } ] }
/// </code>
/// <c>t</c> is seconds after the first frame, non-decreasing. Keys are the game's key names
/// (letters, <c>D0</c>..<c>D9</c>, <c>Space</c>, <c>Escape</c>, <c>Up</c>, <c>F1</c>, ...), buttons
/// <c>left</c>, <c>right</c>, <c>middle</c>; positions are window pixels, y down; the wheel turns
/// by notches, positive away from the user, negative towards. The game closes
/// at <c>duration</c> seconds (default: one second after the last event).
/// <c>{ "t": 5.0, "wait": "rest" }</c> stops the script's clock at 5 s until every ball rests; the
/// script's times are then its own clock's, which stands still while it waits. <c>"speed"</c> (default
/// 1, at most 64) runs the game's physics that many times faster than the wall clock, so a long
/// scripted game plays in a short time; the game played is the same at any speed and frame rate.
/// </summary>
public sealed record InputScript(IReadOnlyList<ScriptEvent> Events, double Duration, double Speed = 1)
{
    /// <summary>The fastest <see cref="Speed"/> a script may ask for.</summary>
    public const double MaxSpeed = 64;

    /// <summary>The format tag.</summary>
    public const string Format = "billiards-input-script/1";

    /// <summary>Reads a script file; a bad file is a <see cref="CliException"/> naming the file, the JSON path and the problem.</summary>
    public static InputScript Load(string path)
    {
        string text;
        try
        {
            text = File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"--script {path}: cannot read it: {e.Message}");
        }
        return Parse(text, path);
    }

    /// <summary>Parses a script's JSON; <paramref name="name"/> names it in messages.</summary>
    public static InputScript Parse(string json, string name)
    {
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json);
        }
        catch (JsonException e)
        {
            throw new CliException($"{name}: not JSON: {e.Message}");
        }
        using (document)
        {
            var root = document.RootElement;
            if (root.ValueKind != JsonValueKind.Object)
            {
                throw Bad(name, "$", "expected an object");
            }
            if (!root.TryGetProperty("format", out var format) || format.ValueKind != JsonValueKind.String || format.GetString() != Format)
            {
                throw Bad(name, "$.format", $"expected \"{Format}\"");
            }
            if (!root.TryGetProperty("events", out var list) || list.ValueKind != JsonValueKind.Array)
            {
                throw Bad(name, "$.events", "expected an array of events");
            }
            var events = new List<ScriptEvent>();
            double last = 0;
            int i = 0;
            foreach (var item in list.EnumerateArray())
            {
                string at = $"$.events[{i}]";
                var e = ParseEvent(item, name, at);
                if (e.Time < last)
                {
                    throw Bad(name, at + ".t", string.Create(CultureInfo.InvariantCulture, $"{e.Time} s is before the previous event ({last} s); times must not decrease"));
                }
                last = e.Time;
                events.Add(e);
                i++;
            }
            double duration = last + 1;
            if (root.TryGetProperty("duration", out var d))
            {
                duration = Number(d, name, "$.duration");
                if (duration < last)
                {
                    throw Bad(name, "$.duration", string.Create(CultureInfo.InvariantCulture, $"{duration} s ends before the last event ({last} s)"));
                }
            }
            double speed = 1;
            if (root.TryGetProperty("speed", out var sp))
            {
                speed = sp.ValueKind == JsonValueKind.Number && sp.TryGetDouble(out double v) && double.IsFinite(v) && v > 0 && v <= MaxSpeed
                    ? v
                    : throw Bad(name, "$.speed", string.Create(CultureInfo.InvariantCulture, $"expected a number above 0, at most {MaxSpeed}"));
            }
            foreach (var property in root.EnumerateObject())
            {
                if (property.Name is not ("format" or "events" or "duration" or "speed"))
                {
                    throw Bad(name, "$." + property.Name, "unknown field (expected format, duration, speed, events)");
                }
            }
            return new InputScript(events, duration, speed);
        }
    }

    private static ScriptEvent ParseEvent(JsonElement item, string name, string at)
    {
        if (item.ValueKind != JsonValueKind.Object)
        {
            throw Bad(name, at, "expected an object");
        }
        if (!item.TryGetProperty("t", out var t))
        {
            throw Bad(name, at + ".t", "missing (seconds after the first frame)");
        }
        double time = Number(t, name, at + ".t");
        ScriptEvent? result = null;
        foreach (var property in item.EnumerateObject())
        {
            if (property.Name == "t")
            {
                continue;
            }
            if (result is not null)
            {
                throw Bad(name, $"{at}.{property.Name}", "one action per event");
            }
            string where = $"{at}.{property.Name}";
            result = property.Name switch
            {
                "key_down" => new ScriptEvent(time, ScriptAction.KeyDown, Key: ParseKey(property.Value, name, where)),
                "key_up" => new ScriptEvent(time, ScriptAction.KeyUp, Key: ParseKey(property.Value, name, where)),
                "mouse_move" => new ScriptEvent(time, ScriptAction.MouseMove, Vector: Pair(property.Value, name, where)),
                "mouse_move_by" => new ScriptEvent(time, ScriptAction.MouseMoveBy, Vector: Pair(property.Value, name, where)),
                "mouse_down" => new ScriptEvent(time, ScriptAction.MouseDown, Button: ParseButton(property.Value, name, where)),
                "mouse_up" => new ScriptEvent(time, ScriptAction.MouseUp, Button: ParseButton(property.Value, name, where)),
                "wheel" => new ScriptEvent(time, ScriptAction.Wheel, Amount: Notches(property.Value, name, where)),
                "wait" => property.Value.ValueKind == JsonValueKind.String && property.Value.GetString() == "rest"
                    ? new ScriptEvent(time, ScriptAction.WaitRest)
                    : throw Bad(name, where, "expected \"rest\""),
                _ => throw Bad(name, where, "unknown action (expected key_down, key_up, mouse_move, mouse_move_by, mouse_down, mouse_up, wheel or wait)"),
            };
        }
        return result ?? throw Bad(name, at, "no action (key_down, key_up, mouse_move, mouse_move_by, mouse_down, mouse_up, wheel or wait)");
    }

    private static double Number(JsonElement e, string name, string at) =>
        e.ValueKind == JsonValueKind.Number && e.TryGetDouble(out double v) && double.IsFinite(v) && v >= 0 && v <= 86_400
            ? v
            : throw Bad(name, at, "expected a number from 0 to 86400");

    /// <summary>The most notches one wheel event may turn, either way.</summary>
    public const double MaxWheelNotches = 100;

    // Either way: negative notches turn the wheel towards the user.
    private static float Notches(JsonElement e, string name, string at) =>
        e.ValueKind == JsonValueKind.Number && e.TryGetDouble(out double v) && double.IsFinite(v) && Math.Abs(v) <= MaxWheelNotches
            ? (float)v
            : throw Bad(name, at, string.Create(CultureInfo.InvariantCulture, $"expected a number of notches from -{MaxWheelNotches} to {MaxWheelNotches}"));

    private static Vector2 Pair(JsonElement e, string name, string at)
    {
        if (e.ValueKind != JsonValueKind.Array || e.GetArrayLength() != 2)
        {
            throw Bad(name, at, "expected [x, y] in pixels");
        }
        var values = e.EnumerateArray().Select(v => v.ValueKind == JsonValueKind.Number && v.TryGetDouble(out double d) && double.IsFinite(d) && Math.Abs(d) <= 100_000
            ? (float)d
            : throw Bad(name, at, "expected [x, y] in pixels")).ToArray();
        return new Vector2(values[0], values[1]);
    }

    private static Key ParseKey(JsonElement e, string name, string at) =>
        e.ValueKind == JsonValueKind.String && Enum.TryParse<Key>(e.GetString(), ignoreCase: true, out var key) && key != Key.Unknown
            && !int.TryParse(e.GetString(), out _)
            ? key
            : throw Bad(name, at, $"unknown key {e} (expected a key name such as S, Space, Escape, Up, F1, D1)");

    private static MouseButton ParseButton(JsonElement e, string name, string at) =>
        e.ValueKind == JsonValueKind.String && e.GetString() is "left" or "right" or "middle"
            ? Enum.Parse<MouseButton>(e.GetString()!, ignoreCase: true)
            : throw Bad(name, at, "expected \"left\", \"right\" or \"middle\"");

    private static CliException Bad(string name, string at, string problem) => new($"{name}: {at}: {problem}");
}
