using System.Globalization;
using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Scenes;

/// <summary>Command-line overrides of a scene's physics (simulate --model/--integrator/--dt).</summary>
public sealed record SceneOverrides(string? Model = null, string? Integrator = null, double? Dt = null);

/// <summary>
/// Reads and validates "billiards-scene/1" files (scene-format.md). Every problem becomes a
/// <see cref="SceneException"/> naming the file, the JSON path and what is wrong; unknown fields
/// and values are refused rather than ignored, so that a typo never silently changes a shot.
/// </summary>
/// <example>
/// Load a scene, run its shot to rest and read what ended the run:
/// <code language="csharp">
/// Scene scene = SceneLoader.Load("assets/scenes/eight-ball-break.json");
/// RunOutcome outcome = SimulationRunner.Run(scene, new RunOptions());
/// Console.WriteLine($"{outcome.Simulation.Events.Count} events, stopped by {outcome.Stop} at {outcome.Simulation.Time:0.000} s");
/// </code>
/// A scene in a string is read by <see cref="Parse"/>, with a name for its error messages:
/// <c>SceneLoader.Parse(json, "shot.json")</c>. A bad scene throws one <see cref="SceneException"/>
/// whose message names the file, the JSON path and the problem.
/// </example>
public static class SceneLoader
{
    /// <summary>The format tag of a scene file.</summary>
    public const string Format = "billiards-scene/1";

    /// <summary>Smallest and largest accepted fixed step (s).</summary>
    public const double MinDt = 1e-6, MaxDt = 0.1;

    /// <summary>Largest accepted cue speed (m/s); a hard break is about 12.</summary>
    public const double MaxShotSpeed = 20;

    /// <summary>Loads a scene file.</summary>
    /// <exception cref="SceneException">When the file is missing, malformed or invalid.</exception>
    public static Scene Load(string path, SceneOverrides? overrides = null)
    {
        string text;
        try
        {
            text = File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new SceneException(path, "$", $"cannot read the file ({e.Message})");
        }
        return Parse(text, path, overrides);
    }

    /// <summary>Parses scene JSON; <paramref name="path"/> only names the source in errors.</summary>
    /// <exception cref="SceneException">When the text is malformed or invalid.</exception>
    public static Scene Parse(string json, string path, SceneOverrides? overrides = null)
    {
        using var doc = ParseJson(json, path);
        return new Reader(path).ReadScene(doc.RootElement, overrides ?? new SceneOverrides());
    }

    /// <summary>
    /// Parses the text of any of the program's JSON files (scenes, game records, self-play
    /// summaries), strictly; malformed text is one <see cref="SceneException"/> at <c>$</c> with
    /// the line and byte of the problem.
    /// </summary>
    internal static JsonDocument ParseJson(string json, string path)
    {
        try
        {
            return JsonDocument.Parse(json, new JsonDocumentOptions { AllowTrailingCommas = false, CommentHandling = JsonCommentHandling.Disallow });
        }
        catch (JsonException e)
        {
            throw new SceneException(path, "$", $"not valid JSON: line {e.LineNumber + 1}, byte {e.BytePositionInLine + 1}: {FirstSentence(e.Message)}");
        }
    }

    /// <summary>Reads a scene object nested in another file (a drill's position); <paramref name="file"/> names that file in errors.</summary>
    internal static Scene ReadScene(JsonElement e, string file) => new Reader(file).ReadScene(e, new SceneOverrides());

    /// <summary>Reads a shot object (the scene's <c>shot</c> block) found at <paramref name="path"/> of another file.</summary>
    internal static ShotSpec ReadShot(JsonElement e, string file, string path) => new Reader(file).ReadShot(e, path);

    private static string FirstSentence(string message)
    {
        int end = message.IndexOf(". ", StringComparison.Ordinal);
        return end < 0 ? message.TrimEnd('.') : message[..end];
    }

    private sealed class Reader(string file)
    {
        private SceneException Error(string jsonPath, string problem) => new(file, jsonPath, problem);

