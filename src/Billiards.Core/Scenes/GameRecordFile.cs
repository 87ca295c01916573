using System.Globalization;
using System.Text.Json;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;

namespace Billiards.Core.Scenes;

/// <summary>A game record as read from a file: the setup, each shot's input and its recorded ruling.</summary>
/// <param name="Setup">Table, physics, rack seed and the start state.</param>
/// <param name="Shots">What the players did, shot by shot.</param>
/// <param name="Rulings">Each shot's ruling as recorded (JSON, as <see cref="GameBlockWriter.RulingToUtf8"/> writes it).</param>
public sealed record GameRecord(GameSetup Setup, IReadOnlyList<GameShot> Shots, IReadOnlyList<string> Rulings);

/// <summary>
/// Writes and reads "billiards-game/1" (scene-format.md): the table, the physics, the rack (game
/// and seed), then per shot the game block before it, the cue-ball placement, the call, the shot
/// and the ruling; "choice" names the option the next shooter took when the ruling offered some.
/// </summary>
public static class GameRecordFile
{
    /// <summary>The format tag of a game record.</summary>
    public const string Format = "billiards-game/1";

    /// <summary>The record of a played game as indented UTF-8 JSON.</summary>
    public static byte[] ToUtf8(GamePlayer game)
    {
        ArgumentNullException.ThrowIfNull(game);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            Write(w, game);
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }

    private static void Write(Utf8JsonWriter w, GamePlayer game)
    {
        var setup = game.Setup;
        w.WriteStartObject();
        w.WriteString("format", Format);
        w.WriteStartObject("table");
        w.WriteString("preset", setup.Table.Preset);
        w.WriteNumber("length", setup.Table.Length);
        w.WriteNumber("width", setup.Table.Width);
        w.WriteNumber("cushion_height", setup.Table.CushionHeight);
        w.WriteEndObject();
        WritePhysics(w, setup.Physics);
        w.WriteStartObject("rack");
        w.WriteString("game", setup.Rules.ToName());
        w.WriteNumber("seed", setup.Seed);
        w.WriteEndObject();
        w.WritePropertyName("game");
        GameBlockWriter.WriteGame(w, setup.Start);
        w.WriteStartArray("shots");
        foreach (var played in game.Shots)
        {
            var input = played.Input;
            w.WriteStartObject();
            w.WritePropertyName("game");
            GameBlockWriter.WriteGame(w, played.Before);
            WritePlace(w, "place", input.Place);
            if (input.Call is { } call)
            {
                GameBlockWriter.WriteCall(w, "call", call);
            }
            else
            {
                w.WriteNull("call");
            }
            WriteShot(w, "shot", input.Shot);
            if (input.Choice is { } choice)
            {
                w.WriteString("choice", choice.ToName());
            }
            else
            {
                w.WriteNull("choice");
            }
            w.WritePropertyName("ruling");
            GameBlockWriter.WriteRuling(w, played.Ruling);
            w.WriteEndObject();
        }
        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>A cue-ball placement as records write it: [x, y] (m), or null.</summary>
    public static void WritePlace(Utf8JsonWriter w, string name, Vec3? place)
    {
        ArgumentNullException.ThrowIfNull(w);
        if (place is not { } p)
        {
            w.WriteNull(name);
            return;
        }
        w.WriteStartArray(name);
        w.WriteNumberValue(p.X);
        w.WriteNumberValue(p.Y);
        w.WriteEndArray();
    }

    /// <summary>A shot as scenes and records write it: speed (m/s), aim (deg), tip (fractions of R), elevation (deg).</summary>
    public static void WriteShot(Utf8JsonWriter w, string name, ShotSpec shot)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(shot);
        w.WriteStartObject(name);
        w.WriteNumber("speed", shot.Speed);
        w.WriteNumber("aim_deg", shot.AimDeg);
        w.WriteStartArray("tip");
        w.WriteNumberValue(shot.TipSide);
        w.WriteNumberValue(shot.TipHeight);
        w.WriteEndArray();
        w.WriteNumber("elevation_deg", shot.ElevationDeg);
        w.WriteEndObject();
    }

    private static void WritePhysics(Utf8JsonWriter w, PhysicsConfig physics)
    {
        w.WriteStartObject("physics");
        w.WriteString("model", physics.Model.Name);
        w.WriteString("integrator", physics.Integrator.Name);
        w.WriteNumber("dt", physics.Dt);
        // Every model's record carries the parameters: a model that keeps its own constants ignores them.
        var p = physics.Params;
        w.WriteStartObject("params");
        w.WriteNumber("m", p.M);
        w.WriteNumber("R", p.R);
        w.WriteNumber("mu_s", p.MuS);
        w.WriteNumber("mu_r", p.MuR);
        w.WriteNumber("mu_sp", p.MuSp);
        if (p.MuBModel == BallBallFriction.Alciatore)
        {
            w.WriteString("mu_b", "alciatore");
        }
        else
        {
            w.WriteNumber("mu_b", p.MuB);
        }
        w.WriteNumber("e_b", p.EB);
        w.WriteNumber("e_c", p.EC);
        w.WriteNumber("f_c", p.FC);
        w.WriteNumber("g", p.G);
        w.WriteNumber("M", p.CueMass);
        w.WriteNumber("m_e", p.CueEndMass);
        w.WriteNumber("omega_ratio", p.OmegaRatio);
        w.WriteEndObject();
        if (physics.Model.TakesInteractionModels)
        {
            ResultWriter.WriteModels(w, physics.Models);
        }
        w.WriteEndObject();
    }

