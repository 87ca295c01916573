using Billiards.Core.Balls;

namespace Billiards.Core.Rules;

/// <summary>
/// The referee's decision on one shot, as results write it under "ruling" (scene-format.md).
/// <see cref="Next"/> is the state for the next shot when the incoming player takes the first of
/// <see cref="Options"/> (or when there are none); <see cref="Choose"/> gives the others.
/// </summary>
/// <param name="Legal">No foul on the shot.</param>
/// <param name="Fouls">Every foul code of the shot, loss codes included; empty when legal.</param>
/// <param name="Pocketed">Object balls pocketed on this shot, in the order they dropped.</param>
/// <param name="Continue">The shooter stays at the table.</param>
/// <param name="BallInHand">Where the next shooter may place the cue ball.</param>
/// <param name="Spot">Balls to put on the foot spot before the next shot, in number order.</param>
/// <param name="Options">The incoming player's choices; the first is the default that <see cref="Next"/> assumes.</param>
/// <param name="GameOver">The game is decided.</param>
/// <param name="Winner">The winner's index, or null.</param>
/// <param name="Message">One sentence for the HUD.</param>
/// <param name="Next">The game state before the next shot.</param>
public sealed record Ruling(
    bool Legal,
    IReadOnlyList<Foul> Fouls,
    IReadOnlyList<BallId> Pocketed,
    bool Continue,
    BallInHand BallInHand,
    IReadOnlyList<BallId> Spot,
    IReadOnlyList<RefereeOption> Options,
    bool GameOver,
    int? Winner,
    string Message,
    GameState Next)
{
    /// <summary>
    /// 14.1: the balls to rack again with the apex spot empty before the next shot (the 14
    /// pocketed balls, or all 15), empty otherwise. The game places them; the ruling's JSON does
    /// not carry them because every reader can tell them from the balls on the table.
    /// </summary>
    public IReadOnlyList<BallId> Rerack { get; init; } = [];

    /// <summary>
    /// The score after the shot (14.1's and snooker's points; 0-0 in the other games). When the
    /// game is over it is the final score, which <see cref="Next"/>, the next game's start, does not carry.
    /// </summary>
    public PerPlayer<int> Score { get; init; }

    /// <summary>Points scored by the shooter on this shot, in games that score shot by shot (snooker); 0 in the others.</summary>
    public int Points { get; init; }

    /// <summary>Points awarded to the other player for a foul, in games that award them (snooker); 0 without one.</summary>
    public int Penalty { get; init; }

    /// <summary>The game's own part of the ruling (<see cref="RulingPart"/>), or null for a game without one.</summary>
    public RulingPart? Part { get; init; }

    /// <summary>The game's own part of the ruling as <typeparamref name="T"/>, or null when the game has none of that kind.</summary>
    public T? PartOf<T>() where T : RulingPart => Part as T;

    /// <summary>
    /// The state and table work that follow when the next shooter takes <paramref name="option"/>.
    /// </summary>
    /// <exception cref="ArgumentException">When the ruling does not offer the option.</exception>
    public OptionOutcome Choose(RefereeOption option) => Ruleset.For(Next.Rules).Choose(this, option);
}

/// <summary>What follows an option of the incoming player.</summary>
/// <param name="Next">The game state before the next shot.</param>
/// <param name="Rerack">Rack all the game's balls again (the next shot is a break).</param>
/// <param name="Spot">Balls to spot before the next shot.</param>
public sealed record OptionOutcome(GameState Next, bool Rerack, IReadOnlyList<BallId> Spot)
{
    /// <summary>Put every ball back where it stood before the shot (snooker's replace); <see cref="Spot"/> is then empty.</summary>
    public bool Replace { get; init; }
}
