using System.Text.Json;
using Billiards.Core.Ai;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Cli;

/// <summary>
/// Writes a played game as a "billiards-game/1" record (scene-format.md): the table, the physics,
/// the rack, then per shot the game block before it, the placement, the call, the shot struck and
/// the ruling. The shot is the one the physics ran (the player's error included), so replaying the
/// record reproduces every ruling; the planned shot is kept beside it.
/// </summary>
public static class GameRecordWriter
{
    /// <summary>The format name.</summary>
    public const string Format = "billiards-game/1";

    /// <summary>The record on one line of UTF-8 JSON.</summary>
    public static byte[] ToUtf8(PlayedGame game, TableSpec table, PhysicsParams physics)
    {
        ArgumentNullException.ThrowIfNull(game);
        ArgumentNullException.ThrowIfNull(table);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            w.WriteStartObject();
            w.WriteString("format", Format);
            w.WriteStartObject("table");
            w.WriteString("preset", table.Preset);
            w.WriteEndObject();
            w.WriteStartObject("physics");
            w.WriteString("model", ModelRegistry.Standard.Name);
            w.WriteString("integrator", Integrators.Event);
            w.WriteNumber("dt", PhysicsConfig.DefaultDt);
            w.WriteEndObject();
            w.WriteStartObject("rack");
            w.WriteString("game", game.Rules.ToName());
            w.WriteNumber("seed", game.Racks[0]);
            w.WriteEndObject();
            w.WriteStartArray("racks");
            foreach (int seed in game.Racks)
            {
                w.WriteNumberValue(seed);
            }
            w.WriteEndArray();
            w.WriteString("rules", game.Rules.ToName());
            w.WriteStartArray("levels");
            w.WriteNumberValue(game.Levels.First);
            w.WriteNumberValue(game.Levels.Second);
            w.WriteEndArray();
            if (game.Winner is { } winner)
            {
                w.WriteNumber("winner", winner);
            }
            else
            {
                w.WriteNull("winner");
            }
            w.WriteStartArray("shots");
            foreach (var s in game.Shots)
            {
                w.WriteStartObject();
                w.WritePropertyName("game");
                GameBlockWriter.WriteGame(w, s.Before);
                if (s.Place is { } p)
                {
                    WritePoint(w, "place", p);
                }
                else
                {
                    w.WriteNull("place");
                }
                WriteCall(w, s.Before.Call);
                WriteShot(w, "shot", s.Executed);
                WriteShot(w, "planned", s.Planned);
                w.WritePropertyName("ruling");
                GameBlockWriter.WriteRuling(w, s.Ruling);
                if (s.Option is { } option)
                {
                    w.WriteString("option", option.ToName());
                }
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteEndObject();
        }
        return stream.ToArray();
    }

    /// <summary>A cue-ball placement as <c>[x, y]</c> (m), or null.</summary>
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

    /// <summary>A shot as scenes write it: speed, aim, tip, elevation.</summary>
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

    /// <summary>The call: {"ball", "pocket"}, {"safety": true} or null.</summary>
    public static void WriteCall(Utf8JsonWriter w, Call? call)
    {
        ArgumentNullException.ThrowIfNull(w);
        if (call is null)
        {
            w.WriteNull("call");
        }
        else
        {
            GameBlockWriter.WriteCall(w, "call", call);
        }
    }

    private static void WritePoint(Utf8JsonWriter w, string name, Vec3 p)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(p.X);
        w.WriteNumberValue(p.Y);
        w.WriteEndArray();
    }
}
