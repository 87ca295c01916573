using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Scenes;

/// <summary>Writes game blocks and rulings as scene-format.md defines them.</summary>
public static class GameBlockWriter
{
    /// <summary>
    /// Writes a game block: the fields every game shares (push_out only when declared, the call
    /// only when made, "ball_in_hand" when there is one) and, at their places in the contract's
    /// order, the game's own, which its ruleset writes (<see cref="IGameStateRules.WritePart"/>).
    /// <see cref="GameBlockReader.Read"/> reads it back to an equal state (the placement excepted).
    /// </summary>
    public static void WriteGame(Utf8JsonWriter w, GameState state)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(state);
        w.WriteStartObject();
        w.WriteString("rules", state.Rules.ToName());
        w.WriteStartArray("players");
        w.WriteStringValue(state.Players.First);
        w.WriteStringValue(state.Players.Second);
        w.WriteEndArray();
        w.WriteNumber("shooter", state.Shooter);
        w.WriteNumber("shot", state.Shot);
        var ruleset = Ruleset.For(state.Rules);
        ruleset.WritePart(w, state, GameBlockSlot.AfterShot);
        if (state.Call is { } call)
        {
            WriteCall(w, "call", call, ruleset.BallSet);
        }
        if (state.PushOut)
        {
            w.WriteBoolean("push_out", true);
        }
        WritePair(w, "fouls_in_row", state.FoulsInRow);
        WritePair(w, "score", state.Score);
        w.WriteNumber("target", state.Target);
        if (state.BallInHand != BallInHand.None)
        {
            w.WriteString("ball_in_hand", state.BallInHand.ToName());
        }
        ruleset.WritePart(w, state, GameBlockSlot.AtEnd);
        w.WriteEndObject();
    }

    /// <summary>Writes a call: <c>{"ball", "pocket"}</c>, <c>{"safety": true}</c> or snooker's nomination <c>{"ball"}</c>; <paramref name="ballSet"/> names the ball.</summary>
    public static void WriteCall(Utf8JsonWriter w, string name, Call call, BallSet ballSet)
    {
        ArgumentNullException.ThrowIfNull(ballSet);
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(call);
        w.WriteStartObject(name);
        if (call.IsSafety)
        {
            w.WriteBoolean("safety", true);
        }
        else if (call.IsNomination)
        {
            w.WriteString("ball", ballSet.NameOf(call.Ball));
        }
        else
        {
            w.WriteString("ball", ballSet.NameOf(call.Ball));
            w.WriteString("pocket", call.Pocket.ToName());
        }
        w.WriteEndObject();
    }

    /// <summary>Writes a ruling with every field of the contract, in its order.</summary>
    public static void WriteRuling(Utf8JsonWriter w, Ruling ruling)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(ruling);
        var set = Ruleset.For(ruling.Next.Rules).BallSet;
        w.WriteStartObject();
        w.WriteBoolean("legal", ruling.Legal);
        WriteNames(w, "fouls", ruling.Fouls.Select(f => f.ToName()));
        WriteNames(w, "pocketed", ruling.Pocketed.Select(set.NameOf));
        w.WriteBoolean("continue", ruling.Continue);
        if (ruling.BallInHand == BallInHand.None)
        {
            w.WriteNull("ball_in_hand");
        }
        else
        {
            w.WriteString("ball_in_hand", ruling.BallInHand.ToName());
        }
        WriteNames(w, "spot", ruling.Spot.Select(set.NameOf));
        WriteNames(w, "options", ruling.Options.Select(Ruleset.For(ruling.Next.Rules).WordOf));
        w.WriteBoolean("game_over", ruling.GameOver);
        if (ruling.Winner is { } winner)
        {
            w.WriteNumber("winner", winner);
        }
        else
        {
            w.WriteNull("winner");
        }
        w.WriteString("message", ruling.Message);
        Ruleset.For(ruling.Next.Rules).WriteRulingFields(w, ruling);
        w.WritePropertyName("next");
        WriteGame(w, ruling.Next);
        w.WriteEndObject();
    }

    /// <summary>A ruling as indented UTF-8 JSON, e.g. to compare two rulings byte for byte.</summary>
    public static byte[] RulingToUtf8(Ruling ruling)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            WriteRuling(w, ruling);
        }
        return stream.ToArray();
    }

    /// <summary>Writes one whole number per player as <c>"name": [first, second]</c>.</summary>
    public static void WritePair(Utf8JsonWriter w, string name, PerPlayer<int> pair)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(pair.First);
        w.WriteNumberValue(pair.Second);
        w.WriteEndArray();
    }

    /// <summary>Writes names as <c>"name": ["a", "b"]</c>.</summary>
    public static void WriteNames(Utf8JsonWriter w, string name, IEnumerable<string> values)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(values);
        w.WriteStartArray(name);
        foreach (string v in values)
        {
            w.WriteStringValue(v);
        }
        w.WriteEndArray();
    }

}
