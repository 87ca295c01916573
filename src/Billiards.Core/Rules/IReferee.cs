using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// A game's referee: a pure function from the state before a shot and the shot's record to a
/// ruling. It reads nothing else (no clock, renderer or random numbers), so the same inputs
/// always give the same ruling, and a recorded game replays ruling for ruling.
/// </summary>
public interface IReferee
{
    /// <summary>The game this referee judges.</summary>
    GameRules Rules { get; }

    /// <summary>The table the game is played on.</summary>
    TableSpec Table { get; }

    /// <summary>The balls' radius (m), for placement checks.</summary>
    double BallRadius { get; }

    /// <summary>Judges one shot.</summary>
    /// <param name="before">The game state before the shot (its <see cref="GameState.Rules"/> must be <see cref="Rules"/>).</param>
    /// <param name="shot">The shot's events from its strike on and every ball after it.</param>
    Ruling Judge(GameState before, ShotRecord shot);
}

/// <summary>Creates the referee of a game.</summary>
public static class Referee
{
    /// <summary>
    /// The referee of <paramref name="rules"/> on <paramref name="table"/>, for balls of radius
    /// <paramref name="ballRadius"/> (m). Table and balls are part of the referee so that games on
    /// other tables and with other ball sets (snooker, carom) fit behind the same interface.
    /// </summary>
    public static IReferee For(GameRules rules, TableSpec table, double ballRadius)
    {
        ArgumentNullException.ThrowIfNull(table);
        return Ruleset.For(rules).Referee(table, ballRadius);
    }

    /// <summary>
    /// <paramref name="rules"/>'s referee as <see cref="For"/> gives it, ruling without words where
    /// the game's referee can (every ruling's fields the same, its <see cref="Ruling.Message"/>
    /// empty): for the planner's search, which reads no sentence.
    /// </summary>
    internal static IReferee Wordless(GameRules rules, TableSpec table, double ballRadius)
    {
        var referee = For(rules, table, ballRadius);
        if (referee is RefereeBase worded)
        {
            worded.Words = false;
        }
        return referee;
    }

    /// <summary>The balls a game is played with, cue ball first (<see cref="Ruleset.Balls"/>).</summary>
    public static IReadOnlyList<Balls.BallId> BallsOf(GameRules rules) => Ruleset.For(rules).Balls;
}
