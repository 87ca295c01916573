using System.Diagnostics;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>
/// The computer player: plans a shot by simulating it. The game and the command line call
/// <see cref="Decide(GameState, TablePosition, SkillLevel, PlannerBudget, ulong)"/> before each shot and <see cref="ChooseOption"/> when the referee offers a
/// choice.
/// </summary>
/// <remarks>
/// The search, top to bottom:
/// <list type="number">
/// <item>Placements: with ball in hand (or on the break), a few cue-ball spots behind the ghost balls
/// of the easiest shots (or behind the head string), each a root of the search.</item>
/// <item>Candidates: ghost-ball geometry for every legal target and pocket (direct, bank, kick,
/// combination, carom) ranked by their geometric ease, plus safeties.</item>
/// <item>Variations: each candidate at several speeds and spins (follow, stun, draw, side with the
/// squirt corrected, an elevated draw), its aim corrected for collision-induced throw.</item>
/// <item>Aim by trial (levels 3 to 5): each pot's aim is tried without error at
/// <see cref="SkillLevel.AimTrials"/> steps of <see cref="AimTrialStepDeg"/> either side of the
/// geometric aim, and the middle of the range of aims that pot is played, so that the player's own
/// error is spent evenly on both sides of the pocket (the geometry's throw and squirt corrections, and
/// the banks' and kicks' mirror images, are approximations the physics then corrects).</item>
/// <item>Simulation: each variation from a snapshot of its root's position (taken once, restored
/// before every shot), with the standard model's event integrator, several times with the player's
/// own error (<see cref="SkillLevel"/>); the referee judges each result and a score says how good
/// it is for the shooter: a won game 1, a lost game 0, staying at the table 0.7 plus 0.3 times the
/// quality of the position for the next shot (<see cref="PlannerTable.PositionQuality(TablePosition, GameState, double)"/>, with the
/// shooter's own error) less 0.04 per ball left without a straight way to a pocket
/// (<see cref="PlannerTable.ProblemBalls"/>), a legal miss 0.5 less 0.4 times the opponent's best shot (how
/// safeties are judged; the opponent judged at least as good as the player,
/// <see cref="SkillLevel.OpponentAimStdDeg"/>), a foul 0.08.</item>
/// <item>Refinement: the best variations are simulated again with more error samples, at levels 4
/// and 5 in two rounds (at level 5 the best 40 with 10 more, the best 10 of those with 60 more);
/// of the last round the best mean less its standard error wins, so that of two shots with nearly
/// the same mean the surer one is played. A chosen pot that none of its (at least ten) simulations
/// made is played, and called where the game calls, as a safety: it was chosen for what it leaves.</item>
/// <item>Pot or safety (the games with snookers, where safety play is strong, at the levels with a
/// <see cref="SkillLevel.SurePotChance"/>): from the middle round on, a pot attempt whose simulations pot
/// less often than that chance loses <see cref="ShortfallWeight"/> of score per unit of chance short,
/// and the middle round takes the first round's best safeties besides its best variations
/// (<see cref="ScreenedSafeties"/>), so that a strong player attempts a pot when it is nearly sure,
/// or when the alternatives are worse by more than what the shortfall costs, and else plays safe.</item>
/// </list>
/// Its jobs live in files of their own: the search's rounds (<c>ShotPlanner.Search.cs</c>), the
/// cue-ball placements (<c>.Placements.cs</c>), the variations of each candidate (<c>.Variations.cs</c>;
/// the search then raises each shot's cue as far as its clearance needs), aim correction (<c>.Aim.cs</c>) and the
/// score with its named weights (<c>.Scoring.cs</c>).
/// Determinism: every simulation draws its error from its own stream, derived from the seed and
/// the variation's and sample's indices, and results are reduced in index order, so the threads
/// (and their number) do not change the decision unless the time cap cuts the search short.
/// </remarks>
/// <example>
/// The computer's shot for the player at the table, struck with its level's error and played:
/// <code language="csharp">
/// var match = new Match(GameSetup.Of(GameRules.EightBall, seed: 7));
/// var planner = new ShotPlanner(match.Setup.Table, match.Setup.Physics.Params);   // once per table
/// Decision d = planner.Decide(match.State, match.Layout(), level: 3, budgetMs: 3000, seed: 7);
/// ShotSpec struck = SkillLevel.Of(3).Execute(d.Shot, new PlannerRandom(8));    // the player's error
/// MatchShot shot = match.Play(new GameShot(struck, d.Call, d.Place, d.PushOut));
/// Console.WriteLine($"{d.Kind}, expected to pot {d.ExpectedPot:P0}: {shot.Ruling.Message}");
/// </code>
/// A hint is the same call for a person's turn: draw <c>d.Shot</c>'s aim line and take its placement and call.
/// </example>
public sealed partial class ShotPlanner
{
    private const double MaxShotTime = 120;
    private const double MaxNormalSpeed = 6.5;

