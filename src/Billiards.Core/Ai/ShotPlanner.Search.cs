using System.Diagnostics;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

namespace Billiards.Core.Ai;

/// <summary>The search of a decision (the class remarks of <see cref="ShotPlanner"/>): its workers, rounds and refinement.</summary>
public sealed partial class ShotPlanner
{
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
            sim.Strike(shot, root.Position.CueBall);
            sim.AdvanceTo(MaxShotTime);
            _record.Capture(sim, 0, shot);
            return referee.Judge(v.Before, _record);
        }
    }

    private sealed partial class Search(ShotPlanner planner, GameState state, TablePosition position, SkillLevel level, PlannerBudget budget, ulong seed, Stopwatch clock)
    {
        private readonly PlannerTable _table = planner.Table;
        // The search reads no ruling's sentence; the decision's expected ruling (suggest writes it) has its words.
        private readonly IReferee _referee = Referee.Wordless(state.Rules, planner.Table.Table, planner.Table.R);
        private readonly IReferee _worded = Referee.For(state.Rules, planner.Table.Table, planner.Table.R);
        private int _simulations;
        private double[] _squares = [];

        // The pot chance below which this player would rather play safe (0: none), and the
        // search's pot counts once the middle round has given every field member enough samples.
        // A frame already decided (the last ball left, the opponent more than its points behind)
        // has no safety worth playing: any pot is attempted.
        private readonly double _sureChance = Ruleset.For(state.Rules).Policy.PlaysSafeBelowSurePot && !Decided(state, position) ? level.SurePotChance : 0;
        private List<Variation> _variations = [];
        private int[]? _pots;

        public Decision Run()
        {
            var roots = Roots();
            foreach (var r in roots)
            {
                r.Snapshot = r.Position.CreateSimulation(planner.Model).CreateSnapshot();
            }
            var variations = _variations = new List<Variation>();
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
            var (screenTop, screenSamples) = level.Break is { } noiseBreak && SearchesNoiseBreak
                ? (noiseBreak.ScreenTop, noiseBreak.ScreenSamples)
                : (level.ScreenTop, level.ScreenSamples);
            if (screenTop > 0 && screenSamples > 0)
            {
                field = WithSafeties(field, screenTop);
                Simulate(workers, variations, field, samples, screenSamples, sum, pots, count);
                samples += screenSamples;
                _pots = pots;
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
            var expected = workers[0].Run(chosen, chosen.Shot, _worded, level).Ruling;
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

        // The one place a candidate shot's cue elevation is decided: the cue's clearance over the
        // rails and the balls behind the cue ball.
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
            return mean - Math.Sqrt(variance / n) - Shortfall(i, count);
        }

        private bool IsPot(int i) => ShotKinds.IsPot(_variations[i].Candidate.Kind, _variations[i].Candidate.Pocket);

        // What a pot attempt loses for each unit of chance it falls short of the player's sure
        // chance (SkillLevel.SurePotChance), judged once it has at least SafetyEvidence samples
        // (the first round's two or three would throw good pots out by bad luck).
        private double Shortfall(int i, int[] count)
        {
            if (_sureChance <= 0 || _pots is null || count[i] < SafetyEvidence || !IsPot(i))
            {
                return 0;
            }
            return ShortfallWeight * Math.Max(0, _sureChance - ((double)_pots[i] / count[i]));
        }

        // The middle round's field: the first round's best, and where pot attempts must be sure,
        // the best safeties besides: the first round's few samples rank pots by their mean alone,
        // and a field of pots only would leave the pot-or-safety choice no safety to choose.
        private List<int> WithSafeties(List<int> ranked, int top)
        {
            var field = ranked.Take(top).ToList();
            if (_sureChance > 0)
            {
                field.AddRange(ranked.Skip(top).Where(i => !IsPot(i)).Take(ScreenedSafeties));
            }
            return field;
        }

        // Best mean first (less a pot's shortfall once it counts), ties by index (so the order
        // never depends on the threads).
        private List<int> Ranked(IEnumerable<int> which, double[] sum, int[] count) =>
            [.. which.Where(i => count[i] > 0).OrderByDescending(i => (sum[i] / count[i]) - Shortfall(i, count)).ThenBy(i => i)];

        private List<int> Ranked(int n, double[] sum, int[] count) => Ranked(Enumerable.Range(0, n), sum, count);

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
                var shot = level.SearchStroke(variations[v].Shot, random, _table.R);
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
    }
}