    /// <summary>Reads a game record; <paramref name="path"/> names the source in errors.</summary>
    /// <exception cref="SceneException">When the record is malformed or invalid.</exception>
    public static GameRecord Parse(string json, string path)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(json);
        }
        catch (JsonException e)
        {
            throw new SceneException(path, "$", $"not valid JSON: line {e.LineNumber + 1}: {e.Message}");
        }
        using (doc)
        {
            return Read(doc.RootElement, path);
        }
    }

    private static GameRecord Read(JsonElement root, string file)
    {
        SceneException Error(string at, string problem) => new(file, at, problem);
        JsonElement Get(JsonElement e, string name, string at) =>
            e.ValueKind == JsonValueKind.Object && e.TryGetProperty(name, out var v) ? v : throw Error(at, $"missing \"{name}\"");

        if (root.ValueKind != JsonValueKind.Object || !root.TryGetProperty("format", out var format) || format.ValueKind != JsonValueKind.String || format.GetString() != Format)
        {
            throw Error("$.format", $"expected \"{Format}\"");
        }
        // The table and physics blocks are the scene's: the scene loader checks them.
        var table = Get(root, "table", "$");
        var physics = Get(root, "physics", "$");
        var scene = SceneLoader.Parse(
            $$"""{ "format": "{{SceneLoader.Format}}", "table": {{table.GetRawText()}}, "physics": {{physics.GetRawText()}} }""", file);
        var rack = Get(root, "rack", "$");
        var seedElement = Get(rack, "seed", "$.rack");
        if (!seedElement.TryGetInt32(out int seed))
        {
            throw Error("$.rack.seed", "expected a whole number (a 32-bit integer)");
        }
        var start = GameBlockReader.Read(Get(root, "game", "$"), file, "$.game");
        string rackGame = Get(rack, "game", "$.rack").GetString() ?? "";
        if (rackGame != start.Rules.ToName())
        {
            throw Error("$.rack.game", $"the rack \"{rackGame}\" does not match the game's rules \"{start.Rules.ToName()}\"");
        }
        var setup = new GameSetup(scene.Table, scene.Physics, seed, start);

        var shots = new List<GameShot>();
        var rulings = new List<string>();
        int i = 0;
        foreach (var s in Get(root, "shots", "$").EnumerateArray())
        {
            string at = string.Create(CultureInfo.InvariantCulture, $"$.shots[{i++}]");
            var before = GameBlockReader.Read(Get(s, "game", at), file, at + ".game");
            Vec3? place = null;
            if (s.TryGetProperty("place", out var pl) && pl.ValueKind == JsonValueKind.Array)
            {
                place = pl.GetArrayLength() == 2 ? new Vec3(pl[0].GetDouble(), pl[1].GetDouble(), setup.BallRadius) : throw Error(at + ".place", "expected [x, y]");
            }
            var shot = Get(s, "shot", at);
            var tip = shot.TryGetProperty("tip", out var t) ? t : default;
            var spec = new ShotSpec(
                Get(shot, "speed", at + ".shot").GetDouble(),
                Get(shot, "aim_deg", at + ".shot").GetDouble(),
                tip.ValueKind == JsonValueKind.Array ? tip[0].GetDouble() : 0,
                tip.ValueKind == JsonValueKind.Array ? tip[1].GetDouble() : 0,
                shot.TryGetProperty("elevation_deg", out var el) ? el.GetDouble() : 0);
            RefereeOption? choice = null;
            if (s.TryGetProperty("choice", out var c) && c.ValueKind == JsonValueKind.String)
            {
                choice = RuleNames.TryParseOption(c.GetString(), out var option) ? option : throw Error(at + ".choice", $"unknown option \"{c.GetString()}\"");
            }
            shots.Add(new GameShot(spec, before.Call, place, before.PushOut, choice));
            rulings.Add(System.Text.Encoding.UTF8.GetString(Reindent(Get(s, "ruling", at))));
        }
        return new GameRecord(setup, shots, rulings);
    }

    // The ruling as GameBlockWriter.RulingToUtf8 formats it, so that rulings compare as text.
    private static byte[] Reindent(JsonElement e)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            e.WriteTo(w);
        }
        return stream.ToArray();
    }

    /// <summary>
    /// Plays a record's shots again through the same physics and referee and returns the first
    /// shot whose ruling differs from the recorded one, or -1 when every ruling is reproduced.
    /// </summary>
    public static int Replay(GameRecord record, out GamePlayer replayed)
    {
        ArgumentNullException.ThrowIfNull(record);
        replayed = new GamePlayer(record.Setup);
        for (int k = 0; k < record.Shots.Count; k++)
        {
            var played = replayed.Play(record.Shots[k]);
            string ruling = System.Text.Encoding.UTF8.GetString(GameBlockWriter.RulingToUtf8(played.Ruling));
            if (ruling != record.Rulings[k])
            {
                return k;
            }
        }
        return -1;
    }
}