    // A level takes the first of these (sorted before use): the strongest players also try the
    // speeds in between.
    private static readonly double[] SpeedFactors = [1.0, 1.5, 2.3, 0.75, 3.2, 1.2, 1.85];

    // The break of the planner that plays for the noise (SkillLevel.PlayingFor): the same break is
    // struck every rack and decides whether the breaker stays, and under the noise the rack's own
    // gaps decide which break drops a ball, so it searches a wide grid on the rack before it: the cue
    // ball's spots on the head string's side of the kitchen (fractions of the half width less R,
    // from the long axis towards either rail), the cue speeds (m/s, elastic tip), the tip heights
    // (fractions of R) and the cuts (R off the full-ball aim, to the side of the ball away from the
    // spot's rail) at the head ball and at the second-row ball nearer the cue ball.
    // 7 x 4 x 4 x 4 x 2 = 896 breaks; the search's rounds keep the best by its outcomes under the
    // noise (a ball down and the cue ball up, and the leave).
    private static readonly double[] NoiseBreakSpots = [0, 0.3, 0.6, 0.85, -0.3, -0.6, -0.85];
    private static readonly double[] NoiseBreakSpeeds = [7.5, 9, 10.5, 12];
    private static readonly double[] NoiseBreakHeights = [-0.3, 0, 0.2, 0.4];
    private static readonly double[] NoiseBreakOffsets = [0, 0.4, 0.8, 1.2];

    // (side, height, elevation deg): stun, follow, draw, side either way, elevated draw; then
    // half follow, half draw and side with draw either way.
    private static readonly (double Side, double Height, double Elevation)[] SpinSet =
        [(0, 0, 0), (0, 0.4, 0), (0, -0.45, 0), (0.3, 0.1, 0), (-0.3, 0.1, 0), (0, -0.5, 8),
         (0, 0.2, 0), (0, -0.25, 0), (0.3, -0.3, 0), (-0.3, -0.3, 0)];

    /// <summary>
    /// A planner for games on <paramref name="table"/> with balls of <paramref name="physics"/>,
    /// simulated with the standard model and the game's collision models (the defaults when null).
    /// </summary>
    public ShotPlanner(TableSpec table, PhysicsParams physics, Physics.Collisions.InteractionModels? models = null)
    {
        Table = new PlannerTable(table, physics);
        PhysicsConfig = TablePosition.PlannerPhysics(physics, models);
        Model = new StandardTableModel(table, PhysicsConfig);
    }

    /// <summary>The physics the planner simulates with (the standard model's event integrator).</summary>
    public PhysicsConfig PhysicsConfig { get; }

    // Built once: every search simulation shares its geometry, and snapshots move between them.
    private StandardTableModel Model { get; }

    /// <summary>The planner's view of the table.</summary>
    public PlannerTable Table { get; }

    /// <summary>
    /// Decides the shot of the player at the table in <paramref name="state"/> with the balls of
    /// <paramref name="position"/>, at <paramref name="level"/>, within <paramref name="budget"/>.
    /// The same arguments give the same decision.
    /// </summary>
    public Decision Decide(GameState state, TablePosition position, SkillLevel level, PlannerBudget budget, ulong seed)
    {
        ArgumentNullException.ThrowIfNull(state);
        ArgumentNullException.ThrowIfNull(position);
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(budget);
        var ruleset = Ruleset.For(state.Rules);
        if (ruleset is ThreeCushionRuleset)
        {
            return DecideCarom(state, position.ForCueBall(ruleset.CueBall(state)), level, budget, seed);
        }
        var clock = Stopwatch.StartNew();
        var search = new Search(this, state, position.ForCueBall(ruleset.CueBall(state)), level, budget, seed, clock);
        return search.Run();
    }

