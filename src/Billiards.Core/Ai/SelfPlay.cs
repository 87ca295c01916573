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
public sealed record PlayedShot(GameState Before, Vec3? Place, ShotSpec Planned, ShotSpec Executed, ShotKind Kind, Ruling Ruling, RefereeOption? Option, double DecisionMs, int Simulations)
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
/// The game as the referee's game player played it: its setup (rack seed k + 1 for the k-th
/// rerack) and shots are what <see cref="Scenes.GameRecordFile"/> writes and replays.
/// </param>
public sealed record PlayedGame(GameRules Rules, PerPlayer<int> Levels, int Breaker, IReadOnlyList<PlayedShot> Shots, int? Winner, GamePlayer Record);

/// <summary>
/// Plays whole games computer against computer on the referee's <see cref="GamePlayer"/>: the
/// planner decides, the player's error is applied to the struck shot, the game player simulates it
/// with the planner's physics (the standard model's event integrator), judges it and applies the
/// ruling (spots, reracks, 14.1's rerack of fourteen), with the option the incoming player chooses.
/// </summary>
public sealed class SelfPlay
{
    /// <summary>Shots after which a game is abandoned without a winner (14.1 allows more: ten per point of the target).</summary>
    public const int MaxShots = 400;

    private readonly ShotPlanner _planner;

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
    /// 14.1's score to win (ignored by the other games).
    /// </summary>
    public PlayedGame Play(GameRules rules, PerPlayer<int> levels, int breaker, ulong seed, PlannerBudget budget, int target = GameState.DefaultTarget)
    {
        ArgumentNullException.ThrowIfNull(budget);
        var table = _planner.Table;
        var skills = new PerPlayer<SkillLevel>(SkillLevel.Of(levels.First), SkillLevel.Of(levels.Second));
        int rackSeed = (int)(PlannerRandom.Derive(seed, 7_000_000) & 0x3FFFFFFF);
        var setup = new GameSetup(table.Table, _planner.PhysicsConfig, rackSeed, new GameState(rules) { Shooter = breaker, Target = target });
        var game = new GamePlayer(setup);
        var referee = Referee.For(rules, table.Table, table.R);
        var shots = new List<PlayedShot>();
        int maxShots = rules == GameRules.StraightPool ? Math.Max(MaxShots, 10 * target) : MaxShots;
        for (int k = 0; k < maxShots && !game.IsOver; k++)
        {
            var state = game.State;
            var skill = skills[state.Shooter];
            var balls = game.Balls.OrderBy(b => b.Key.Value).ToList();
            var position = new TablePosition(balls.Select(b => (b.Key, b.Value)));
            var decision = _planner.Decide(state, position, skill, budget, PlannerRandom.Derive(seed, k, 1));
            var place = game.BallInHand == BallInHand.None ? null : decision.Place;
            var executed = skill.Execute(decision.Shot, new PlannerRandom(PlannerRandom.Derive(seed, k, 2)));

            // The incoming player's option depends on the ruling, which the game player applies as it
            // judges: the shot is judged once beforehand, on the same balls, physics and referee.
            RefereeOption? option = null;
            var (preview, after) = Preview(setup, referee, state with { Call = decision.Call, PushOut = decision.PushOut }, balls, place, executed);
            if (!preview.GameOver && preview.Options.Count > 0)
            {
                option = _planner.ChooseOption(preview, after);
            }
            var played = game.Play(new GameShot(executed, decision.Call, place, decision.PushOut, option));
            shots.Add(new PlayedShot(played.Before, place, decision.Shot, executed, decision.Kind, played.Ruling, option, decision.Milliseconds, decision.Simulations)
            {
                Pocket = decision.Pocket,
                ExpectedPot = decision.ExpectedPot,
            });
        }
        int? winner = game.IsOver ? game.Shots[^1].Ruling.Winner : null;
        return new PlayedGame(rules, levels, breaker, shots, winner, game);
    }

    // The shot as GamePlayer.Play runs it: the balls in id order, the cue ball placed or on the head spot.
    private static (Ruling Ruling, TablePosition After) Preview(GameSetup setup, IReferee referee, GameState before, List<KeyValuePair<BallId, Vec3>> balls, Vec3? place, ShotSpec shot)
    {
        double r = setup.BallRadius;
        var start = balls.ToDictionary(b => b.Key.Value, b => b.Value);
        before = before with { Placement = null };
        if (place is { } p)
        {
            start[0] = p with { Z = r };
            before = before with { Placement = start[0] };
        }
        else if (!start.ContainsKey(0))
        {
            start[0] = Initializer.HeadSpot(setup.Table, r);
            before = before with { Placement = start[0] };
        }
        var scene = new Scene("game", null, setup.Table, setup.Physics, null,
            [.. start.OrderBy(b => b.Key).Select(b => new BallSetup(new BallId(b.Key), b.Value, Vec3.Zero, Vec3.Zero))], shot, setup.Rules.ToName());
        var sim = SimulationFactory.Create(scene);
        sim.Strike(shot);
        sim.AdvanceTo(GamePlayer.MaxShotTime);
        var record = ShotRecord.LastShot(sim, shot);
        return (referee.Judge(before, record), TablePosition.After(record));
    }
}
