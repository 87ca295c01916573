using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;

namespace Billiards.Core.Scenes;

/// <summary>Writes "billiards-result/1" JSON (scene-format.md).</summary>
public static class ResultWriter
{
    /// <summary>The format tag of a result.</summary>
    public const string Format = "billiards-result/1";

    /// <summary>
    /// The result as UTF-8 JSON bytes with round-trip numbers and a final line break: indented, or
    /// on one line (<paramref name="indented"/> false, one line of <c>simulate --batch</c>); the two
    /// differ only in white space.
    /// </summary>
    public static byte[] ToUtf8(RunOutcome outcome, bool indented = true)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = indented }))
        {
            Write(w, outcome);
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }

    /// <summary>
    /// Writes the result object (without the final line break) to <paramref name="w"/>, which
    /// decides the white space: what <see cref="ToUtf8"/> writes, for a caller that reuses its
    /// writer and buffer from one result to the next (simulate --batch).
    /// </summary>
    public static void Write(Utf8JsonWriter w, RunOutcome outcome)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(outcome);
        var sim = outcome.Simulation;
        w.WriteStartObject();
        w.WriteString("format", Format);
        w.WriteString("model", sim.Model);
        w.WriteString("integrator", sim.Integrator.Name);
        w.WriteNumber("dt", sim.Dt);
        if (sim.Models is { } models)
        {
            WriteModels(w, models);
        }
        w.WriteNumber("t_end", sim.Time);

        w.WriteStartArray("balls");
        var balls = sim.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            ref readonly var b = ref balls[i];
            w.WriteStartObject();
            w.WriteString("id", sim.BallSet.NameOf(sim.Ids[i]));
            WriteVector(w, "position", b.Position);
            WriteVector(w, "velocity", b.Velocity);
            WriteVector(w, "spin", b.Spin);
            w.WriteString("state", b.State.ToName());
            if (b.Pocket >= 0)
            {
                w.WriteString("pocket", sim.FeatureName(EventKind.BallPocket, b.Pocket));
            }
            else
            {
                w.WriteNull("pocket");
            }
            w.WriteEndObject();
        }
        w.WriteEndArray();

        w.WriteStartArray("events");
        foreach (ref readonly var e in sim.Events.AsSpan())
        {
            w.WriteStartObject();
            w.WriteNumber("t", e.Time);
            switch (e.Kind)
            {
                case EventKind.CueStrike or EventKind.Miscue:
                    w.WriteString("type", e.Kind == EventKind.CueStrike ? "cue-strike" : "miscue");
                    WriteIds(w, sim.BallSet, e.A);
                    w.WriteNumber("speed", e.Speed);
                    break;
                case EventKind.BallBall:
                    w.WriteString("type", "ball-ball");
                    WriteIds(w, sim.BallSet, e.A, e.B);
                    w.WriteNumber("speed", e.Speed);
                    break;
                case EventKind.BallCushion:
                    w.WriteString("type", "ball-cushion");
                    WriteIds(w, sim.BallSet, e.A);
                    w.WriteString("cushion", sim.FeatureName(e.Kind, e.Feature));
                    w.WriteNumber("speed", e.Speed);
                    break;
                case EventKind.BallPocket:
                    w.WriteString("type", "ball-pocket");
                    WriteIds(w, sim.BallSet, e.A);
                    w.WriteString("pocket", sim.FeatureName(e.Kind, e.Feature));
                    w.WriteNumber("speed", e.Speed);
                    break;
                case EventKind.BallAirborne or EventKind.BallTable or EventKind.BallOffTable:
                    w.WriteString("type", e.Kind switch
                    {
                        EventKind.BallAirborne => "ball-airborne",
                        EventKind.BallTable => "ball-table",
                        _ => "ball-off-table",
                    });
                    WriteIds(w, sim.BallSet, e.A);
                    w.WriteNumber("speed", e.Speed);
                    break;
            }
            w.WriteEndObject();
        }
        w.WriteEndArray();

        if (outcome.Samples.Count > 0)
        {
            w.WriteStartArray("samples");
            foreach (var s in outcome.Samples)
            {
                w.WriteStartObject();
                w.WriteNumber("t", s.Time);
                w.WriteStartObject("positions");
                for (int i = 0; i < s.Positions.Length; i++)
                {
                    w.WriteStartArray(sim.BallSet.NameOf(sim.Ids[i]));
                    w.WriteNumberValue(s.Positions[i].X);
                    w.WriteNumberValue(s.Positions[i].Y);
                    w.WriteNumberValue(s.Positions[i].Z);
                    w.WriteEndArray();
                }
                w.WriteEndObject();
                w.WriteEndObject();
            }
            w.WriteEndArray();
        }

        w.WriteStartObject("stats");
        w.WriteNumber("steps", sim.StepCount);
        w.WriteNumber("events", sim.Events.Count);
        w.WriteNumber("wall_ms", Math.Round(outcome.WallMilliseconds, 3));
        w.WriteBoolean("at_rest", outcome.AtRest);
        w.WriteString("stop", SimulationRunner.Name(outcome.Stop));
        w.WriteNumber("event_cap_hits", sim.EventCapHits);
        w.WriteNumber("truncated_impacts", sim.TruncatedImpacts);
        w.WriteEndObject();
        if (outcome.Ruling is { } ruling)
        {
            w.WritePropertyName("ruling");
            GameBlockWriter.WriteRuling(w, ruling);
        }
        w.WriteEndObject();
    }

    /// <summary>The <c>"models"</c> object of scenes, results and game records: the resolver of each interaction by name.</summary>
    public static void WriteModels(Utf8JsonWriter w, InteractionModels models)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(models);
        w.WriteStartObject("models");
        w.WriteString("ball_cushion", models.BallCushion.Name);
        w.WriteString("ball_ball", models.BallBall.Name);
        w.WriteEndObject();
    }

    private static void WriteIds(Utf8JsonWriter w, BallSet set, params ReadOnlySpan<BallId> ids)
    {
        w.WriteStartArray("balls");
        foreach (var id in ids)
        {
            w.WriteStringValue(set.NameOf(id));
        }
        w.WriteEndArray();
    }

    private static void WriteVector(Utf8JsonWriter w, string name, Vec3 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X);
        w.WriteNumberValue(v.Y);
        w.WriteNumberValue(v.Z);
        w.WriteEndArray();
    }
}
