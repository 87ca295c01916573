using System.Globalization;
using System.Text.Json;

namespace Billiards.App.Net;

// The wire's messages (docs/network.md): each a JSON object {"v": 1, "kind": "...", ...}. They are
// read with JsonDocument field by field into these records only: no type names, no polymorphic
// deserialisation, nothing on the wire decides which .NET type is made. Every field is checked
// (type, range, finite, length) and an unknown field or kind refuses the message.

/// <summary>One message of the network protocol.</summary>
public abstract record Message
{
    /// <summary>The protocol's version; a message of another is refused.</summary>
    public const int Version = 1;

    /// <summary>The kind's name on the wire.</summary>
    public abstract string Kind { get; }
}

/// <summary>The physics and the game the host chose, in its hello.</summary>
/// <param name="Scene">The game not yet played as a game record (compact JSON: table, physics, rack).</param>
/// <param name="Models">The physics' model names, for the one line that says what differs.</param>
/// <param name="Hash">SHA-256 (hex) of the scene's table and physics as written.</param>
/// <param name="FirstPlayer">Player 1's name (the host's seat).</param>
/// <param name="SecondPlayer">Player 2's name.</param>
public sealed record HostGame(string Scene, string Models, string Hash, string FirstPlayer, string SecondPlayer);

/// <summary>The handshake: both sides send one first; the host's carries the game.</summary>
/// <param name="Program">The program's version (<c>billiards --version</c>).</param>
/// <param name="Code">The 6-character code.</param>
/// <param name="Game">The game and physics (the host's hello), or null (the joiner's).</param>
/// <param name="Shots">The shots the sender's game has played (a joiner coming back resumes from the host's).</param>
public sealed record Hello(string Program, string Code, HostGame? Game, int Shots) : Message
{
    public override string Kind => "hello";
}

/// <summary>A stroke: the cue's five parameters for shot number <paramref name="Shot"/> of the session.</summary>
public sealed record Stroke(int Shot, double Speed, double AimDeg, double TipSide, double TipHeight, double ElevationDeg, bool PushOut) : Message
{
    public override string Kind => "stroke";
}

/// <summary>Ball in hand: where the cue ball is placed for shot <paramref name="Shot"/> (m, table frame).</summary>
public sealed record Placement(int Shot, double X, double Y) : Message
{
    public override string Kind => "placement";
}

/// <summary>The call for shot <paramref name="Shot"/>: a ball and a pocket (a name of the table's), a nomination (no pocket) or a safety (no ball).</summary>
public sealed record CallMessage(int Shot, int? Ball, string? Pocket) : Message
{
    public override string Kind => "call";
}

/// <summary>The incoming player's choice among the ruling's options after shot <paramref name="Shot"/>.</summary>
public sealed record Choice(int Shot, string Option) : Message
{
    public override string Kind => "choice";
}

/// <summary>After shot <paramref name="Shot"/>: the hash of the balls at rest and of the ruling.</summary>
public sealed record StateHash(int Shot, string Balls, string Ruling) : Message
{
    public override string Kind => "state_hash";
}

/// <summary>
/// One part of the host's whole game after shot <paramref name="Shot"/> (after a mismatch, or for
/// a joiner coming back): part <paramref name="Part"/> of <paramref name="Parts"/> of the game
/// record packed by <see cref="ResyncPacking"/>.
/// </summary>
public sealed record Resync(int Shot, int Part, int Parts, string Record) : Message
{
    public override string Kind => "resync";
}

/// <summary>A ping (<paramref name="Reply"/> false) or its answer; <paramref name="Id"/> pairs them.</summary>
public sealed record Ping(long Id, bool Reply) : Message
{
    public override string Kind => "ping";
}

/// <summary>The last message: why the sender closes (a refusal names what differs).</summary>
public sealed record Bye(string Reason) : Message
{
    public override string Kind => "bye";
}

/// <summary>A message refused: what is wrong with it, in one line.</summary>
public sealed class ProtocolException(string message) : Exception(message);

