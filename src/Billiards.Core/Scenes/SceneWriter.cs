using System.Text.Json;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Scenes;

/// <summary>
/// Writes a scene as "billiards-scene/1" JSON (scene-format.md): what practice saves, and what
/// <c>simulate</c>, <c>render</c> and <c>play</c> read back. Every number is written round-trip, and
/// the table and every physics parameter explicitly, so that the scene read back makes the same
/// simulation bit for bit whatever the defaults of a later version.
/// </summary>
public static class SceneWriter
{
    /// <summary>The scene as indented UTF-8 JSON with a final line break; no rack (its balls are written as balls) and no game block.</summary>
    public static byte[] ToUtf8(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            Write(w, scene);
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }

    private static void Write(Utf8JsonWriter w, Scene scene)
    {
        w.WriteStartObject();
        w.WriteString("format", SceneLoader.Format);
        if (scene.Name is { } name)
        {
            w.WriteString("name", name);
        }
        var table = scene.Table;
        w.WriteStartObject("table");
        w.WriteString("preset", table.Preset);
        w.WriteNumber("length", table.Length);
        w.WriteNumber("width", table.Width);
        w.WriteNumber("cushion_height", table.CushionHeight);
        w.WriteNumber("rail_height", table.RailHeight);
        w.WriteEndObject();
        GameRecordFile.WritePhysics(w, scene.Physics);
        w.WriteStartArray("balls");
        double r = scene.BallRadius;
        foreach (var ball in scene.Balls)
        {
            w.WriteStartObject();
            w.WriteString("id", ball.Id.ToString());
            // On the bed a position is [x, y] (z = R is implied); a ball in the air keeps its height.
            bool flying = ball.Position.Z != r || ball.Velocity.Z != 0;
            Numbers(w, "position", flying ? [ball.Position.X, ball.Position.Y, ball.Position.Z] : [ball.Position.X, ball.Position.Y]);
            if (ball.Velocity != Vec3.Zero)
            {
                Numbers(w, "velocity", flying ? [ball.Velocity.X, ball.Velocity.Y, ball.Velocity.Z] : [ball.Velocity.X, ball.Velocity.Y]);
            }
            if (ball.Spin != Vec3.Zero)
            {
                Numbers(w, "spin", [ball.Spin.X, ball.Spin.Y, ball.Spin.Z]);
            }
            w.WriteEndObject();
        }
        w.WriteEndArray();
        if (scene.Shot is { } shot)
        {
            GameRecordFile.WriteShot(w, "shot", shot);
        }
        if (scene.Rules is { } rules)
        {
            w.WriteString("rules", rules);
        }
        w.WriteEndObject();
    }

    private static void Numbers(Utf8JsonWriter w, string name, double[] values)
    {
        w.WriteStartArray(name);
        foreach (double v in values)
        {
            w.WriteNumberValue(v);
        }
        w.WriteEndArray();
    }
}
