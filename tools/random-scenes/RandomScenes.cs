using System.Text;
using System.Text.Json;
using Billiards.Core.Ai;

namespace Billiards.Tools;

/// <summary>
/// Seeded random scenes (billiards-scene/1, one per line) for batch runs and their tests: a mix of
/// racked breaks and scattered balls on the three pool tables, the standard model's exact and
/// event integrators (some with other cushion and ball-ball models) and the thesis model, random cue strikes, and some scenes with a game block
/// (a break to judge). Scene k of a seed depends only on the seed and k. The elevated mix is
/// issue 40's strokes instead (<see cref="WriteElevated"/>).
/// </summary>
internal static class RandomScenes
{
    /// <summary>The default mix: racks and scatters on the pool tables, cues up to 15 deg.</summary>
    public const string StandardMix = "standard";

    /// <summary>Elevated strokes: racked 8- and 9-ball tables on every preset, the cue ball anywhere on the bed, 0.1-12 m/s, tip within 0.5 R, elevation 0-80 deg.</summary>
    public const string ElevatedMix = "elevated";

    private static readonly string[] ElevatedTables = ["pool-9ft", "pool-8ft", "pool-7ft", "snooker-12ft", "thesis", "pocketless"];

    private static readonly string[] Tables = ["pool-9ft", "pool-8ft", "pool-7ft"];
    private static readonly string[] CushionModels = ["han-2005", "mathavan-2010", "stronge-compliant"];
    private static readonly string[] BallModels = ["frictional-inelastic", "frictional-mathavan"];

    /// <summary>Scene <paramref name="k"/> of <paramref name="seed"/> as one UTF-8 line with its line break.</summary>
    public static byte[] Line(ulong seed, int k, string mix = StandardMix)
    {
        var rng = new PlannerRandom(PlannerRandom.Derive(seed, k));
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            if (mix == ElevatedMix)
            {
                WriteElevated(w, rng, k);
            }
            else
            {
                Write(w, rng, k);
            }
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }

    /// <summary><paramref name="count"/> scenes of <paramref name="seed"/>, one per line.</summary>
    public static string Lines(ulong seed, int count, string mix = StandardMix)
    {
        var text = new StringBuilder();
        for (int k = 0; k < count; k++)
        {
            text.Append(Encoding.UTF8.GetString(Line(seed, k, mix)));
        }
        return text.ToString();
    }

    // Issue 40's strokes through the scene format: the standard model (exact or event), a racked
    // 8- or 9-ball table on any preset, the cue ball anywhere on the bed clear of the rack.
    private static void WriteElevated(Utf8JsonWriter w, PlannerRandom rng, int k)
    {
        string preset = ElevatedTables[(int)(rng.NextDouble() * ElevatedTables.Length)];
        var table = Billiards.Core.Table.TableSpec.FromPreset(preset);
        double r = Billiards.Core.Physics.PhysicsParams.DefaultRadius;
        var rackGame = rng.NextDouble() < 0.5 ? Billiards.Core.Setup.RackGame.EightBall : Billiards.Core.Setup.RackGame.NineBall;
        int rackSeed = (int)(rng.NextUInt64() % 1_000_000);
        var rack = Billiards.Core.Setup.Initializer.Rack(new Billiards.Core.Setup.RackSpec(rackGame, rackSeed), table, r);
        double x, y;
        do
        {
            // Four decimals, as written, and at least a millimetre clear of every racked ball.
            x = Round((2 * rng.NextDouble() - 1) * (table.HalfLength - r - 1e-3));
            y = Round((2 * rng.NextDouble() - 1) * (table.HalfWidth - r - 1e-3));
        }
        while (rack.Any(b => Math.Sqrt((b.Position.X - x) * (b.Position.X - x) + (b.Position.Y - y) * (b.Position.Y - y)) < 2 * r + 1e-3));
        w.WriteStartObject();
        w.WriteString("format", "billiards-scene/1");
        w.WriteString("name", $"random elevated scene {k}");
        w.WriteStartObject("table");
        w.WriteString("preset", preset);
        w.WriteEndObject();
        w.WriteStartObject("physics");
        w.WriteString("model", "standard");
        w.WriteString("integrator", rng.NextDouble() < 0.5 ? "exact" : "event");
        w.WriteEndObject();
        w.WriteStartObject("rack");
        w.WriteString("game", rackGame == Billiards.Core.Setup.RackGame.EightBall ? "eight-ball" : "nine-ball");
        w.WriteNumber("seed", rackSeed);
        w.WriteEndObject();
        w.WriteStartArray("balls");
        Ball(w, "cue", x, y);
        w.WriteEndArray();
        w.WriteStartObject("shot");
        w.WriteNumber("speed", Round(0.1 + 11.9 * rng.NextDouble()));
        w.WriteNumber("aim_deg", Round(360 * rng.NextDouble() - 180));
        double tip = 0.5 * Math.Sqrt(rng.NextDouble()), angle = 2 * Math.PI * rng.NextDouble();
        w.WriteStartArray("tip");
        w.WriteNumberValue(Round(tip * Math.Cos(angle)));
        w.WriteNumberValue(Round(tip * Math.Sin(angle)));
        w.WriteEndArray();
        w.WriteNumber("elevation_deg", Round(80 * rng.NextDouble()));
        w.WriteEndObject();
        w.WriteEndObject();
    }

