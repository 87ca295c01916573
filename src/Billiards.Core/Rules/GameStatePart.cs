namespace Billiards.Core.Rules;

/// <summary>
/// A game's own part of the game state (8-ball's groups, snooker's ball on, three-cushion's
/// innings): each game's folder defines one record deriving from this, and its ruleset reads and
/// writes the game-block fields that carry it (<see cref="IGameStateRules"/>). The common
/// <see cref="GameState"/> holds it in <see cref="GameState.Part"/>, so that the state of a game
/// is not a union of every game's fields. Records compare by value, and so do the states that hold them.
/// </summary>
public abstract record GameStatePart
{
    /// <summary>The part as a game that ended shows it: by default unchanged; an award for a next shot (snooker's free ball) is dropped.</summary>
    public virtual GameStatePart AtEnd => this;
}

/// <summary>
/// Where in a game block a ruleset's own fields are written, so that every block keeps the
/// contract's field order (scene-format.md): a game's fields that the contract puts before the call
/// (8-ball's groups) go <see cref="AfterShot"/>, the others <see cref="AtEnd"/>.
/// </summary>
public enum GameBlockSlot
{
    /// <summary>After "shot", before "call".</summary>
    AfterShot,

    /// <summary>After "ball_in_hand", at the end of the block.</summary>
    AtEnd,
}
