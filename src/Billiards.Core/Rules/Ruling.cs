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

    /// <summary>Snooker: points scored by the shooter on this shot.</summary>
    public int Points { get; init; }

    /// <summary>Snooker: points awarded to the other player for a foul (0 without one).</summary>
    public int Penalty { get; init; }

    /// <summary>Snooker: the referee called a foul and a miss (<see cref="RefereeOption.Replace"/> is offered).</summary>
    public bool FoulAndMiss { get; init; }

    /// <summary>Snooker: the incoming player is snookered after a foul and may nominate a free ball.</summary>
    public bool FreeBall { get; init; }

    /// <summary>Three-cushion: the shot scored a point.</summary>
    public bool Point { get; init; }

    /// <summary>
    /// Three-cushion: the shooter's cue ball's cushion contacts before its contact with the
    /// second object ball, or in all when it met fewer than two.
    /// </summary>
    public int Cushions { get; init; }

    /// <summary>Three-cushion: each player's innings after the shot (the score sheet's).</summary>
    public PerPlayer<int> Innings { get; init; }

    /// <summary>Three-cushion: the shooter's points in this inning, this shot's included.</summary>
    public int Run { get; init; }

    /// <summary>
    /// Snooker, after a foul and a miss: the state for the offender's next shot when the balls are
    /// replaced where they were before the shot (<see cref="RefereeOption.Replace"/>), else null.
    /// </summary>
    public GameState? Replaced { get; init; }

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