        public Scene ReadScene(JsonElement root, SceneOverrides overrides)
        {
            var fields = Object(root, "$", "format", "name", "table", "physics", "rack", "balls", "shot", "rules", "game");
            if (!fields.TryGetValue("format", out var format))
            {
                throw Error("$", $"missing \"format\" (expected \"{Format}\")");
            }
            string formatText = String(format, "$.format");
            if (formatText != Format)
            {
                throw Error("$.format", $"unknown format \"{formatText}\" (expected \"{Format}\")");
            }
            string? name = fields.TryGetValue("name", out var n) ? String(n, "$.name") : null;

            var set = SceneBallSet(fields);
            var physics = fields.TryGetValue("physics", out var p) ? ReadPhysics(p, overrides, set) : ApplyOverrides(PhysicsConfig.Default with { Params = set.DefaultParams }, overrides, "$");
            var table = fields.TryGetValue("table", out var t)
                ? ReadTable(t)
                : TableSpec.FromPreset(physics.Model.DefaultTablePreset);
            double radius = physics.Model.BallRadius(physics.Params);
            if (physics.Model.RadiusProblem(table, radius) is { } radiusProblem)
            {
                throw Error("$.physics.params.R", radiusProblem);
            }

            // The game names the ball set; the game block is read in full below, once the balls are.
            var cueBall = set.CueBalls[0];
            RackSpec? rack = fields.TryGetValue("rack", out var r) ? ReadRack(r, fields) : null;
            var balls = new SortedDictionary<int, (BallSetup Ball, string Path)>();
            if (rack is not null)
            {
                foreach (var (id, position) in Initializer.Rack(rack, table, radius))
                {
                    balls[id.Value] = (new BallSetup(id, position, Vec3.Zero, Vec3.Zero), "$.rack");
                }
                if (!balls.ContainsKey(cueBall.Value))
                {
                    balls[cueBall.Value] = (new BallSetup(cueBall, Initializer.CueStart(rack.Game, table, radius), Vec3.Zero, Vec3.Zero), "$.rack");
                }
            }
            if (fields.TryGetValue("balls", out var b))
            {
                var explicitIds = new HashSet<int>();
                int i = 0;
                foreach (var item in Array(b, "$.balls"))
                {
                    string itemPath = $"$.balls[{i++}]";
                    var ball = ReadBall(item, itemPath, set, radius, physics.Model.HasFlight);
                    if (!explicitIds.Add(ball.Id.Value))
                    {
                        throw Error(itemPath + ".id", $"ball \"{ball.Id}\" appears twice");
                    }
                    balls[ball.Id.Value] = (ball, itemPath);
                }
            }
            var list = balls.Values.ToList();
            ValidatePlacement(list, table, radius);

            ShotSpec? shot = fields.TryGetValue("shot", out var s) ? ReadShot(s) : null;
            string? rules = fields.TryGetValue("rules", out var ru) ? OneOf(ru, "$.rules", [.. Rules.RuleNames.GameNames]) : null;

            // A game block without a shot is a position to play (suggest); a run refuses it (SimulationRunner).
            var game = fields.TryGetValue("game", out var gm) ? GameBlockReader.Read(gm, table.Pockets, file) : null;
            var scene = new Scene(file, name, table, physics, rack, list.Select(x => x.Ball).ToList(), shot, rules) { Game = game, BallSet = set };
            if (shot is not null && !balls.ContainsKey(scene.CueBall.Value))
            {
                throw Error("$.shot", $"a shot needs a cue ball (\"{set.NameOf(scene.CueBall)}\"), and the scene has none");
            }
            return scene;
        }