    /// <summary>Decides with a level number and a time cap: the short form for the game.</summary>
    public Decision Decide(GameState state, Simulation simulation, int level, int budgetMs, ulong seed) =>
        Decide(state, TablePosition.Of(simulation, Ruleset.For(state.Rules).CueBall(state)), SkillLevel.Of(level), new PlannerBudget(budgetMs), seed);

    /// <summary>
    /// The choice of the incoming player when <paramref name="ruling"/> offers options, with the
    /// balls as they lie in <paramref name="position"/>: shoot after a push-out or accept a bad break
    /// when the table offers a good shot, else hand it back or rerack; spot the 8.
    /// </summary>
    public RefereeOption ChooseOption(Ruling ruling, TablePosition position)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        ArgumentNullException.ThrowIfNull(position);
        var options = ruling.Options;
        if (options.Count == 0)
        {
            throw new ArgumentException("the ruling offers no options", nameof(ruling));
        }
        double q = Table.BestEase(position.ForCueBall(Ruleset.For(ruling.Next.Rules).CueBall(ruling.Next)), ruling.Next);
        if (options.Contains(RefereeOption.SpotEight))
        {
            return RefereeOption.SpotEight;
        }
        if (options.Contains(RefereeOption.Shoot) && options.Contains(RefereeOption.PassBack))
        {
            return q >= 0.4 ? RefereeOption.Shoot : RefereeOption.PassBack;
        }
        if (options.Contains(RefereeOption.Accept) && options.Contains(RefereeOption.Rerack))
        {
            return q >= 0.3 ? RefereeOption.Accept : RefereeOption.Rerack;
        }
        if (options.Contains(RefereeOption.Play) && options.Contains(RefereeOption.PutBack))
        {
            return ChooseAfterFoul(ruling, position, q);
        }
        return options[0];
    }

    /// <summary>The ease of a leave from which the incoming player takes the table after a foul (snooker's <c>play</c>).</summary>
    public const double PlayEase = 0.3;

    // After a foul (snooker): take a good shot as it lies; after a miss from a hard position, have
    // the offender try it again (replace: a new penalty, and a third miss with a full view loses the
    // frame); when the table lies badly for both, put the offender back in.
    private RefereeOption ChooseAfterFoul(Ruling ruling, TablePosition position, double q)
    {
        if (q >= PlayEase)
        {
            return RefereeOption.Play;
        }
        if (ruling.Options.Contains(RefereeOption.Replace))
        {
            return RefereeOption.Replace;
        }
        var offender = ruling.Choose(RefereeOption.PutBack).Next;
        double theirs = position.Cue is null ? 1 : Table.BestEase(position, offender);
        return theirs < q ? RefereeOption.PutBack : RefereeOption.Play;
    }

    /// <summary>True when the ruling keeps <paramref name="shooter"/> at the table or gives them the game: the shot was made.</summary>
    internal static bool Made(Ruling ruling, int shooter) =>
        ruling.GameOver ? ruling.Winner == shooter : ruling.Continue;

    /// <summary>The fewest simulations of a chosen pot, none of them potting, that make it a safety.</summary>
    internal const int SafetyEvidence = 10;

    /// <summary>
    /// How a chosen candidate is declared: a pot that none of at least <see cref="SafetyEvidence"/>
    /// simulations made is not meant to pot (it was chosen for what it leaves), so it is played as a
    /// safety and called as one where the game has a call; anything else as it is.
    /// </summary>
    internal static (ShotKind Kind, PocketId Pocket, Call? Call) Declared(Candidate candidate, Call? call, int pots, int simulations)
    {
        return ShotKinds.IsPot(candidate.Kind, candidate.Pocket) && pots == 0 && simulations >= SafetyEvidence
            // A nomination (snooker) stays: it names the ball to strike first, not a pot.
            ? (ShotKind.Safety, PocketId.None, call is null || call.IsNomination ? call : Call.Safety)
            : (candidate.Kind, candidate.Pocket, call);
    }

    private sealed record Root(TablePosition Position, Vec3 Cue, Vec3? Place)
    {
        // The position at rest, captured once; every worker restores it before each shot.
        public SimulationSnapshot? Snapshot { get; set; }
    }

    private sealed record Variation(int Root, Candidate Candidate, ShotSpec Shot, GameState Before);
}
