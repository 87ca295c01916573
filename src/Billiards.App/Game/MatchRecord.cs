using System.Text;
using System.Text.Json;
using Billiards.Core.Scenes;

namespace Billiards.App.Game;

/// <summary>
/// <c>play --record FILE</c>: the match as it stood when the game closed, for tests and bug
/// reports: every shot struck (the game block before it with its call, the cue ball's placement by
/// hand, the strike), every ruling the referee gave (in the scene format's ruling shape), the state
/// of the game, the winner, and the HUD's lines of the last frame.
/// </summary>
public static class MatchRecord
{
    /// <summary>The record's format tag.</summary>
    public const string Format = "billiards-play-record/1";

    /// <summary>The record as UTF-8 JSON.</summary>
    public static byte[] ToJson(MatchNode match, IReadOnlyList<string> hudLines)
    {
        ArgumentNullException.ThrowIfNull(match);
        ArgumentNullException.ThrowIfNull(hudLines);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("format", Format);
            w.WriteStartArray("players");
            foreach (var p in match.Players)
            {
                w.WriteStringValue(p.IsHuman ? "human" : $"computer:{p.ComputerLevel}");
            }
            w.WriteEndArray();
            w.WritePropertyName("game");
            GameBlockWriter.WriteGame(w, match.State);
            w.WriteBoolean("over", match.IsOver);
            if (match.Winner is int winner)
            {
                w.WriteNumber("winner", winner);
            }
            else
            {
                w.WriteNull("winner");
            }
            w.WriteStartArray("shots");
            foreach (var (before, shot) in match.Shots)
            {
                w.WriteStartObject();
                w.WritePropertyName("before");
                GameBlockWriter.WriteGame(w, before);
                GameRecordFile.WritePlace(w, "place", before.Placement);
                GameRecordFile.WriteShot(w, "shot", shot);
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartArray("rulings");
            foreach (var ruling in match.Rulings)
            {
                GameBlockWriter.WriteRuling(w, ruling);
            }
            w.WriteEndArray();
            w.WriteStartArray("hud");
            foreach (var line in hudLines)
            {
                w.WriteStringValue(line);
            }
            w.WriteEndArray();
            w.WriteEndObject();
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }

    /// <summary>The record as text.</summary>
    public static string ToText(MatchNode match, IReadOnlyList<string> hudLines) => Encoding.UTF8.GetString(ToJson(match, hudLines));
}