        // The balls a scene is played with, for its ball ids and the default radius and mass: its
        // game's set (SceneGame.Of: the game block's rules, else "rules"), else that of the game
        // its rack or table belongs to (SceneGame.BallSetOf); a bad name is refused where the field is read.
        // Read before the fields are validated, which happens as each is read.
        private static BallSet SceneBallSet(Dictionary<string, JsonElement> fields)
        {
            string? game = null;
            if (fields.TryGetValue("game", out var g) && g.ValueKind == JsonValueKind.Object && g.TryGetProperty("rules", out var gr) && gr.ValueKind == JsonValueKind.String)
            {
                game = gr.GetString();
            }
            string? rulesField = fields.TryGetValue("rules", out var ru) && ru.ValueKind == JsonValueKind.String ? ru.GetString() : null;
            if (SceneGame.Of(game, rulesField) is { } rules)
            {
                return Rules.Ruleset.For(rules).BallSet;
            }
            static string? Text(Dictionary<string, JsonElement> f, string block, string property) =>
                f.TryGetValue(block, out var e) && e.ValueKind == JsonValueKind.Object && e.TryGetProperty(property, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;
            return SceneGame.BallSetOf(Text(fields, "rack", "game"), Text(fields, "table", "preset"));
        }

        private void ValidatePlacement(List<(BallSetup Ball, string Path)> balls, TableSpec table, double radius)
        {
            if (Placement.Check(table, radius, balls.ConvertAll(b => (b.Ball.Id, b.Ball.Position)), out int culprit) is { } problem)
            {
                throw Error(balls[culprit].Path, problem);
            }
        }

        private TableSpec ReadTable(JsonElement e)
        {
            var f = Object(e, "$.table", "preset", "length", "width", "cushion_height", "rail_height");
            if (!f.TryGetValue("preset", out var preset))
            {
                throw Error("$.table", "missing \"preset\"");
            }
            var table = TableSpec.FromPreset(OneOf(preset, "$.table.preset", [.. TableSpec.PresetNames]));
            if (f.TryGetValue("length", out var l))
            {
                table = table with { Length = Number(l, "$.table.length", 0.5, 10) };
            }
            if (f.TryGetValue("width", out var w))
            {
                table = table with { Width = Number(w, "$.table.width", 0.25, 5) };
            }
            if (f.TryGetValue("cushion_height", out var h))
            {
                table = table with { CushionHeight = Number(h, "$.table.cushion_height", 0.0, 0.1) };
            }
            if (f.TryGetValue("rail_height", out var rh))
            {
                table = table with { RailHeight = Number(rh, "$.table.rail_height", 0.0, 0.5) };
            }
            else
            {
                // A higher cushion than the preset's raises the rails' top with it.
                table = table with { RailHeight = Math.Max(table.RailHeight, table.CushionHeight) };
            }
            if (table.RailHeight < table.CushionHeight)
            {
                throw Error("$.table.rail_height", string.Create(CultureInfo.InvariantCulture,
                    $"the top of the rails ({table.RailHeight} m) is below the cushion's contact height ({table.CushionHeight} m)"));
            }
            return table;
        }

        private PhysicsConfig ReadPhysics(JsonElement e, SceneOverrides overrides, BallSet set)
        {
            var f = Object(e, "$.physics", "model", "integrator", "dt", "params", "models");
            var config = PhysicsConfig.Default with { Params = set.DefaultParams };
            if (f.TryGetValue("model", out var m))
            {
                var model = ModelRegistry.Get(OneOf(m, "$.physics.model", [.. ModelRegistry.Names]));
                config = config with { Model = model, Integrator = model.Integrators[0] };
            }
            if (f.TryGetValue("integrator", out var i))
            {
                var model = ModelRegistry.Find(overrides.Model) ?? config.Model;
                string name = OneOf(i, "$.physics.integrator", [.. ModelRegistry.IntegratorNames(model)]);
                config = config with { Integrator = ModelRegistry.FindIntegrator(model, name)! };
            }
            if (f.TryGetValue("dt", out var dt))
            {
                config = config with { Dt = Number(dt, "$.physics.dt", MinDt, MaxDt) };
            }
            if (f.TryGetValue("params", out var p))
            {
                config = config with { Params = ReadParams(p, set) };
            }
            config = ApplyOverrides(config, overrides, "$.physics");
            if (f.TryGetValue("models", out var ms))
            {
                if (!config.Model.TakesInteractionModels)
                {
                    throw Error("$.physics.models", $"model \"{config.Model}\" keeps its own collisions (\"models\" is for the standard model)");
                }
                config = config with { Models = ReadModels(ms) };
            }
            return config;
        }

        private InteractionModels ReadModels(JsonElement e)
        {
            var f = Object(e, "$.physics.models", "ball_cushion", "ball_ball");
            var models = InteractionModels.Default;
            if (f.TryGetValue("ball_cushion", out var c))
            {
                models = models with { BallCushion = ModelRegistry.FindBallCushion(OneOf(c, "$.physics.models.ball_cushion", [.. ModelRegistry.BallCushionNames]))! };
            }
            if (f.TryGetValue("ball_ball", out var b))
            {
                models = models with { BallBall = ModelRegistry.FindBallBall(OneOf(b, "$.physics.models.ball_ball", [.. ModelRegistry.BallBallNames]))! };
            }
            return models;
        }

        private PhysicsConfig ApplyOverrides(PhysicsConfig config, SceneOverrides o, string path)
        {
            if (o.Model is not null)
            {
                var model = ModelRegistry.Find(o.Model)
                    ?? throw new SceneException("--model", "$", $"unknown model \"{o.Model}\" (expected one of {ModelRegistry.Quote(ModelRegistry.Names)})");
                config = config with { Model = model };
                if (!model.Integrators.Contains(config.Integrator))
                {
                    config = config with { Integrator = model.Integrators[0] };
                }
            }
            if (o.Integrator is not null)
            {
                var integrator = ModelRegistry.FindIntegrator(config.Model, o.Integrator)
                    ?? throw new SceneException("--integrator", "$", $"integrator \"{o.Integrator}\" is not available for model \"{config.Model}\" (expected one of {ModelRegistry.Quote(ModelRegistry.IntegratorNames(config.Model))})");
                config = config with { Integrator = integrator };
            }
            if (o.Dt is { } dt)
            {
                if (!double.IsFinite(dt) || dt < MinDt || dt > MaxDt)
                {
                    throw new SceneException("--dt", "$", string.Create(CultureInfo.InvariantCulture, $"dt {dt} is out of range [{MinDt}, {MaxDt}]"));
                }
                config = config with { Dt = dt };
            }
            _ = path;
            return config;
        }

        private PhysicsParams ReadParams(JsonElement e, BallSet set)
        {
            var f = Object(e, "$.physics.params", [.. PhysicsParams.Symbols]);
            var p = set.DefaultParams;
            var preset = p;
            double Get(string key, double min, double max, double fallback) =>
                f.TryGetValue(key, out var v) ? Number(v, $"$.physics.params.{key}", min, max) : fallback;

            p = p with
            {
                M = Get("m", 0.01, 10, p.M),
                R = Get("R", 0.005, 0.1, p.R),
                MuS = Get("mu_s", 0, 2, p.MuS),
                MuR = Get("mu_r", 0, 1, p.MuR),
                EB = Get("e_b", 0, 1, p.EB),
                FC = Get("f_c", 0, 2, p.FC),
                ET = Get("e_t", 0, 1, p.ET),
                G = Get("g", 0.1, 100, p.G),
                CueMass = Get("M", 0.01, 10, p.CueMass),
                ETip = Get("e_tip", 0, 1, p.ETip),
                MiscueLimit = Get("miscue_limit", 0, 1, p.MiscueLimit),
            };
            // mu_sp and m_e default relative to R and m, so they follow an overridden R or m (the
            // preset's spin-down rate and its ratio m / m_e stay).
            p = p with
            {
                MuSp = Get("mu_sp", 0, 1, preset.MuSp * p.R / preset.R),
                CueEndMass = Get("m_e", 1e-4, 10, preset.CueEndMass * p.M / preset.M),
            };
            if (f.TryGetValue("tip_frame", out var frame))
            {
                p = p with { Tip = OneOf(frame, "$.physics.params.tip_frame", "cue", "face") == "face" ? TipFrame.Face : TipFrame.Cue };
            }
            if (f.TryGetValue("e_c", out var ec))
            {
                if (ec.ValueKind == JsonValueKind.String)
                {
                    OneOf(ec, "$.physics.params.e_c", "mathavan-2009");
                    p = p with { ECModel = CushionRestitution.Measured };
                }
                else
                {
                    p = p with { EC = Number(ec, "$.physics.params.e_c", 0, 1), ECModel = CushionRestitution.Constant };
                }
            }
            if (f.TryGetValue("omega_ratio", out var omega))
            {
                // Stronge's tangential and normal frequencies: the open interval (1, 2), where the
                // compliant contact sticks at most once (StrongeCompliant).
                double ratio = Number(omega, "$.physics.params.omega_ratio", 1, 2);
                if (ratio <= 1 || ratio >= 2)
                {
                    throw Error("$.physics.params.omega_ratio", string.Create(CultureInfo.InvariantCulture, $"{ratio} is out of range (1, 2): both ends excluded"));
                }
                p = p with { OmegaRatio = ratio };
            }
            if (f.TryGetValue("mu_b", out var mb))
            {
                if (mb.ValueKind == JsonValueKind.String)
                {
                    p = p with
                    {
                        MuBModel = OneOf(mb, "$.physics.params.mu_b", "alciatore", "alciatore-2014") == "alciatore"
                            ? BallBallFriction.Alciatore
                            : BallBallFriction.Measured,
                    };
                }
                else
                {
                    p = p with { MuB = Number(mb, "$.physics.params.mu_b", 0, 2), MuBModel = BallBallFriction.Constant };
                }
            }
            return p;
        }

        private RackSpec ReadRack(JsonElement e, Dictionary<string, JsonElement> fields)
        {
            var f = Object(e, "$.rack", "game", "seed");
            if (!f.TryGetValue("game", out var g))
            {
                throw Error("$.rack", "missing \"game\"");
            }
            var game = OneOf(g, "$.rack.game", "eight-ball", "nine-ball", "ten-ball", "straight-pool", "snooker", "three-cushion") switch
            {
                "three-cushion" => RackGame.ThreeCushion,
                "eight-ball" => RackGame.EightBall,
                "nine-ball" => RackGame.NineBall,
                "ten-ball" => RackGame.TenBall,
                "snooker" => RackGame.Snooker,
                _ => RackGame.StraightPool,
            };
            int seed = 0;
            if (f.TryGetValue("seed", out var s))
            {
                if (s.ValueKind != JsonValueKind.Number || !s.TryGetInt32(out seed))
                {
                    throw Error("$.rack.seed", "expected a whole number (a 32-bit integer)");
                }
            }
            return new RackSpec(game, seed, game == RackGame.ThreeCushion ? CaromBreaker(fields) : null);
        }

        // Three-cushion's breaker's ball: the game block's shooter's cue ball (its cue_balls, else
        // white and yellow); a bad block is refused where it is read in full.
        private static BallId CaromBreaker(Dictionary<string, JsonElement> fields)
        {
            if (!fields.TryGetValue("game", out var g) || g.ValueKind != JsonValueKind.Object)
            {
                return BallSet.White;
            }
            int shooter = g.TryGetProperty("shooter", out var s) && s.ValueKind == JsonValueKind.Number && s.TryGetInt32(out int i) && i is 0 or 1 ? i : 0;
            if (g.TryGetProperty("cue_balls", out var c) && c.ValueKind == JsonValueKind.Array && c.GetArrayLength() == 2
                && c[shooter].ValueKind == JsonValueKind.String && BallSet.Carom.TryParse(c[shooter].GetString(), out var ball) && BallSet.Carom.IsCueBall(ball))
            {
                return ball;
            }
            return shooter == 0 ? BallSet.White : BallSet.Yellow;
        }

        private BallSetup ReadBall(JsonElement e, string path, BallSet set, double radius, bool flight)
        {
            var f = Object(e, path, "id", "position", "velocity", "spin");
            if (!f.TryGetValue("id", out var idElement))
            {
                throw Error(path, "missing \"id\"");
            }
            string idText = String(idElement, path + ".id");
            if (!set.TryParse(idText, out var id))
            {
                throw Error(path + ".id", $"unknown ball id \"{idText}\" (expected {set.Describe()})");
            }
            if (!f.TryGetValue("position", out var pos))
            {
                throw Error(path, "missing \"position\"");
            }
            // [x, y] on the bed, or [x, y, z] (z >= R) and [vx, vy, vz] for a ball that may fly.
            var p = Numbers(pos, path + ".position", 2, 100, allowZ: true);
            var v = f.TryGetValue("velocity", out var ve) ? Numbers(ve, path + ".velocity", 2, MaxShotSpeed, allowZ: true) : [0, 0];
            var w = f.TryGetValue("spin", out var sp) ? Numbers(sp, path + ".spin", 3, 5000) : [0, 0, 0];
            double z = p.Length == 3 ? p[2] : radius;
            double vz = v.Length == 3 ? v[2] : 0;
            if ((p.Length == 3 || v.Length == 3) && !flight)
            {
                throw Error(p.Length == 3 ? path + ".position" : path + ".velocity",
                    "a third (vertical) component needs the standard model, whose balls can fly; give [x, y]");
            }
            if (z < radius)
            {
                throw Error(path + ".position[2]", string.Create(CultureInfo.InvariantCulture,
                    $"{z} puts the ball into the bed: its centre must be at least R = {radius} above it"));
            }
            return new BallSetup(id, new Vec3(p[0], p[1], z), new Vec3(v[0], v[1], vz), new Vec3(w[0], w[1], w[2]));
        }

        public ShotSpec ReadShot(JsonElement e, string at = "$.shot")
        {
            var f = Object(e, at, "speed", "aim_deg", "tip", "elevation_deg");
            if (!f.TryGetValue("speed", out var speed))
            {
                throw Error(at, "missing \"speed\"");
            }
            if (!f.TryGetValue("aim_deg", out var aim))
            {
                throw Error(at, "missing \"aim_deg\"");
            }
            double[] tip = f.TryGetValue("tip", out var t) ? Numbers(t, at + ".tip", 2, 1) : [0, 0];
            if (tip[0] * tip[0] + tip[1] * tip[1] >= 1)
            {
                throw Error(at + ".tip", "the tip offset must lie inside the ball (side^2 + height^2 < 1)");
            }
            double elevation = f.TryGetValue("elevation_deg", out var el) ? Number(el, at + ".elevation_deg", 0, 90) : 0;
            return new ShotSpec(Number(speed, at + ".speed", 0, MaxShotSpeed), Number(aim, at + ".aim_deg", -360, 360), tip[0], tip[1], elevation);
        }

        private Dictionary<string, JsonElement> Object(JsonElement e, string path, params string[] allowed)
        {
            if (e.ValueKind != JsonValueKind.Object)
            {
                throw Error(path, $"expected an object, found {Describe(e)}");
            }
            var result = new Dictionary<string, JsonElement>(StringComparer.Ordinal);
            foreach (var property in e.EnumerateObject())
            {
                if (!allowed.Contains(property.Name))
                {
                    throw Error($"{path}.{property.Name}", $"unknown field (expected one of {Quote(allowed)})");
                }
                if (!result.TryAdd(property.Name, property.Value))
                {
                    throw Error($"{path}.{property.Name}", "field appears twice");
                }
            }
            return result;
        }

        private JsonElement.ArrayEnumerator Array(JsonElement e, string path) =>
            e.ValueKind == JsonValueKind.Array ? e.EnumerateArray() : throw Error(path, $"expected an array, found {Describe(e)}");

        private string String(JsonElement e, string path) =>
            e.ValueKind == JsonValueKind.String ? e.GetString()! : throw Error(path, $"expected a string, found {Describe(e)}");

        private string OneOf(JsonElement e, string path, params string[] values)
        {
            string s = String(e, path);
            return values.Contains(s) ? s : throw Error(path, $"unknown value \"{s}\" (expected one of {Quote(values)})");
        }

        private double Number(JsonElement e, string path, double min, double max)
        {
            if (e.ValueKind != JsonValueKind.Number)
            {
                throw Error(path, $"expected a number, found {Describe(e)}");
            }
            double x = e.GetDouble();
            if (!double.IsFinite(x))
            {
                throw Error(path, "the number is not finite");
            }
            if (x < min || x > max)
            {
                throw Error(path, string.Create(CultureInfo.InvariantCulture, $"{x} is out of range [{min}, {max}]"));
            }
            return x;
        }

        private double[] Numbers(JsonElement e, string path, int count, double maxAbs, bool allowZ = false)
        {
            if (e.ValueKind != JsonValueKind.Array || (e.GetArrayLength() != count && !(allowZ && e.GetArrayLength() == count + 1)))
            {
                string expected = allowZ ? $"{count} or {count + 1}" : $"{count}";
                throw Error(path, $"expected an array of {expected} numbers, found {Describe(e)}");
            }
            var result = new double[e.GetArrayLength()];
            int i = 0;
            foreach (var x in e.EnumerateArray())
            {
                result[i] = Number(x, $"{path}[{i}]", -maxAbs, maxAbs);
                i++;
            }
            return result;
        }

        private static string Describe(JsonElement e) => e.ValueKind switch
        {
            JsonValueKind.Array => $"an array of {e.GetArrayLength()}",
            JsonValueKind.Object => "an object",
            JsonValueKind.String => $"the string \"{e.GetString()}\"",
            JsonValueKind.Number => $"the number {e.GetRawText()}",
            JsonValueKind.True or JsonValueKind.False => e.GetRawText(),
            JsonValueKind.Null => "null",
            _ => e.ValueKind.ToString(),
        };
    }

    private static string Quote(IEnumerable<string> values) => string.Join(", ", values.Select(v => $"\"{v}\""));
}
