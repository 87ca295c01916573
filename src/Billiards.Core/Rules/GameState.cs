using Billiards.Core.Mathematics;

namespace Billiards.Core.Rules;

/// <summary>
/// One value per player of a two-player game, with value equality (so that a whole
/// <see cref="GameState"/> compares by value).
/// </summary>
/// <param name="First">Player 0's value.</param>
/// <param name="Second">Player 1's value.</param>
public readonly record struct PerPlayer<T>(T First, T Second)
{
    /// <summary>Player <paramref name="player"/>'s value (0 or 1).</summary>
    public T this[int player] => player switch
    {
        0 => First,
        1 => Second,
        _ => throw new ArgumentOutOfRangeException(nameof(player), player, "a game has players 0 and 1"),
    };

    /// <summary>A copy with player <paramref name="player"/>'s value replaced.</summary>
    public PerPlayer<T> With(int player, T value) => player == 0 ? this with { First = value } : this with { Second = value };
}

/// <summary>
/// The state of a game before a shot: what scene files carry as the "game" block
/// (scene-format.md) and what the referee needs besides the shot itself. Every member but
/// <see cref="Rules"/> defaults to the start of a game.
/// </summary>
public sealed record GameState
{
    /// <summary>The default target score of 14.1 (points).</summary>
    public const int DefaultTarget = 100;

    /// <summary>The default player names.</summary>
    public static PerPlayer<string> DefaultPlayers { get; } = new("Player 1", "Player 2");

    /// <summary>The start of a game of <paramref name="rules"/>: player 0 breaks, for the game's default target (<see cref="Ruleset.DefaultTarget"/>).</summary>
    public GameState(GameRules rules)
    {
        Rules = rules;
        var ruleset = rules.Name is null ? null : Ruleset.Find(rules.Name);
        Target = ruleset?.DefaultTarget ?? DefaultTarget;
        Part = ruleset?.StartPart;
    }

    /// <summary>Which game is played.</summary>
    public GameRules Rules { get; init; }

    /// <summary>The players' names.</summary>
    public PerPlayer<string> Players { get; init; } = DefaultPlayers;

    /// <summary>Index (0 or 1) of the player at the table.</summary>
    public int Shooter { get; init; }

    /// <summary>The index of the player waiting: the incoming player if the turn passes.</summary>
    public int Incoming => 1 - Shooter;

    /// <summary>The shot's number in this rack; 0 is the break.</summary>
    public int Shot { get; init; }

    /// <summary>The shooter's call, or null when none was made (counts as calling nothing).</summary>
    public Call? Call { get; init; }

    /// <summary>9-ball and 10-ball: this shot is a declared push-out (only on shot 1).</summary>
    public bool PushOut { get; init; }

    /// <summary>Consecutive fouls of each player.</summary>
    public PerPlayer<int> FoulsInRow { get; init; }

    /// <summary>14.1, snooker and three-cushion: each player's points.</summary>
    public PerPlayer<int> Score { get; init; }

    /// <summary>14.1 and three-cushion: the points that win (default 100 in 14.1, 40 in three-cushion).</summary>
    public int Target { get; init; } = DefaultTarget;

    /// <summary>
    /// Where the shooter may place the cue ball before this shot (the previous ruling's
    /// ball in hand). The break always places behind the head string.
    /// </summary>
    public BallInHand BallInHand { get; init; }

    /// <summary>
    /// Where the shooter placed the cue ball with ball in hand (m, z = R), or null when it was
    /// not placed; the referee checks it against <see cref="BallInHand"/>.
    /// </summary>
    public Vec3? Placement { get; init; }

    /// <summary>
    /// The game's own part of the state (<see cref="GameStatePart"/>): 8-ball's groups, snooker's
    /// ball on, three-cushion's innings; null where the game has none. A new state starts with its
    /// ruleset's <see cref="IGameStateRules.StartPart"/>.
    /// </summary>
    public GameStatePart? Part { get; init; }

    /// <summary>
    /// The game's own part as <typeparamref name="T"/>, or the start of one (<c>new T()</c>) when
    /// the state holds none of that type (a state of another game).
    /// </summary>
    public T PartOf<T>() where T : GameStatePart, new() => Part as T ?? StartOf<T>.Value;

    /// <summary>The shooter's name.</summary>
    public string ShooterName => Players[Shooter];

    /// <summary>The incoming player's name.</summary>
    public string IncomingName => Players[Incoming];

    // One start part per part type, shared: parts are immutable records.
    private static class StartOf<T> where T : GameStatePart, new()
    {
        public static readonly T Value = new();
    }
}
