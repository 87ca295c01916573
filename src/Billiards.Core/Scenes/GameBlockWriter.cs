using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Scenes;

/// <summary>Writes game blocks and rulings as scene-format.md defines them.</summary>
public static class GameBlockWriter
{
    /// <summary>
    /// Writes a game block: the contract's fields that apply to the game (groups only for 8-ball,
    /// push_out only when declared, the call only when made) and "ball_in_hand" when there is one.
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
        if (Ruleset.For(state.Rules).HasGroups)
        {
            if (state.Groups is { } g)
            {
                w.WriteStartArray("groups");
                w.WriteStringValue(g.First.ToName());
                w.WriteStringValue(g.Second.ToName());
                w.WriteEndArray();
            }
            else
            {
                w.WriteNull("groups");
            }
        }
        if (state.Call is { } call)
        {
            WriteCall(w, "call", call, Ruleset.For(state.Rules).BallSet);
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
        if (Ruleset.For(state.Rules).HasBallOn)
        {
            w.WriteString("ball_on", SnookerRuleset.BallOnOf(state));
            w.WriteBoolean("free_ball", state.FreeBall);
            WritePair(w, "misses_in_row", state.MissesInRow);
        }
        if (Ruleset.For(state.Rules).HasInnings)
        {
            var cueBalls = state.CueBalls ?? ThreeCushionRuleset.DefaultCueBalls;
            var set = Ruleset.For(state.Rules).BallSet;
            WriteNames(w, "cue_balls", [set.NameOf(cueBalls.First), set.NameOf(cueBalls.Second)]);
            WritePair(w, "innings", state.Innings);
            w.WriteBoolean("equalizing", state.Equalizing);
            w.WriteNumber("breaker", state.Breaker);
            w.WriteNumber("run", state.Run);
        }
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
        WriteNames(w, "options", ruling.Options.Select(o => o.ToName()));
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
        if (Ruleset.For(ruling.Next.Rules).HasBallOn)
        {
            w.WriteNumber("points", ruling.Points);
            w.WriteNumber("penalty", ruling.Penalty);
            w.WriteBoolean("foul_and_miss", ruling.FoulAndMiss);
            w.WriteBoolean("free_ball", ruling.FreeBall);
        }
        if (Ruleset.For(ruling.Next.Rules).HasInnings)
        {
            w.WriteBoolean("point", ruling.Point);
            w.WriteNumber("cushions", ruling.Cushions);
            WritePair(w, "score", ruling.Score);
            WritePair(w, "innings", ruling.Innings);
            w.WriteStartArray("average");
            w.WriteNumberValue(ThreeCushionRuleset.AverageValue(ruling.Score.First, ruling.Innings.First));
            w.WriteNumberValue(ThreeCushionRuleset.AverageValue(ruling.Score.Second, ruling.Innings.Second));
            w.WriteEndArray();
            w.WriteNumber("run", ruling.Run);
        }
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

    private static void WritePair(Utf8JsonWriter w, string name, PerPlayer<int> pair)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(pair.First);
        w.WriteNumberValue(pair.Second);
        w.WriteEndArray();
    }

    private static void WriteNames(Utf8JsonWriter w, string name, IEnumerable<string> values)
    {
        w.WriteStartArray(name);
        foreach (string v in values)
        {
            w.WriteStringValue(v);
        }
        w.WriteEndArray();
    }

}