/// <summary>Reads and writes <see cref="Message"/>s as the wire's JSON.</summary>
public static class MessageCodec
{
    /// <summary>The game's code: 6 characters of this alphabet (no 0/O, 1/I).</summary>
    public const string CodeAlphabet = "ABCDEFGHJKLMNPQRSTUVWXYZ23456789";

    /// <summary>Length of a code.</summary>
    public const int CodeLength = 6;

    /// <summary>Largest cue speed on the wire (m/s), the scene format's.</summary>
    public const double MaxSpeed = Core.Scenes.SceneLoader.MaxShotSpeed;

    /// <summary>Largest shot number (a session longer than this is refused).</summary>
    public const int MaxShot = 100_000;

    /// <summary>Longest text field (a reason, an option, a hash, a version), characters.</summary>
    public const int MaxText = 200;

    /// <summary>Largest table coordinate of a placement (m).</summary>
    public const double MaxCoordinate = 5;

    private static readonly JsonDocumentOptions DocumentOptions = new() { MaxDepth = 8, AllowTrailingCommas = false, CommentHandling = JsonCommentHandling.Disallow };

    /// <summary>True when <paramref name="code"/> is a well-formed code.</summary>
    public static bool IsCode(string? code) => code is { Length: CodeLength } && code.All(c => CodeAlphabet.Contains(c, StringComparison.Ordinal));

    /// <summary>A new code from <paramref name="random"/>.</summary>
    public static string NewCode(Random random)
    {
        ArgumentNullException.ThrowIfNull(random);
        return new string([.. Enumerable.Range(0, CodeLength).Select(_ => CodeAlphabet[random.Next(CodeAlphabet.Length)])]);
    }

