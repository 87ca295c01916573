using System.Globalization;
using System.Text.Json;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;

namespace Billiards.Core.Scenes;

/// <summary>A game record as read from a file: the setup, each shot's input and what was recorded of it.</summary>
/// <param name="Setup">Table, physics, rack seed, the start state and the first position when it is not the rack.</param>
/// <param name="Shots">What the players did, shot by shot.</param>
/// <param name="Before">Each shot's game block as recorded: the state before it.</param>
/// <param name="Rulings">Each shot's ruling as recorded (JSON, as <see cref="GameBlockWriter.RulingToUtf8"/> writes it).</param>
/// <param name="Balls">Each shot's balls at rest as recorded (JSON, as the record writes them), or null where the record has none.</param>
public sealed record GameRecord(GameSetup Setup, IReadOnlyList<GameShot> Shots, IReadOnlyList<GameState> Before, IReadOnlyList<string> Rulings, IReadOnlyList<string?> Balls)
{
    /// <summary>
    /// The option the incoming player took after shot <paramref name="shot"/>, whose ruling (as
    /// replayed) is <paramref name="ruling"/>: the one the shot names (older records), else the
    /// offered option whose outcome is the next shot's recorded game block; null when no shot
    /// follows or none fits.
    /// </summary>
    public RefereeOption? ChoiceAfter(int shot, Ruling ruling)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        if (Shots[shot].Choice is { } named)
        {
            return named;
        }
        if (shot + 1 >= Before.Count)
        {
            return null;
        }
        string next = GameRecordFile.StateText(Before[shot + 1]);
        foreach (var option in ruling.Options)
        {
            if (GameRecordFile.StateText(ruling.Choose(option).Next) == next)
            {
                return option;
            }
        }
        return null;
    }
}

/// <summary>The first difference between a record and its replay.</summary>
/// <param name="Shot">The shot's index in the record (0 the first).</param>
/// <param name="Field">What differs: "ruling.NAME" (a field of the ruling), "balls" (the balls at rest), or "shot" (the replay refused the shot).</param>
/// <param name="Recorded">The recorded value (JSON).</param>
/// <param name="Replayed">The replayed value (JSON).</param>
public sealed record ReplayDifference(int Shot, string Field, string Recorded, string Replayed);

/// <summary>What replaying a record found.</summary>
/// <param name="Shots">The record's shots.</param>
/// <param name="Same">Shots replayed the same, up to the first difference.</param>
/// <param name="FirstDifference">The first difference, or null when every shot is the same.</param>
public sealed record ReplayReport(int Shots, int Same, ReplayDifference? FirstDifference);

/// <summary>
/// Writes and reads "billiards-game/1" (scene-format.md): the table, the physics, the rack (game
/// and seed), then per shot the game block before it, the cue-ball placement, the call, the shot
/// and the ruling, with the balls at rest after it ("balls", as a scene lists its balls), which
/// <c>replay --verify</c> compares with the replayed ones (scene-format.md); a game that starts
/// from a scene's position rather than its rack lists that position the same way, in a top-level
/// "balls". The option the incoming
/// player took after a ruling that offered some is the one that leads to the next shot's game
/// block (<see cref="GameRecord.ChoiceAfter"/>). Several games (a session's rematches, a
/// self-play run) are one record per line (<see cref="ToJsonLines"/>).
/// </summary>
public static class GameRecordFile
{
    /// <summary>The format tag of a game record.</summary>
    public const string Format = "billiards-game/1";

    /// <summary>The record of a played game as UTF-8 JSON, indented or on one line, ending in a newline.</summary>
    public static byte[] ToUtf8(Match game, bool indented = true)
    {
        ArgumentNullException.ThrowIfNull(game);
        using var stream = new MemoryStream();
        Write(stream, game, indented);
        return stream.ToArray();
    }

    /// <summary>The records of several games, one per line in play order (JSON lines, as <c>replay</c> reads them).</summary>
    public static byte[] ToJsonLines(IEnumerable<Match> games)
    {
        ArgumentNullException.ThrowIfNull(games);
        using var stream = new MemoryStream();
        foreach (var game in games)
        {
            Write(stream, game, indented: false);
        }
        return stream.ToArray();
    }

