using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>One shot of a played game, as the game record keeps it.</summary>
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
    public bool AttemptedPot => Kind is ShotKind.Direct or ShotKind.Bank or ShotKind.Combination or ShotKind.Carom
        || (Kind == ShotKind.Kick && PotKick);

    /// <summary>True when the shooter stayed at the table or won.</summary>
    public bool Made => Ruling.GameOver ? Ruling.Winner == Before.Shooter : Ruling.Continue;

    /// <summary>A kick meant to pot (it has a pocket); set by the player.</summary>
    public bool PotKick { get; init; }
}

/// <summary>A game the computer played against itself.</summary>
/// <param name="Rules">The game.</param>
/// <param name="Racks">The racks' seeds, first rack first (a rerack adds one).</param>
/// <param name="Levels">The two players' levels, player 0 first.</param>
/// <param name="Breaker">The player who broke the first rack.</param>
/// <param name="Shots">Every shot in order.</param>
/// <param name="Winner">The winner, or null when the game hit the shot limit.</param>
public sealed record PlayedGame(GameRules Rules, IReadOnlyList<int> Racks, PerPlayer<int> Levels, int Breaker, IReadOnlyList<PlayedShot> Shots, int? Winner);

/// <summary>
/// Plays whole games computer against computer: the planner decides, the player's error is
/// applied to the struck shot, the standard model simulates it, the referee judges it, options are
/// chosen, balls spotted and racks reracked as the ruling says.
/// </summary>
public sealed class SelfPlay
{
    /// <summary>Shots after which a game is abandoned without a winner.</summary>
    public const int MaxShots = 400;

    private readonly ShotPlanner _planner;

    /// <summary>Self-play on <paramref name="table"/> with <paramref name="physics"/>.</summary>
    public SelfPlay(TableSpec table, PhysicsParams physics)
    {
        _planner = new ShotPlanner(table, physics);
    }

    /// <summary>The planner both players use.</summary>
    public ShotPlanner Planner => _planner;

    /// <summary>The rack a game of <paramref name="rules"/> is played with, or null for 14.1, whose reracks of 14 balls self-play does not place yet.</summary>
    public static RackGame? RackOf(GameRules rules) => rules switch
    {
        GameRules.EightBall => RackGame.EightBall,
        GameRules.NineBall => RackGame.NineBall,
        GameRules.TenBall => RackGame.TenBall,
        _ => null,
    };

    /// <summary>
    /// Plays one game. Player 0 plays at <paramref name="levels"/>.First; <paramref name="breaker"/>
    /// breaks. Everything random follows from <paramref name="seed"/>.
    /// </summary>
    /// <exception cref="NotSupportedException">For a game whose rack the Initializer cannot place yet.</exception>
    public PlayedGame Play(GameRules rules, PerPlayer<int> levels, int breaker, ulong seed, PlannerBudget budget)
    {
        ArgumentNullException.ThrowIfNull(budget);
        var rackGame = RackOf(rules) ?? throw new NotSupportedException($"self-play cannot rack {rules.ToName()} yet");
        var table = _planner.Table;
        var skills = new PerPlayer<SkillLevel>(SkillLevel.Of(levels.First), SkillLevel.Of(levels.Second));
        var racks = new List<int>();
        int NewRack()
        {
            int rackSeed = (int)(PlannerRandom.Derive(seed, 7_000_000 + racks.Count) & 0x7FFFFFFF);
            racks.Add(rackSeed);
            return rackSeed;
        }
        var position = TablePosition.Rack(new RackSpec(rackGame, NewRack()), table.Table, table.R);
        var state = new GameState(rules) { Shooter = breaker };
        var shots = new List<PlayedShot>();
        var record = new ShotRecord();
        int? winner = null;
        for (int k = 0; k < MaxShots; k++)
        {
            var skill = skills[state.Shooter];
            var decision = _planner.Decide(state, position, skill, budget, PlannerRandom.Derive(seed, k, 1));
            var before = state with { Call = decision.Call, PushOut = decision.PushOut, Placement = decision.Place };
            var start = decision.Place is { } place ? position.With(Balls.BallId.Cue, place) : position;
            var executed = skill.Execute(decision.Shot, new PlannerRandom(PlannerRandom.Derive(seed, k, 2)));
            var sim = start.CreateSimulation(table.Table, table.Physics);
            sim.Strike(executed);
            sim.AdvanceTo(120);
            record.Capture(sim, 0, executed);
            var ruling = Referee.For(rules, table.Table, table.R).Judge(before, record);
            position = TablePosition.After(record);
            RefereeOption? option = null;
            var next = ruling.Next;
            IReadOnlyList<Balls.BallId> spot = ruling.Spot;
            bool rerack = false;
            if (!ruling.GameOver && ruling.Options.Count > 0)
            {
                var chosen = _planner.ChooseOption(ruling, position);
                option = chosen;
                var outcome = ruling.Choose(chosen);
                next = outcome.Next;
                spot = outcome.Spot;
                rerack = outcome.Rerack;
            }
            shots.Add(new PlayedShot(before, decision.Place, decision.Shot, executed, decision.Kind, ruling, option, decision.Milliseconds, decision.Simulations)
            {
                PotKick = decision.Kind == ShotKind.Kick && decision.Pocket != PocketId.None,
            });
            if (ruling.GameOver)
            {
                winner = ruling.Winner;
                break;
            }
            if (rerack)
            {
                position = TablePosition.Rack(new RackSpec(rackGame, NewRack()), table.Table, table.R);
            }
            else if (spot.Count > 0)
            {
                position = position.Spotted(spot, table.Table, table.R);
            }
            state = next;
        }
        return new PlayedGame(rules, racks, levels, breaker, shots, winner);
    }
}
