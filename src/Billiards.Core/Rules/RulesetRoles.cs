using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

// A ruleset's members by role, as pooltool splits its rulesets: what the next shot may be (the
// constraints), how a shot is judged and what follows (the referee), what people are shown (the
// presentation) and how the computer plays the game (the planner's policy). A layer takes the
// role it needs; only a ruleset implements them, all at once (Ruleset). A game's own part of the
// state, and the game-block fields that carry it, are a fifth role (IGameStateRules).

/// <summary>The next shot's constraints (pooltool's ShotConstraints): what may be cued, hit first, called, placed.</summary>
public interface IShotConstraints
{
    /// <inheritdoc cref="Ruleset.CueBall"/>
    BallId CueBall(GameState state);

    /// <inheritdoc cref="Ruleset.LegalTargets"/>
    IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls);

    /// <inheritdoc cref="Ruleset.NeedsCall"/>
    bool NeedsCall(GameState state);

    /// <inheritdoc cref="Ruleset.MayCall"/>
    bool MayCall(GameState state, BallId ball);

    /// <inheritdoc cref="Ruleset.Nominates"/>
    bool Nominates(GameState state);

    /// <inheritdoc cref="Ruleset.MayPushOut"/>
    bool MayPushOut(GameState state);

    /// <inheritdoc cref="Ruleset.BreakBallInHand"/>
    BallInHand BreakBallInHand { get; }

    /// <inheritdoc cref="Ruleset.PowerBreak"/>
    bool PowerBreak { get; }
}

/// <summary>The referee's side of a game: its balls and rack, the judge, what each option leads to, spots and reracks.</summary>
public interface IRefereeRules
{
    /// <inheritdoc cref="Ruleset.Balls"/>
    IReadOnlyList<BallId> Balls { get; }

    /// <inheritdoc cref="Ruleset.Rack(TableSpec, double, int)"/>
    IReadOnlyList<(BallId Id, Vec3 Position)> Rack(TableSpec table, double ballRadius, int seed);

    /// <inheritdoc cref="Ruleset.Rack(GameState, TableSpec, double, int)"/>
    IReadOnlyList<(BallId Id, Vec3 Position)> Rack(GameState start, TableSpec table, double ballRadius, int seed);

    /// <inheritdoc cref="Ruleset.CueStart"/>
    Vec3 CueStart(TableSpec table, double ballRadius);

    /// <inheritdoc cref="Ruleset.Referee"/>
    IReferee Referee(TableSpec table, double ballRadius);

    /// <inheritdoc cref="Ruleset.Choose"/>
    OptionOutcome Choose(Ruling ruling, RefereeOption option);

    /// <inheritdoc cref="Ruleset.SpotBalls"/>
    void SpotBalls(Physics.Simulation simulation, IReadOnlyList<BallId> balls);

    /// <inheritdoc cref="Ruleset.RerackDuringPlay"/>
    (BallLayout Balls, BallInHand? BallInHand) RerackDuringPlay(BallLayout table, IReadOnlyList<BallId> balls, TableSpec tableSpec, double ballRadius, int seed);
}

/// <summary>What people are shown of a game: its names, each player's target, the words of its scores.</summary>
public interface IGamePresentation
{
    /// <inheritdoc cref="Ruleset.ShortName"/>
    string ShortName { get; }

    /// <inheritdoc cref="Ruleset.Title"/>
    string Title { get; }

    /// <inheritdoc cref="Ruleset.Target"/>
    HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls);

    /// <inheritdoc cref="Ruleset.BreakWord"/>
    string BreakWord { get; }

    /// <inheritdoc cref="Ruleset.GameWord"/>
    string GameWord { get; }

    /// <inheritdoc cref="Ruleset.PointsRemaining"/>
    int? PointsRemaining(GameState state, IReadOnlyCollection<BallId> objectBalls);
}

/// <summary>How the computer plays a game: whether it does, what it must still pot, when a game between computers stops.</summary>
public interface IPlannerPolicy
{
    /// <inheritdoc cref="Ruleset.HasComputerPlayer"/>
    bool HasComputerPlayer { get; }

    /// <inheritdoc cref="Ruleset.StillToPot"/>
    IReadOnlyList<BallId> StillToPot(GameState state, IEnumerable<BallId> objectBalls);

    /// <inheritdoc cref="Ruleset.Policy"/>
    Ai.PlannerPolicy Policy { get; }

    /// <inheritdoc cref="Ruleset.MaxShots"/>
    int MaxShots(GameState start);
}

/// <summary>
/// A game's own part of the game state (<see cref="GameStatePart"/>) and the game-block fields
/// that carry it (scene-format.md): the ruleset reads and writes them, so the block's reader and
/// writer know only the fields every game shares.
/// </summary>
public interface IGameStateRules
{
    /// <summary>The game's own part at the start of a game, or null where the game has none.</summary>
    GameStatePart? StartPart { get; }

    /// <summary>The game-block fields of the game's own part, e.g. snooker's "ball_on".</summary>
    IReadOnlyList<string> PartFields { get; }

    /// <summary>Reads the game's own part from a block's fields (<see cref="StartPart"/> where it has none of them).</summary>
    /// <exception cref="Scenes.SceneException">When a field is invalid.</exception>
    GameStatePart? ReadPart(Scenes.GameBlockFields block);

    /// <summary>Reads a block's "call" (not null): pool's <c>{"ball", "pocket"}</c>, snooker's nomination <c>{"ball"}</c>; <c>{"safety": true}</c> is read before.</summary>
    /// <exception cref="Scenes.SceneException">When the call is invalid.</exception>
    Call ReadCall(JsonElement call, Scenes.GameBlockFields block);

    /// <summary>Writes the game's own fields of <paramref name="state"/> that go at <paramref name="slot"/> of the block.</summary>
    void WritePart(Utf8JsonWriter writer, GameState state, GameBlockSlot slot);

    /// <summary>Writes the game's own fields of a ruling (snooker's points, three-cushion's innings), after "message".</summary>
    void WriteRulingFields(Utf8JsonWriter writer, Ruling ruling);
}