    /// <summary>Parses one message's UTF-8 JSON.</summary>
    /// <exception cref="ProtocolException">Not JSON, not an object, another version, an unknown kind, or a field missing, unknown, of the wrong type or out of range.</exception>
    public static Message Parse(ReadOnlyMemory<byte> json)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(json, DocumentOptions);
        }
        catch (JsonException e)
        {
            throw new ProtocolException($"malformed JSON ({FirstLine(e.Message)})");
        }
        using (doc)
        {
            var root = doc.RootElement;
            if (root.ValueKind != JsonValueKind.Object)
            {
                throw new ProtocolException($"a message is a JSON object, not {root.ValueKind.ToString().ToLowerInvariant()}");
            }
            var f = new Fields(root);
            int v = f.Int("v", 0, 1000);
            if (v != Message.Version)
            {
                throw new ProtocolException($"protocol version {v}, expected {Message.Version}");
            }
            string kind = f.Text("kind", 32);
            Message m = kind switch
            {
                "hello" => new Hello(f.Text("program", 64), f.Text("code", 16), f.Has("game") ? HostGameOf(f.Object("game")) : null, f.Int("shots", 0, MaxShot)),
                "stroke" => new Stroke(f.Int("shot", 0, MaxShot), f.Number("speed", 0, MaxSpeed), f.Number("aim_deg", -360, 360),
                    f.Number("tip_side", -1, 1), f.Number("tip_height", -1, 1), f.Number("elevation_deg", 0, 90), f.Bool("push_out")),
                "placement" => new Placement(f.Int("shot", 0, MaxShot), f.Number("x", -MaxCoordinate, MaxCoordinate), f.Number("y", -MaxCoordinate, MaxCoordinate)),
                "call" => new CallMessage(f.Int("shot", 0, MaxShot), f.OptionalInt("ball", 0, 63), f.OptionalText("pocket", 32)),
                "choice" => new Choice(f.Int("shot", 0, MaxShot), f.Text("option", 32)),
                "state_hash" => new StateHash(f.Int("shot", 0, MaxShot), f.Hex("balls"), f.Hex("ruling")),
                "resync" => ResyncOf(f),
                "ping" => new Ping(f.Long("id"), f.Bool("reply")),
                "bye" => new Bye(f.Text("reason", MaxText)),
                _ => throw new ProtocolException($"unknown kind \"{Clip(kind)}\""),
            };
            f.NoOthers(kind);
            if (m is Stroke s && (s.TipSide * s.TipSide) + (s.TipHeight * s.TipHeight) >= 1)
            {
                throw new ProtocolException("stroke: the tip offset must lie inside the ball (side^2 + height^2 < 1)");
            }
            return m;
        }
    }

    private static Resync ResyncOf(Fields f)
    {
        var r = new Resync(f.Int("shot", 0, MaxShot), f.Int("part", 0, ResyncPacking.MaxParts - 1), f.Int("parts", 1, ResyncPacking.MaxParts), f.Text("record", ResyncPacking.PartChars));
        return r.Part < r.Parts ? r : throw new ProtocolException($"resync: part {r.Part} of {r.Parts}");
    }

    private static HostGame HostGameOf(JsonElement e)
    {
        var f = new Fields(e);
        var game = new HostGame(f.Text("scene", Framing.MaxMessageBytes), f.Text("models", 1000), f.Hex("hash"), f.Text("first_player", Core.Rules.Seat.MaxNameLength), f.Text("second_player", Core.Rules.Seat.MaxNameLength));
        f.NoOthers("hello.game");
        return game;
    }

    /// <summary>The message as the wire's UTF-8 JSON.</summary>
    public static byte[] Write(Message message)
    {
        ArgumentNullException.ThrowIfNull(message);
        using var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer))
        {
            w.WriteStartObject();
            w.WriteNumber("v", Message.Version);
            w.WriteString("kind", message.Kind);
            switch (message)
            {
                case Hello h:
                    w.WriteString("program", h.Program);
                    w.WriteString("code", h.Code);
                    w.WriteNumber("shots", h.Shots);
                    if (h.Game is { } g)
                    {
                        w.WriteStartObject("game");
                        w.WriteString("scene", g.Scene);
                        w.WriteString("models", g.Models);
                        w.WriteString("hash", g.Hash);
                        w.WriteString("first_player", g.FirstPlayer);
                        w.WriteString("second_player", g.SecondPlayer);
                        w.WriteEndObject();
                    }
                    break;
                case Stroke s:
                    w.WriteNumber("shot", s.Shot);
                    w.WriteNumber("speed", s.Speed);
                    w.WriteNumber("aim_deg", s.AimDeg);
                    w.WriteNumber("tip_side", s.TipSide);
                    w.WriteNumber("tip_height", s.TipHeight);
                    w.WriteNumber("elevation_deg", s.ElevationDeg);
                    w.WriteBoolean("push_out", s.PushOut);
                    break;
                case Placement p:
                    w.WriteNumber("shot", p.Shot);
                    w.WriteNumber("x", p.X);
                    w.WriteNumber("y", p.Y);
                    break;
                case CallMessage c:
                    w.WriteNumber("shot", c.Shot);
                    if (c.Ball is int ball)
                    {
                        w.WriteNumber("ball", ball);
                    }
                    if (c.Pocket is { } pocket)
                    {
                        w.WriteString("pocket", pocket);
                    }
                    break;
                case Choice c:
                    w.WriteNumber("shot", c.Shot);
                    w.WriteString("option", c.Option);
                    break;
                case StateHash h:
                    w.WriteNumber("shot", h.Shot);
                    w.WriteString("balls", h.Balls);
                    w.WriteString("ruling", h.Ruling);
                    break;
                case Resync r:
                    w.WriteNumber("shot", r.Shot);
                    w.WriteNumber("part", r.Part);
                    w.WriteNumber("parts", r.Parts);
                    w.WriteString("record", r.Record);
                    break;
                case Ping p:
                    w.WriteNumber("id", p.Id);
                    w.WriteBoolean("reply", p.Reply);
                    break;
                case Bye b:
                    w.WriteString("reason", b.Reason);
                    break;
                default:
                    throw new ArgumentException($"no wire form for {message.GetType().Name}", nameof(message));
            }
            w.WriteEndObject();
        }
        return buffer.ToArray();
    }

    /// <summary>At most 40 characters of <paramref name="text"/>, control characters shown as '?', for a log line.</summary>
    public static string Clip(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        string s = new([.. text.Take(40).Select(c => char.IsControl(c) ? '?' : c)]);
        return text.Length > 40 ? s + "..." : s;
    }

    private static string FirstLine(string s) => Clip(s.Split('\n')[0]);

    // The fields of one object, each read once; what is left over is an unknown field.
    private sealed class Fields
    {
        private readonly Dictionary<string, JsonElement> _fields = new(StringComparer.Ordinal);

        public Fields(JsonElement e)
        {
            foreach (var p in e.EnumerateObject())
            {
                if (!_fields.TryAdd(p.Name, p.Value))
                {
                    throw new ProtocolException($"field \"{Clip(p.Name)}\" twice");
                }
            }
        }

        public bool Has(string name) => _fields.ContainsKey(name);

        private JsonElement Take(string name, JsonValueKind kind)
        {
            if (!_fields.Remove(name, out var e))
            {
                throw new ProtocolException($"missing field \"{name}\"");
            }
            bool ok = kind == JsonValueKind.True ? e.ValueKind is JsonValueKind.True or JsonValueKind.False : e.ValueKind == kind;
            return ok ? e : throw new ProtocolException($"\"{name}\": expected {(kind == JsonValueKind.True ? "true or false" : kind.ToString().ToLowerInvariant())}, not {e.ValueKind.ToString().ToLowerInvariant()}");
        }

        public JsonElement Object(string name) => Take(name, JsonValueKind.Object);

        public bool Bool(string name) => Take(name, JsonValueKind.True).GetBoolean();

        public double Number(string name, double min, double max)
        {
            var e = Take(name, JsonValueKind.Number);
            if (!e.TryGetDouble(out double x) || !double.IsFinite(x))
            {
                throw new ProtocolException($"\"{name}\": not a finite number");
            }
            return x >= min && x <= max ? x : throw new ProtocolException(string.Create(CultureInfo.InvariantCulture, $"\"{name}\": {x} is out of range [{min}, {max}]"));
        }

        public long Long(string name) => Take(name, JsonValueKind.Number).TryGetInt64(out long x) ? x : throw new ProtocolException($"\"{name}\": not an integer");

        public int Int(string name, int min, int max)
        {
            if (!Take(name, JsonValueKind.Number).TryGetInt32(out int x))
            {
                throw new ProtocolException($"\"{name}\": not an integer");
            }
            return x >= min && x <= max ? x : throw new ProtocolException($"\"{name}\": {x} is out of range [{min}, {max}]");
        }

        public int? OptionalInt(string name, int min, int max) => Has(name) ? Int(name, min, max) : null;

        public string Text(string name, int maxLength)
        {
            string s = Take(name, JsonValueKind.String).GetString()!;
            if (s.Length > maxLength)
            {
                throw new ProtocolException($"\"{name}\": longer than {maxLength} characters");
            }
            // A log line is one line: no control characters in short fields (a scene or a record is JSON text and may have newlines).
            return maxLength > MaxText || !s.Any(char.IsControl) ? s : throw new ProtocolException($"\"{name}\": a control character");
        }

        public string? OptionalText(string name, int maxLength) => Has(name) ? Text(name, maxLength) : null;

        public string Hex(string name)
        {
            string s = Text(name, 64);
            return s.Length == 64 && s.All(char.IsAsciiHexDigitLower) ? s : throw new ProtocolException($"\"{name}\": expected 64 lowercase hex digits");
        }

        public void NoOthers(string kind)
        {
            if (_fields.Count > 0)
            {
                throw new ProtocolException($"{kind}: unknown field \"{Clip(_fields.Keys.First())}\"");
            }
        }
    }
}