    private static void Write(Utf8JsonWriter w, PlannerRandom rng, int k)
    {
        double kind = rng.NextDouble();
        bool thesis = kind < 0.15;
        bool racked = thesis || rng.NextDouble() < 0.6;
        string game = rng.NextDouble() < 0.5 ? "eight-ball" : "nine-ball";
        w.WriteStartObject();
        w.WriteString("format", "billiards-scene/1");
        w.WriteString("name", $"random scene {k}");
        w.WriteStartObject("table");
        w.WriteString("preset", thesis ? "thesis" : Tables[(int)(rng.NextDouble() * Tables.Length)]);
        w.WriteEndObject();
        w.WriteStartObject("physics");
        if (thesis)
        {
            w.WriteString("model", "thesis");
        }
        else
        {
            w.WriteString("model", "standard");
            w.WriteString("integrator", kind < 0.3 ? "event" : "exact");
            if (rng.NextDouble() < 0.3)
            {
                w.WriteStartObject("models");
                w.WriteString("ball_cushion", CushionModels[(int)(rng.NextDouble() * CushionModels.Length)]);
                w.WriteString("ball_ball", BallModels[(int)(rng.NextDouble() * BallModels.Length)]);
                w.WriteEndObject();
            }
        }
        w.WriteEndObject();
        if (racked)
        {
            w.WriteStartObject("rack");
            w.WriteString("game", game);
            w.WriteNumber("seed", (int)(rng.NextUInt64() % 1_000_000));
            w.WriteEndObject();
        }
        w.WriteStartArray("balls");
        // The cue ball in the head half (x < 0), the object balls in the foot half on a grid of
        // 12 cm cells (more than a ball's diameter), so no two balls ever overlap.
        Ball(w, "cue", -0.3 - 0.6 * rng.NextDouble(), 0.8 * rng.NextDouble() - 0.4);
        if (!racked)
        {
            int balls = 1 + (int)(rng.NextDouble() * 6);
            var cells = new HashSet<int>();
            for (int b = 1; b <= balls; b++)
            {
                int cell;
                do
                {
                    cell = (int)(rng.NextDouble() * 49);
                }
                while (!cells.Add(cell));
                Ball(w, b.ToString(System.Globalization.CultureInfo.InvariantCulture), 0.05 + 0.12 * (cell % 7), -0.36 + 0.12 * (cell / 7));
            }
        }
        w.WriteEndArray();
        w.WriteStartObject("shot");
        w.WriteNumber("speed", Round(0.5 + 9.5 * rng.NextDouble()));
        w.WriteNumber("aim_deg", Round(360 * rng.NextDouble() - 180));
        w.WriteStartArray("tip");
        w.WriteNumberValue(Round(0.8 * rng.NextDouble() - 0.4));
        w.WriteNumberValue(Round(0.8 * rng.NextDouble() - 0.4));
        w.WriteEndArray();
        w.WriteNumber("elevation_deg", thesis ? 0 : Round(15 * rng.NextDouble()));
        w.WriteEndObject();
        if (racked && !thesis && rng.NextDouble() < 0.3)
        {
            w.WriteStartObject("game");
            w.WriteString("rules", game);
            w.WriteNumber("shot", 0);
            w.WriteEndObject();
        }
        w.WriteEndObject();
    }

    private static void Ball(Utf8JsonWriter w, string id, double x, double y)
    {
        w.WriteStartObject();
        w.WriteString("id", id);
        w.WriteStartArray("position");
        w.WriteNumberValue(Round(x));
        w.WriteNumberValue(Round(y));
        w.WriteEndArray();
        w.WriteEndObject();
    }

    // Four decimals: the scenes read like hand-written ones.
    private static double Round(double x) => Math.Round(x, 4);
}
