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
/// quality of the position for the next shot (<see cref="PlannerTable.PositionQuality"/>, with the
/// shooter's own error) less 0.04 per ball left without a straight way to a pocket
/// (<see cref="PlannerTable.ProblemBalls"/>), a legal miss 0.5 less 0.4 times the opponent's best shot (how
/// safeties are judged; the opponent judged at least as good as the player,
/// <see cref="SkillLevel.OpponentAimStdDeg"/>), a foul 0.08.</item>
/// <item>Refinement: the best variations are simulated again with more error samples, at levels 4
/// and 5 in two rounds (at level 5 the best 40 with 10 more, the best 10 of those with 60 more);
/// of the last round the best mean less its standard error wins, so that of two shots with nearly
/// the same mean the surer one is played. A chosen pot that none of its (at least ten) simulations
/// made is played, and called where the game calls, as a safety: it was chosen for what it leaves.</item>
/// </list>
/// Determinism: every simulation draws its error from its own stream, derived from the seed and
/// the variation's and sample's indices, and results are reduced in index order, so the threads
/// (and their number) do not change the decision unless the time cap cuts the search short.
/// </remarks>
public sealed class ShotPlanner
{
    private const double MaxShotTime = 120;
    private const double MaxNormalSpeed = 6.5;

    // A level takes the first of these (sorted before use): the strongest players also try the
    // speeds in between.
    private static readonly double[] SpeedFactors = [1.0, 1.5, 2.3, 0.75, 3.2, 1.2, 1.85];

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
        var clock = Stopwatch.StartNew();
        var search = new Search(this, state, position, level, budget, seed, clock);
        return search.Run();
    }

    /// <summary>Decides with a level number and a time cap: the short form for the game.</summary>
    public Decision Decide(GameState state, Simulation simulation, int level, int budgetMs, ulong seed) =>
        Decide(state, TablePosition.Of(simulation), SkillLevel.Of(level), new PlannerBudget(budgetMs), seed);

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
        double q = Table.BestEase(position, ruling.Next);
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
        return options[0];
    }

    /// <summary>
    /// The score of a judged shot for the player who shot it (see the class remarks), with the
    /// balls after it in <paramref name="after"/>, as <paramref name="level"/> judges it: levels
    /// without look-ahead see only the ruling; the others also the next shot, their own judged with
    /// their own error (<see cref="SkillLevel.PositionAimStdDeg"/>), the opponent's as if the
    /// opponent were at least as good (<see cref="SkillLevel.OpponentAimStdDeg"/>).
    /// </summary>
    public double Score(GameState before, Ruling ruling, TablePosition after, SkillLevel level)
    {
        ArgumentNullException.ThrowIfNull(before);
        ArgumentNullException.ThrowIfNull(ruling);
        ArgumentNullException.ThrowIfNull(level);
        bool look = level.LookAhead > 0;
        if (ruling.GameOver)
        {
            return ruling.Winner is not { } w ? 0.5 : w == before.Shooter ? 1 : 0;
        }
        if (before.PushOut)
        {
            if (!ruling.Legal)
            {
                return 0.1;
            }
            // The opponent shoots a good leave and hands back a bad one: leave one in between.
            double q = look ? Table.BestEase(after, ruling.Next) : 0.5;
            return 0.4 - 0.3 * Math.Abs(2 * q - 1);
        }
        if (ruling.Continue)
        {
            // Position counts, but less than the pot: for a strong player a moderate next shot is
            // still likely, and the pot in hand is certain. Each ball left without a straight way
            // to a pocket costs a little, so that shots which free a cluster are preferred.
            double q = look ? Table.PositionQuality(after, ruling.Next, level.PositionAimStdDeg) : 0.5;
            double problems = look ? 0.04 * Table.ProblemBalls(after, ruling.Next) : 0;
            return 0.7 + 0.3 * q - problems;
        }
        if (!ruling.Legal)
        {
            return 0.08;
        }
        double opponent = look ? Table.BestEase(after, ruling.Next, level.OpponentAimStdDeg) : 0.5;
        return 0.5 - 0.4 * opponent;
    }

    /// <summary>
    /// The cue's aim (deg) that sends the candidate's first ball along its direction with the given
    /// tip, corrected for throw (the object ball dragged towards the cue ball's path by ball-ball
    /// friction) and for squirt (the cue ball leaving off the cue's line with side spin).
    /// </summary>
    internal double AimFor(Candidate c, Vec3 cue, double tipSide, double tipHeight)
    {
        var p = Table.Physics;
        double r = Table.R;
        var aimPoint = c.AimPoint;
        if (c.Direction != Vec3.Zero)
        {
            var u = c.Direction;
            var ghost = c.Contact - u * (2 * r);
            double mu = p.MuBModel == BallBallFriction.Constant ? p.MuB : 0.06;
            for (int iteration = 0; iteration < 3; iteration++)
            {
                var v = (ghost - cue).XY.Normalized();
                double sin = v.X * c.Direction.Y - v.Y * c.Direction.X;
                double cos = Vec3.Dot(v, c.Direction);
                if (cos <= 0.05)
                {
                    break;
                }
                double s = Math.Abs(sin);
                // A stunned ball slides across the object ball; a rolling one also slides vertically,
                // which takes friction away from the sideways throw (Alciatore, TP A.14).
                double roll = Math.Abs(tipHeight) > 0.1 ? 1 : 0.5;
                double slip = Math.Sqrt(s * s + roll * roll * cos * cos);
                double tan = Math.Min(mu * s / Math.Max(slip, 1e-9), 2 * s / (7 * (1 + p.EB) * cos));
                double throwAngle = Math.Atan(tan) * Math.Sign(sin);
                double ca = Math.Cos(throwAngle);
                double sa = Math.Sin(throwAngle);
                var turned = new Vec3(c.Direction.X * ca - c.Direction.Y * sa, c.Direction.X * sa + c.Direction.Y * ca, 0);
                ghost = c.Contact - turned * (2 * r);
            }
            aimPoint = ghost;
        }
        var d = aimPoint - cue;
        double aim = Math.Atan2(d.Y, d.X) * 180 / Math.PI;
        aim -= CueStrike.SquirtAngle(tipSide, p.M / p.CueEndMass) * 180 / Math.PI;
        return aim;
    }

    /// <summary>The step (deg) between the aims tried without error either side of a pot's geometric aim.</summary>
    public const double AimTrialStepDeg = 0.3;

    // Halvings of the step at each end of the potting range: its ends are then known to a quarter step.
    private const int EdgeHalvings = 2;

    /// <summary>
    /// The aim (deg) in the middle of the range of aims that pot: <paramref name="pots"/> says whether
    /// the shot aimed at an angle pots without error. It is tried at <paramref name="trials"/> steps of
    /// <see cref="AimTrialStepDeg"/> either side of <paramref name="aim"/>; of the runs of potting aims the
    /// one whose middle is nearest <paramref name="aim"/> is taken, and each of its ends inside the tried
    /// range is found to a quarter step by halving. Without a potting aim, <paramref name="aim"/> itself.
    /// </summary>
    /// <returns>The centred aim and the number of trials it took.</returns>
    internal static (double AimDeg, int Trials) CentredAim(Func<double, bool> pots, double aim, int trials)
    {
        ArgumentNullException.ThrowIfNull(pots);
        int n = 2 * trials + 1;
        Span<bool> made = stackalloc bool[n];
        for (int j = 0; j < n; j++)
        {
            made[j] = pots(aim + (j - trials) * AimTrialStepDeg);
        }
        int tried = n;
        int lo = -1, hi = -1;
        double nearest = double.MaxValue;
        for (int j = 0; j < n;)
        {
            if (!made[j])
            {
                j++;
                continue;
            }
            int start = j;
            while (j < n && made[j])
            {
                j++;
            }
            double off = Math.Abs((start + j - 1) / 2.0 - trials);
            if (off < nearest)
            {
                (nearest, lo, hi) = (off, start, j - 1);
            }
        }
        if (lo < 0)
        {
            return (aim, tried);
        }
        double At(int j) => aim + (j - trials) * AimTrialStepDeg;
        double Edge(double inside, double outside)
        {
            for (int k = 0; k < EdgeHalvings; k++)
            {
                double middle = (inside + outside) / 2;
                tried++;
                if (pots(middle))
                {
                    inside = middle;
                }
                else
                {
                    outside = middle;
                }
            }
            return (inside + outside) / 2;
        }
        double lower = lo > 0 ? Edge(At(lo), At(lo - 1)) : At(lo);
        double upper = hi < n - 1 ? Edge(At(hi), At(hi + 1)) : At(hi);
        return ((lower + upper) / 2, tried);
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
            ? (ShotKind.Safety, PocketId.None, call is null ? null : Call.Safety)
            : (candidate.Kind, candidate.Pocket, call);
    }

    private sealed record Root(TablePosition Position, Vec3 Cue, Vec3? Place)
    {
        // The position at rest, captured once; every worker restores it before each shot.
        public SimulationSnapshot? Snapshot { get; set; }
    }

    private sealed record Variation(int Root, Candidate Candidate, ShotSpec Shot, GameState Before);

    private sealed class Worker(ShotPlanner planner, IReadOnlyList<Root> roots)
    {
        private readonly Simulation?[] _sims = new Simulation?[roots.Count];
        private readonly ShotRecord _record = new();

        public (double Score, bool Pot, Ruling Ruling) Run(Variation v, ShotSpec shot, IReferee referee, SkillLevel level)
        {
            var ruling = Judge(v, shot, referee);
            var after = TablePosition.After(_record);
            double score = planner.Score(v.Before, ruling, after, level);
            return (score, Made(ruling, v.Before.Shooter), ruling);
        }

        /// <summary>Whether the shot, struck as given, pots for the shooter (judged, not scored).</summary>
        public bool Pots(Variation v, ShotSpec shot, IReferee referee) => Made(Judge(v, shot, referee), v.Before.Shooter);

        private Ruling Judge(Variation v, ShotSpec shot, IReferee referee)
        {
            var root = roots[v.Root];
            var sim = _sims[v.Root] ??= root.Position.CreateSimulation(planner.Model);
            sim.Restore(root.Snapshot!);
            sim.Strike(shot);
            sim.AdvanceTo(MaxShotTime);
            _record.Capture(sim, 0, shot);
            return referee.Judge(v.Before, _record);
        }
    }

    private sealed class Search(ShotPlanner planner, GameState state, TablePosition position, SkillLevel level, PlannerBudget budget, ulong seed, Stopwatch clock)
    {
        private readonly PlannerTable _table = planner.Table;
        private readonly IReferee _referee = Referee.For(state.Rules, planner.Table.Table, planner.Table.R);
        private int _simulations;
        private double[] _squares = [];

        public Decision Run()
        {
            var roots = Roots();
            foreach (var r in roots)
            {
                r.Snapshot = r.Position.CreateSimulation(planner.Model).CreateSnapshot();
            }
            var variations = new List<Variation>();
            int perRoot = roots.Count > 1 ? Math.Max(3, level.Candidates / 2) : level.Candidates;
            for (int i = 0; i < roots.Count; i++)
            {
                AddVariations(i, roots[i], perRoot, variations);
            }
            int threads = budget.Threads > 0 ? budget.Threads : Environment.ProcessorCount;
            var workers = new Worker[threads];
            for (int w = 0; w < threads; w++)
            {
                workers[w] = new Worker(planner, roots);
            }

            // Every shot as the cue can play it (raised over a rail or a ball behind the cue ball),
            // before its aim is centred and again after, for the aim it ends with.
            Playable(roots, variations);
            if (level.AimTrials > 0)
            {
                CentreAims(workers, variations);
                Playable(roots, variations);
            }

            // Round 1: every variation with a few error samples; then the best again with more,
            // and the best of those with many more: the winner comes from the last round, so its
            // mean rests on enough samples that a lucky few do not decide.
            var sum = new double[variations.Count];
            _squares = new double[variations.Count];
            var pots = new int[variations.Count];
            var count = new int[variations.Count];
            int first = Math.Clamp(level.FirstRoundSimulations / Math.Max(1, variations.Count), 1, level.Samples);
            Simulate(workers, variations, Enumerable.Range(0, variations.Count), 0, first, sum, pots, count);
            int samples = first;
            var field = Ranked(variations.Count, sum, count);
            if (level.ScreenTop > 0 && level.ScreenSamples > 0)
            {
                field = field.Take(level.ScreenTop).ToList();
                Simulate(workers, variations, field, samples, level.ScreenSamples, sum, pots, count);
                samples += level.ScreenSamples;
                field = Ranked(field, sum, count);
            }
            var finalists = field.Take(Math.Max(1, level.RefineTop)).ToList();
            if (level.RefineSamples > 0)
            {
                Simulate(workers, variations, finalists, samples, level.RefineSamples, sum, pots, count);
            }
            // The winner by a cautious mean: its mean less one standard error, so that of two shots
            // with nearly the same mean the one whose outcome varies less (the surer pot) wins.
            int best = finalists.Count > 0
                ? finalists.OrderByDescending(i => Cautious(i, sum, count)).ThenBy(i => i).First()
                : 0;
            var chosen = variations[best];
            var (kind, pocket, declared) = Declared(chosen.Candidate, chosen.Before.Call, pots[best], count[best]);
            chosen = chosen with
            {
                Candidate = chosen.Candidate with { Kind = kind, Pocket = pocket },
                Before = chosen.Before with { Call = declared },
            };
            var root = roots[chosen.Root];
            var expected = workers[0].Run(chosen, chosen.Shot, _referee, level).Ruling;
            _simulations++;
            var c = chosen.Candidate;
            return new Decision(
                chosen.Shot,
                root.Place,
                chosen.Before.Call,
                chosen.Before.PushOut,
                c.Kind,
                c.Target,
                c.Pocket,
                count[best] > 0 ? (double)pots[best] / count[best] : 0,
                count[best] > 0 ? sum[best] / count[best] : 0,
                _simulations,
                clock.Elapsed.TotalMilliseconds)
            {
                ExpectedRuling = expected,
            };
        }

        // Every pot's aim moved to the middle of its potting range (CentredAim), a variation per
        // work item; each result depends on its variation alone, so not on the threads (unless the
        // time cap stops the work, like the search's rounds).
        private void CentreAims(Worker[] workers, List<Variation> variations)
        {
            var which = Enumerable.Range(0, variations.Count)
                .Where(i => ShotKinds.IsPot(variations[i].Candidate.Kind, variations[i].Candidate.Pocket))
                .ToArray();
            var aims = new double[which.Length];
            var trials = new int[which.Length];
            var done = RunUntilCap(workers, which.Length, (worker, j) =>
            {
                var v = variations[which[j]];
                (aims[j], trials[j]) = CentredAim(a => worker.Pots(v, v.Shot with { AimDeg = a }, _referee), v.Shot.AimDeg, level.AimTrials);
            });
            // Past the time cap the rest keep their geometric aim.
            for (int j = 0; j < which.Length; j++)
            {
                if (!done[j])
                {
                    continue;
                }
                var v = variations[which[j]];
                variations[which[j]] = v with { Shot = v.Shot with { AimDeg = aims[j] } };
                _simulations += trials[j];
            }
        }

        private void Playable(List<Root> roots, List<Variation> variations)
        {
            for (int i = 0; i < variations.Count; i++)
            {
                var v = variations[i];
                var root = roots[v.Root];
                variations[i] = v with { Shot = CueClearance.Playable(v.Shot, _table.Table, _table.R, root.Cue, root.Position.Positions) };
            }
        }

        private double Cautious(int i, double[] sum, int[] count)
        {
            if (count[i] == 0)
            {
                return double.NegativeInfinity;
            }
            double n = count[i];
            double mean = sum[i] / n;
            double variance = Math.Max(0, _squares[i] / n - mean * mean);
            return mean - Math.Sqrt(variance / n);
        }

        // Best mean first, ties by index (so the order never depends on the threads).
        private static List<int> Ranked(IEnumerable<int> which, double[] sum, int[] count) =>
            [.. which.Where(i => count[i] > 0).OrderByDescending(i => sum[i] / count[i]).ThenBy(i => i)];

        private static List<int> Ranked(int n, double[] sum, int[] count) => Ranked(Enumerable.Range(0, n), sum, count);

        // Work items 0..count-1 shared out to the workers, one thread each, until the time cap: an
        // item is run whole by one worker, and the result says which ran (to reduce in item order,
        // whichever thread ran what). On the caller's scheduler: a game runs the search on
        // low-priority threads of its own, and Parallel.For would otherwise take the shared pool.
        private bool[] RunUntilCap(Worker[] workers, int count, Action<Worker, int> item)
        {
            var done = new bool[count];
            int next = -1;
            double cap = budget.Milliseconds;
            var options = new ParallelOptions { MaxDegreeOfParallelism = workers.Length, TaskScheduler = TaskScheduler.Current };
            Parallel.For(0, workers.Length, options, w =>
            {
                int i;
                while ((i = Interlocked.Increment(ref next)) < count && clock.Elapsed.TotalMilliseconds <= cap)
                {
                    item(workers[w], i);
                    done[i] = true;
                }
            });
            return done;
        }

        private void Simulate(Worker[] workers, List<Variation> variations, IEnumerable<int> which, int firstSample, int samples, double[] sum, int[] pots, int[] count)
        {
            var items = which.SelectMany(v => Enumerable.Range(firstSample, samples).Select(s => (v, s))).ToArray();
            var scores = new double[items.Length];
            var made = new bool[items.Length];
            var done = RunUntilCap(workers, items.Length, (worker, i) =>
            {
                var (v, s) = items[i];
                var random = new PlannerRandom(PlannerRandom.Derive(seed, v, s));
                var shot = level.Execute(variations[v].Shot, random);
                (scores[i], made[i], _) = worker.Run(variations[v], shot, _referee, level);
            });
            // Reduced in item order, whichever thread ran what.
            for (int i = 0; i < items.Length; i++)
            {
                if (done[i])
                {
                    int v = items[i].v;
                    sum[v] += scores[i];
                    _squares[v] += scores[i] * scores[i];
                    pots[v] += made[i] ? 1 : 0;
                    count[v]++;
                    _simulations++;
                }
            }
        }

        private List<Root> Roots()
        {
            var region = state.Shot == 0 ? BallInHand.Kitchen : state.BallInHand;
            if (region == BallInHand.None && position.Cue is { } cue)
            {
                return [new Root(position, cue, null)];
            }
            if (region == BallInHand.None)
            {
                region = BallInHand.Table;
            }
            var spots = state.Shot == 0 ? BreakSpots() : Placements(region);
            return [.. spots.Select(p => new Root(position.With(BallId.Cue, p), p, p))];
        }

        private List<Vec3> BreakSpots()
        {
            var t = _table.Table;
            double r = _table.R;
            double x = -t.HalfLength / 2 - 2 * r;
            var spots = new List<Vec3> { new(x, 0, r) };
            if (level.Level >= 3)
            {
                spots.Add(new Vec3(x, 0.45 * t.HalfWidth, r));
                spots.Add(new Vec3(x, -0.45 * t.HalfWidth, r));
            }
            return [.. spots.Where(p => position.CanPlace(p, BallInHand.Kitchen, t, r, BallId.Cue))];
        }

        private List<Vec3> Placements(BallInHand region)
        {
            var t = _table.Table;
            double r = _table.R;
            var scored = new List<(Vec3 P, double Ease)>();
            var without = position.Without(BallId.Cue);
            foreach (var target in PlannerTable.LegalTargets(state, without))
            {
                var o = without.Positions[without.IndexOf(target)];
                foreach (var pocket in _table.Pockets)
                {
                    var aim = _table.AimPoint(pocket);
                    var u = (aim - o).XY.Normalized();
                    if (_table.Window(pocket, u) <= 0 || _table.Blocked(without, o, aim, target))
                    {
                        continue;
                    }
                    var ghost = _table.Ghost(o, aim);
                    foreach (double cutDeg in (ReadOnlySpan<double>)[0, 15, -15, 30, -30])
                    {
                        double a = cutDeg * Math.PI / 180;
                        var back = new Vec3(u.X * Math.Cos(a) - u.Y * Math.Sin(a), u.X * Math.Sin(a) + u.Y * Math.Cos(a), 0);
                        foreach (double distance in (ReadOnlySpan<double>)[0.15, 0.3, 0.55])
                        {
                            var p = (ghost - back * distance) with { Z = r };
                            if (without.CanPlace(p, region, t, r, BallId.Cue))
                            {
                                double ease = _table.DirectEase(without.With(BallId.Cue, p), p, target, pocket);
                                if (ease > 0)
                                {
                                    scored.Add((p, ease - 0.02 * Math.Abs(cutDeg) / 15));
                                }
                            }
                        }
                    }
                }
            }
            var chosen = new List<Vec3>();
            foreach (var (p, _) in scored.OrderByDescending(s => s.Ease))
            {
                if (chosen.Count >= level.Placements)
                {
                    break;
                }
                if (chosen.All(q => (q - p).LengthXY > 0.1))
                {
                    chosen.Add(p);
                }
            }
            if (chosen.Count == 0)
            {
                // Nothing to pot: a spot with a clear look at a target, else any free spot.
                var grid = new List<Vec3>();
                for (double gx = -0.9; gx <= 0.9; gx += 0.15)
                {
                    for (double gy = -0.8; gy <= 0.8; gy += 0.2)
                    {
                        var p = new Vec3(gx * (t.HalfLength - r), gy * (t.HalfWidth - r), r);
                        if (without.CanPlace(p, region, t, r, BallId.Cue))
                        {
                            grid.Add(p);
                        }
                    }
                }
                var targets = PlannerTable.LegalTargets(state, without);
                chosen.AddRange(grid.Where(p => targets.Any(b => !_table.Blocked(without, p, without.Positions[without.IndexOf(b)], b))).Take(2));
                if (chosen.Count == 0 && grid.Count > 0)
                {
                    chosen.Add(grid[0]);
                }
            }
            return chosen;
        }

        private void AddVariations(int rootIndex, Root root, int candidates, List<Variation> variations)
        {
            var cue = root.Cue;
            if (state.Shot == 0)
            {
                AddBreak(rootIndex, root, variations);
                return;
            }
            var pots = CandidateGenerator.Pots(_table, state, root.Position, cue)
                .OrderByDescending(c => c.Prior).Take(candidates).ToList();
            var safeties = CandidateGenerator.Safeties(_table, state, root.Position, cue)
                .Take(level.Level >= 3 ? candidates / 2 + 2 : 2).ToList();
            if (pots.Count == 0 && safeties.Count == 0)
            {
                safeties = CandidateGenerator.LastResort(_table, state, root.Position, cue);
            }
            bool call = Ruleset.For(state.Rules).NeedsCall(state);
            var before = state with { Placement = root.Place, PushOut = false };
            foreach (var c in pots)
            {
                var withCall = before with { Call = call ? new Call(c.Called, c.Pocket) : null };
                Vary(rootIndex, c, cue, withCall, level.Speeds, level.Spins, variations);
            }
            foreach (var c in safeties)
            {
                var withCall = before with { Call = call ? Call.Safety : null };
                Vary(rootIndex, c, cue, withCall, Math.Min(level.Speeds, 3), Math.Min(level.Spins, 3), variations);
            }
            // 9-ball and 10-ball: the shot after the break may be a push-out (no contact needed).
            if (level.LookAhead > 0 && Ruleset.For(state.Rules).MayPushOut(state)
                && pots.All(c => c.Prior < 0.2))
            {
                var push = state with { Placement = root.Place, PushOut = true, Call = null };
                foreach (var c in safeties.Take(3))
                {
                    Vary(rootIndex, c with { Kind = ShotKind.PushOut }, cue, push, 2, 1, variations);
                }
            }
        }

        private void AddBreak(int rootIndex, Root root, List<Variation> variations)
        {
            var balls = root.Position.Enumerate().Where(b => !b.Id.IsCue).ToList();
            if (balls.Count == 0)
            {
                return;
            }
            var foot = Setup.Initializer.FootSpot(_table.Table, _table.R);
            var apex = balls.OrderBy(b => (b.Position - foot).LengthXY).First();
            var before = state with { Placement = root.Place, Call = null, PushOut = false };
            var n = (apex.Position - root.Cue).XY.Normalized();
            var side = new Vec3(-n.Y, n.X, 0);
            var offsets = level.Level >= 3 ? new[] { 0.0, 0.3, -0.3 } : [0.0];
            var speeds = level.Level >= 2 ? new[] { 6.0, 7.5 } : [6.5];
            foreach (double offset in offsets)
            {
                var aimPoint = apex.Position + side * (offset * _table.R);
                var c = new Candidate(ShotKind.Break, apex.Id, apex.Id, PocketId.None, apex.Position, Vec3.Zero, aimPoint, 7, 0.5);
                foreach (double speed in speeds)
                {
                    var d = aimPoint - root.Cue;
                    var shot = new ShotSpec(speed, Math.Atan2(d.Y, d.X) * 180 / Math.PI, 0, -0.2, 0);
                    variations.Add(new Variation(rootIndex, c, shot, before));
                }
            }
        }

        private void Vary(int rootIndex, Candidate c, Vec3 cue, GameState before, int speeds, int spins, List<Variation> variations)
        {
            var factors = SpeedFactors.Take(speeds).Order().ToArray();
            for (int k = 0; k < spins; k++)
            {
                var (sideTip, height, elevation) = SpinSet[k];
                double aim = planner.AimFor(c, cue, sideTip, height);
                foreach (double f in factors)
                {
                    double speed = Math.Min(MaxNormalSpeed, c.BaseSpeed * f);
                    variations.Add(new Variation(rootIndex, c, new ShotSpec(speed, aim, sideTip, height, elevation), before));
                }
            }
        }
    }
}
