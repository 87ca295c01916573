using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>One shot of a played game, with what the planner meant and expected.</summary>
/// <param name="Before">The game state before the shot, with the call, placement and push-out that were made.</param>
/// <param name="Place">The cue ball's placement (m), or null.</param>
/// <param name="Planned">The shot the player meant.</param>
/// <param name="Executed">The shot struck, the player's error included (what the physics ran).</param>
/// <param name="Kind">The kind of shot.</param>
/// <param name="Ruling">The referee's ruling.</param>
/// <param name="Option">The option the next player took, when the ruling offered one.</param>
/// <param name="DecisionMs">Wall-clock time of the decision (ms).</param>
/// <param name="Simulations">Simulations of the decision.</param>
public sealed record SelfPlayShot(GameState Before, Vec3? Place, ShotSpec Planned, ShotSpec Executed, ShotKind Kind, Ruling Ruling, RefereeOption? Option, double DecisionMs, int Simulations)
{
    /// <summary>True when the shot meant to pot a ball (not a break, safety or push-out).</summary>
    public bool AttemptedPot => ShotKinds.IsPot(Kind, Pocket);

    /// <summary>True when the shooter stayed at the table or won.</summary>
    public bool Made => ShotPlanner.Made(Ruling, Before.Shooter);

    /// <summary>The pocket the player meant, or <see cref="PocketId.None"/>; set by the player.</summary>
    public PocketId Pocket { get; init; } = PocketId.None;

    /// <summary>The planner's expected pot probability of the shot (<see cref="Decision.ExpectedPot"/>).</summary>
    public double ExpectedPot { get; init; }
}

/// <summary>A game the computer played against itself.</summary>
/// <param name="Rules">The game.</param>
/// <param name="Levels">The two players' levels, player 0 first.</param>
/// <param name="Breaker">The player who broke the first rack.</param>
/// <param name="Shots">Every shot in order.</param>
/// <param name="Winner">The winner, or null when the game hit the shot limit.</param>
/// <param name="Record">
/// The game as the match played it: its setup (rack seed k + 1 for the k-th rerack) and shots are
/// what <see cref="Scenes.GameRecordFile"/> writes and replays.
/// </param>
public sealed record PlayedGame(GameRules Rules, PerPlayer<int> Levels, int Breaker, IReadOnlyList<SelfPlayShot> Shots, int? Winner, Match Record);

/// <summary>
/// Plays whole games computer against computer on a <see cref="Match"/>: the planner decides, the
/// player's error is applied to the struck shot, the match simulates it once with the planner's
/// physics (the standard model's event integrator), judges it and applies the ruling (spots,
/// reracks, 14.1's rerack of fourteen); when the ruling offers options, the incoming player
/// chooses from the table the shot left.
/// </summary>
public sealed class SelfPlay
{
    /// <summary>Shots after which a game is abandoned without a winner (14.1 allows more: ten per point of the target).</summary>
    public const int MaxShots = 400;

    private readonly ShotPlanner _planner;

    // The index of the noise's stream among a shot's (1: the planner's, 2: the level's own error).
    private const long NoiseStream = 3;

    /// <summary>Self-play on <paramref name="table"/> with <paramref name="physics"/>.</summary>
    public SelfPlay(TableSpec table, PhysicsParams physics)
    {
        _planner = new ShotPlanner(table, physics);
    }

    /// <summary>The planner both players use.</summary>
    public ShotPlanner Planner => _planner;

    /// <summary>
    /// Plays one game. Player 0 plays at <paramref name="levels"/>.First; <paramref name="breaker"/>
    /// breaks. Everything random follows from <paramref name="seed"/>; <paramref name="target"/> is
    /// the score to win of 14.1 and three-cushion (ignored by the other games).
    /// </summary>
    public PlayedGame Play(GameRules rules, PerPlayer<int> levels, int breaker, ulong seed, PlannerBudget budget, int target = GameState.DefaultTarget) =>
        Play(rules, new PerPlayer<SkillLevel>(SkillLevel.Of(levels.First), SkillLevel.Of(levels.Second)), breaker, seed, budget, target, null);

    /// <summary>
    /// Plays one game with the players' planners <paramref name="skills"/> (a level as it is, playing
    /// for the noise or blind to it: <see cref="SkillLevel.PlayingFor"/>, <see cref="SkillLevel.NoiseBlind"/>).
    /// With <paramref name="noise"/> every stroke (the break too) is struck with a draw of the noise
    /// in place of the level's own error, from a stream of its own (derived from
    /// <paramref name="seed"/> and the shot's index, apart from the planner's), so the planner never
    /// sees the draws and the games are the same at any thread count.
    /// </summary>
    public PlayedGame Play(GameRules rules, PerPlayer<SkillLevel> skills, int breaker, ulong seed, PlannerBudget budget, int target, ExecutionNoise? noise)
    {
        ArgumentNullException.ThrowIfNull(budget);
        ArgumentNullException.ThrowIfNull(skills.First);
        ArgumentNullException.ThrowIfNull(skills.Second);
        var table = _planner.Table;
        var levels = new PerPlayer<int>(skills.First.Level, skills.Second.Level);
        int rackSeed = (int)(PlannerRandom.Derive(seed, 7_000_000) & 0x3FFFFFFF);
        var setup = new GameSetup(table.Table, _planner.PhysicsConfig, rackSeed, Ruleset.For(rules).BrokenBy(new GameState(rules) { Target = target }, breaker));
        var session = new Session(setup, Seat.Of(setup.Start.Players, SeatKind.Computer));
        var game = session.Game;
        var shots = new List<SelfPlayShot>();
        int maxShots = game.Ruleset.MaxShots(setup.Start);
        for (int k = 0; k < maxShots && !game.IsOver; k++)
        {
            var state = game.State;
            var skill = skills[state.Shooter];
            var position = new TablePosition(game.Balls.OrderBy(b => b.Id.Value), game.Ruleset.CueBall(state));
            var decision = _planner.Decide(state, position, skill, budget, PlannerRandom.Derive(seed, k, 1));
            var place = game.BallInHand == BallInHand.None ? null : decision.Place;
            var executed = noise is null
                ? skill.Execute(decision.Shot, new PlannerRandom(PlannerRandom.Derive(seed, k, 2)))
                : noise.Apply(decision.Shot, new PlannerRandom(PlannerRandom.Derive(seed, k, NoiseStream)), table.R);
            RefereeOption? option = null;
            // The incoming player chooses from the table as the shot left it.
            var played = session.Play(new GameShot(executed, decision.Call, place, decision.PushOut), SeatKind.Computer,
                judged => option = _planner.ChooseOption(judged.Ruling, new TablePosition(judged.After, game.Ruleset.CueBall(judged.Ruling.Next))));
            shots.Add(new SelfPlayShot(played.Before, place, decision.Shot, executed, decision.Kind, played.Ruling, option, decision.Milliseconds, decision.Simulations)
            {
                Pocket = decision.Pocket,
                ExpectedPot = decision.ExpectedPot,
            });
        }
        int? winner = game.IsOver ? game.Shots[^1].Ruling.Winner : null;
        return new PlayedGame(rules, levels, breaker, shots, winner, game);
    }
}