    private static void Write(Stream stream, Match game, bool indented)
    {
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = indented }))
        {
            Write(w, game);
        }
        stream.WriteByte((byte)'\n');
    }

    /// <summary>A game state as a game block's JSON on one line, to compare states as the record writes them.</summary>
    public static string StateText(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            // What a shot adds to the state before it (its call, a push-out) is not part of the state it follows from.
            GameBlockWriter.WriteGame(w, state with { Call = null, PushOut = false, Placement = null });
        }
        return System.Text.Encoding.UTF8.GetString(stream.ToArray());
    }

    private static void Write(Utf8JsonWriter w, Match game)
    {
        var setup = game.Setup;
        w.WriteStartObject();
        w.WriteString("format", Format);
        w.WriteStartObject("table");
        w.WriteString("preset", setup.Table.Preset);
        w.WriteNumber("length", setup.Table.Length);
        w.WriteNumber("width", setup.Table.Width);
        w.WriteNumber("cushion_height", setup.Table.CushionHeight);
        w.WriteNumber("rail_height", setup.Table.RailHeight);
        w.WriteEndObject();
        WritePhysics(w, setup.Physics);
        w.WriteStartObject("rack");
        w.WriteString("game", setup.Rules.ToName());
        w.WriteNumber("seed", setup.Seed);
        w.WriteEndObject();
        if (setup.Position is { } position)
        {
            // A game from a scene's position rather than its rack.
            WriteBalls(w, "balls", position, setup.Ruleset.BallSet);
        }
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
                GameBlockWriter.WriteCall(w, "call", call, setup.Ruleset.BallSet);
            }
            else
            {
                w.WriteNull("call");
            }
            WriteShot(w, "shot", input.Shot);
            // The option taken, where the ruling offered some: the next shot's block cannot tell
            // snooker's "replace" (the balls go back) from its "put-back" (they stay).
            if (input.Choice is { } choice)
            {
                w.WriteString("choice", setup.Ruleset.WordOf(choice));
            }
            w.WritePropertyName("ruling");
            GameBlockWriter.WriteRuling(w, played.Ruling);
            // replay --verify compares "the balls at rest with the recorded ones" (scene-format.md):
            // the record keeps them, as a scene lists its balls.
            WriteBalls(w, "balls", played.After, setup.Ruleset.BallSet);
            w.WriteEndObject();
        }
        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>Balls at rest as records write them: [{"id", "position": [x, y]}] (m), as a scene's balls.</summary>
    public static void WriteBalls(Utf8JsonWriter w, string name, IEnumerable<(Balls.BallId Id, Vec3 Position)> balls, Balls.BallSet ballSet)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(balls);
        ArgumentNullException.ThrowIfNull(ballSet);
        w.WritePropertyName(name);
        WriteBallsValue(w, balls, ballSet);
    }

    private static void WriteBallsValue(Utf8JsonWriter w, IEnumerable<(Balls.BallId Id, Vec3 Position)> balls, Balls.BallSet ballSet)
    {
        w.WriteStartArray();
        foreach (var (id, p) in balls)
        {
            w.WriteStartObject();
            w.WriteString("id", ballSet.NameOf(id));
            WritePlace(w, "position", p);
            w.WriteEndObject();
        }
        w.WriteEndArray();
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

    /// <summary>The <c>physics</c> block as records and written scenes carry it: the model, integrator, step, every parameter and the collision models.</summary>
    internal static void WritePhysics(Utf8JsonWriter w, PhysicsConfig physics)
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
        switch (p.MuBModel)
        {
            case BallBallFriction.Alciatore:
                w.WriteString("mu_b", "alciatore");
                break;
            case BallBallFriction.Measured:
                w.WriteString("mu_b", "alciatore-2014");
                break;
            default:
                w.WriteNumber("mu_b", p.MuB);
                break;
        }
        w.WriteNumber("e_b", p.EB);
        if (p.ECModel == CushionRestitution.Measured)
        {
            w.WriteString("e_c", "mathavan-2009");
        }
        else
        {
            w.WriteNumber("e_c", p.EC);
        }
        w.WriteNumber("f_c", p.FC);
        w.WriteNumber("g", p.G);
        w.WriteNumber("M", p.CueMass);
        w.WriteNumber("m_e", p.CueEndMass);
        w.WriteNumber("omega_ratio", p.OmegaRatio);
        w.WriteNumber("e_t", p.ET);
        w.WriteNumber("e_tip", p.ETip);
        w.WriteNumber("miscue_limit", p.MiscueLimit);
        if (p.Tip == TipFrame.Face)
        {
            w.WriteString("tip_frame", "face");
        }
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
        using (var doc = SceneLoader.ParseJson(json, path))
        {
            try
            {
                return Read(doc.RootElement, path);
            }
            catch (Exception e) when (e is InvalidOperationException or FormatException or IndexOutOfRangeException)
            {
                // A value of the wrong kind where a number, string or array was expected.
                throw new SceneException(path, "$.shots", $"malformed record: {e.Message}");
            }
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
        string rackGame = Get(rack, "game", "$.rack").GetString() ?? "";
        if (!RuleNames.TryParseGame(rackGame, out var rules))
        {
            throw Error("$.rack.game", $"unknown game \"{rackGame}\" (expected one of {string.Join(", ", RuleNames.GameNames.Select(n => $"\"{n}\""))})");
        }
        var shotElements = Get(root, "shots", "$");
        if (shotElements.ValueKind != JsonValueKind.Array)
        {
            throw Error("$.shots", "expected an array of shots");
        }
        var blocks = shotElements.EnumerateArray()
            .Select((s, k) => GameBlockReader.Read(Get(s, "game", At(k)), scene.Table.Pockets, file, At(k) + ".game"))
            .ToList();
        // The game's start is its first shot's block without what the shot added (records of
        // earlier writers have it in a top-level "game"); a record without shots starts a game.
        var start = root.TryGetProperty("game", out var startBlock)
            ? GameBlockReader.Read(startBlock, scene.Table.Pockets, file, "$.game")
            : blocks.Count > 0 ? blocks[0] with { Call = null, PushOut = false, Placement = null } : new GameState(rules);
        if (start.Rules != rules)
        {
            throw Error("$.rack.game", $"the rack \"{rackGame}\" does not match the game's rules \"{start.Rules.ToName()}\"");
        }
        // A record written before the cue's frame (its params have no "e_tip") struck with the tip
        // on the ball's face, an elastic tip and no miscues: it replays that way.
        var physicsConfig = scene.Physics;
        if (physics.TryGetProperty("params", out var written) && written.ValueKind == JsonValueKind.Object && !written.TryGetProperty("e_tip", out _))
        {
            physicsConfig = physicsConfig with { Params = physicsConfig.Params with { ETip = 1, MiscueLimit = 1, Tip = TipFrame.Face } };
        }
        var setup = new GameSetup(scene.Table, physicsConfig, seed, start);
        if (root.TryGetProperty("balls", out var startBalls))
        {
            setup = setup with { Position = ReadBalls(startBalls, setup, file, "$.balls") };
        }

        var shots = new List<GameShot>();
        var rulings = new List<string>();
        var balls = new List<string?>();
        int i = 0;
        foreach (var s in shotElements.EnumerateArray())
        {
            string at = At(i);
            var before = blocks[i++];
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
            // The option taken after the shot, where the ruling offered some.
            RefereeOption? choice = null;
            if (s.TryGetProperty("choice", out var c) && c.ValueKind == JsonValueKind.String)
            {
                choice = setup.Ruleset.TryParseOption(c.GetString(), out var option) ? option
                    : throw Error(at + ".choice", $"unknown option \"{c.GetString()}\" (expected one of {rules.ToName()}'s: {string.Join(", ", setup.Ruleset.OptionWords.Select(o => $"\"{o.Word}\""))})");
            }
            shots.Add(new GameShot(spec, before.Call, place, before.PushOut, choice));
            rulings.Add(System.Text.Encoding.UTF8.GetString(Reindent(Get(s, "ruling", at))));
            if (s.TryGetProperty("balls", out var after))
            {
                ReadBalls(after, setup, file, at + ".balls");
                balls.Add(after.GetRawText());
            }
            else
            {
                balls.Add(null);
            }
        }
        return new GameRecord(setup, shots, blocks, rulings, balls);

        static string At(int k) => string.Create(CultureInfo.InvariantCulture, $"$.shots[{k}]");
    }

    private static Balls.BallLayout ReadBalls(JsonElement e, GameSetup setup, string file, string at)
    {
        if (e.ValueKind != JsonValueKind.Array)
        {
            throw new SceneException(file, at, "expected an array of balls [{\"id\", \"position\": [x, y]}]");
        }
        var set = setup.Ruleset.BallSet;
        var list = new List<(Balls.BallId, Vec3)>();
        int i = 0;
        foreach (var b in e.EnumerateArray())
        {
            string here = string.Create(CultureInfo.InvariantCulture, $"{at}[{i++}]");
            if (b.ValueKind != JsonValueKind.Object || !b.TryGetProperty("id", out var id) || id.ValueKind != JsonValueKind.String
                || !set.TryParse(id.GetString(), out var ball))
            {
                throw new SceneException(file, here + ".id", $"expected a ball id of {set.Name}'s set ({set.Describe()})");
            }
            if (!b.TryGetProperty("position", out var p) || p.ValueKind != JsonValueKind.Array || p.GetArrayLength() != 2
                || p[0].ValueKind != JsonValueKind.Number || p[1].ValueKind != JsonValueKind.Number)
            {
                throw new SceneException(file, here + ".position", "expected [x, y] (m)");
            }
            if (list.Exists(x => x.Item1 == ball))
            {
                throw new SceneException(file, here + ".id", $"ball \"{id.GetString()}\" is listed twice");
            }
            list.Add((ball, new Vec3(p[0].GetDouble(), p[1].GetDouble(), setup.BallRadius)));
        }
        return new Balls.BallLayout(list);
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
    public static int Replay(GameRecord record, out Match replayed)
    {
        var report = Verify(record, out replayed);
        return report.FirstDifference?.Shot ?? -1;
    }

    /// <summary>
    /// <c>replay --verify</c> (scene-format.md): plays a record's shots again through the same
    /// physics and referee, and compares each shot's ruling, field by field, and its balls at rest
    /// with the recorded ones, up to the first difference.
    /// </summary>
    public static ReplayReport Verify(GameRecord record, out Match replayed)
    {
        ArgumentNullException.ThrowIfNull(record);
        var session = new Session(record.Setup, Seat.Of(record.Setup.Start.Players, SeatKind.Script));
        replayed = session.Game;
        for (int k = 0; k < record.Shots.Count; k++)
        {
            MatchShot played;
            try
            {
                // With the choice the record took (none found leaves the options pending).
                int shot = k;
                played = session.Play(record.Shots[k], SeatKind.Script, judged => record.ChoiceAfter(shot, judged.Ruling));
            }
            catch (Exception e) when (e is InvalidOperationException or ArgumentException)
            {
                // The replayed game went elsewhere: the shot cannot be played as recorded (the game
                // is over, no ball in hand for its placement, an option to choose that none fits).
                return new ReplayReport(record.Shots.Count, k, new ReplayDifference(k, "shot", "\"played\"", JsonString(e.Message)));
            }
            if (FirstDifference(record.Rulings[k], GameBlockWriter.RulingToUtf8(played.Ruling)) is { } field)
            {
                return new ReplayReport(record.Shots.Count, k, new ReplayDifference(k, "ruling." + field.Name, field.Recorded, field.Replayed));
            }
            if (record.Balls[k] is { } recordedBalls)
            {
                string replayedBalls = BallsJson(played.After, record.Setup.Ruleset.BallSet);
                if (Compact(recordedBalls) != replayedBalls)
                {
                    return new ReplayReport(record.Shots.Count, k, new ReplayDifference(k, "balls", Compact(recordedBalls), replayedBalls));
                }
            }
        }
        return new ReplayReport(record.Shots.Count, record.Shots.Count, null);
    }

    private static (string Name, string Recorded, string Replayed)? FirstDifference(string recorded, byte[] replayed)
    {
        using var a = JsonDocument.Parse(recorded);
        using var b = JsonDocument.Parse(replayed);
        var names = a.RootElement.EnumerateObject().Select(p => p.Name).Union(b.RootElement.EnumerateObject().Select(p => p.Name));
        foreach (string name in names)
        {
            string x = a.RootElement.TryGetProperty(name, out var pa) ? Compact(pa.GetRawText()) : "null";
            string y = b.RootElement.TryGetProperty(name, out var pb) ? Compact(pb.GetRawText()) : "null";
            if (x != y)
            {
                return (name, x, y);
            }
        }
        return null;
    }

    private static string BallsJson(IEnumerable<(Balls.BallId Id, Vec3 Position)> balls, Balls.BallSet ballSet)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            WriteBallsValue(w, balls, ballSet);
        }
        return System.Text.Encoding.UTF8.GetString(stream.ToArray());
    }

    // JSON without insignificant white space, numbers as written.
    private static string Compact(string json)
    {
        using var doc = JsonDocument.Parse(json);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            doc.RootElement.WriteTo(w);
        }
        return System.Text.Encoding.UTF8.GetString(stream.ToArray());
    }

    private static string JsonString(string text) => JsonSerializer.Serialize(text);
}
