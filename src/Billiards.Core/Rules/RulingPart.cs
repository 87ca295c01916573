namespace Billiards.Core.Rules;

/// <summary>
/// A game's own part of a ruling (snooker's foul and miss, three-cushion's point and innings):
/// each game's folder defines one record deriving from this, its referee fills it and its ruleset
/// writes the ruling fields that carry it (<see cref="Ruleset.WriteRulingFields"/>). The common
/// <see cref="Ruling"/> holds it in <see cref="Ruling.Part"/>, so that a ruling is not a union of
/// every game's fields, as <see cref="GameStatePart"/> keeps the game state from being one.
/// </summary>
public abstract record RulingPart;
