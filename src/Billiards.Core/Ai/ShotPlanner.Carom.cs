using System.Diagnostics;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;

namespace Billiards.Core.Ai;

/// <summary>
/// The computer player of three-cushion (<see cref="ThreeCushionRuleset"/>): a search over strokes
/// whose simulated outcome is a point.
/// </summary>
/// <remarks>
/// <list type="number">
/// <item>Strokes: for each object ball as the first ball, aims across the whole ball from one edge
/// to the other (<see cref="CaromLevel.Cuts"/> cut fractions of the two-radius window, the aim
/// angle asin(f 2R / d)), at <see cref="CaromLevel.Speeds"/> cue speeds and
/// <see cref="CaromLevel.Spins"/> tip offsets (running and reverse side with follow or draw); at
/// levels 4 and 5 also cushion-first strokes (<see cref="CaromLevel.BankAims"/> aims around the
/// circle). On the break only the red is the first ball. Every stroke is raised as far as the cue's
/// clearance needs (<see cref="CueClearance.Playable"/>).</item>
/// <item>First round: every stroke simulated once without error with the planner's physics and
/// judged by the referee; the strokes that score are kept.</item>
/// <item>Refinement: the scoring strokes, nearest to the middle of their run of neighbouring
/// scoring aims first, are simulated <see cref="CaromLevel.Samples"/> more times with the player's
/// own error (<see cref="SkillLevel.Execute"/>); the stroke with the most points wins. At level 5
/// each sample that scores is also judged by the next point it leaves
/// (<see cref="CaromPositionWeight"/> of <see cref="LeaveQuality"/>): the object balls close together
/// and the cue ball not frozen to either.</item>
/// <item>Without a scoring stroke: the stroke whose cue ball met both balls with the most cushions
/// before the second, else a soft stroke on the first ball (on the break, the red).</item>
/// </list>
/// Deterministic: every error sample draws from its own stream derived from the seed and the
/// stroke's and sample's indices, and the results are reduced in index order.
/// </remarks>
public sealed partial class ShotPlanner
{
    /// <summary>How much of a point's score the leave's quality is worth at level 5.</summary>
    public const double CaromPositionWeight = 0.3;

    /// <summary>A carom level's search: how many strokes it tries and how often it samples its own error.</summary>
    /// <param name="Cuts">Aims across each object ball.</param>
    /// <param name="Speeds">Cue speeds per aim.</param>
    /// <param name="Spins">Tip offsets per aim and speed.</param>
    /// <param name="BankAims">Cushion-first aims around the circle (0: none).</param>
    /// <param name="Keep">Scoring strokes refined.</param>
    /// <param name="Samples">Error samples per refined stroke.</param>
    /// <param name="Position">Judge a point by the next point it leaves.</param>
    public sealed record CaromLevel(int Cuts, int Speeds, int Spins, int BankAims, int Keep, int Samples, bool Position)
    {
        private static readonly CaromLevel[] All =
        [
            new(5, 2, 2, 0, 2, 2, false),
            new(7, 2, 3, 0, 3, 3, false),
            new(9, 3, 4, 0, 6, 6, false),
            new(11, 4, 6, 24, 10, 10, false),
            new(15, 4, 8, 36, 14, 16, true),
        ];

        /// <summary>The search of level <paramref name="level"/> (1 to 5).</summary>
        public static CaromLevel Of(int level) => All[Math.Clamp(level, SkillLevel.Min, SkillLevel.Max) - 1];
    }

    // Cue speeds (m/s), the first Speeds of them; and (side, height) tips, the first Spins.
    private static readonly double[] CaromSpeeds = [3.5, 2.6, 4.6, 5.6];
    private static readonly (double Side, double Height)[] CaromTips =
        [(0.35, 0.2), (-0.35, 0.2), (0, 0.3), (0.35, -0.25), (-0.35, -0.25), (0, -0.35), (0.5, 0), (-0.5, 0)];

    private Decision DecideCarom(GameState state, TablePosition position, SkillLevel skill, PlannerBudget budget, ulong seed)
    {
        var clock = Stopwatch.StartNew();
        var level = CaromLevel.Of(skill.Level);
        var referee = Referee.For(state.Rules, Table.Table, Table.R);
        var cue = position.Cue ?? throw new ArgumentException("the position has no cue ball", nameof(position));
        var strokes = CaromStrokes(state, position, cue, level);
        var snapshot = position.CreateSimulation(Model).CreateSnapshot();
        int threads = Math.Max(1, budget.Threads > 0 ? budget.Threads : Environment.ProcessorCount);
        var sims = new Simulation?[threads];
        var records = new ShotRecord[threads];
        for (int t = 0; t < threads; t++)
        {
            records[t] = new ShotRecord();
        }

        // First round: each stroke once, without error.
        var first = new Ruling[strokes.Count];
        var firstBalls = new BallId[strokes.Count];
        Parallel.For(0, threads, new ParallelOptions { MaxDegreeOfParallelism = threads }, t =>
        {
            for (int i = t; i < strokes.Count; i += threads)
            {
                first[i] = JudgeCarom(ref sims[t], records[t], snapshot, position, strokes[i], state, referee, out _);
                // The decision names the ball the stroke meets first (a cushion-first stroke's too).
                firstBalls[i] = ThreeCushionReferee.Read(records[t].Events, records[t].CueBall).FirstBall ?? BallId.None;
            }
        });
        int simulations = strokes.Count;
        var scoring = new List<int>();
        for (int i = 0; i < strokes.Count; i++)
        {
            if (Point(first[i]))
            {
                scoring.Add(i);
            }
        }
        if (scoring.Count == 0)
        {
            int best = Fallback(strokes, first, state, position);
            return CaromDecision(strokes[best], firstBalls[best], first[best], 0, 0, simulations, clock);
        }

        // The scoring strokes most surrounded by scoring neighbours (same speed and spin, the next aims) first.
        var kept = scoring.OrderByDescending(i => Neighbours(i, first, level)).ThenBy(i => i).Take(level.Keep).ToList();
        var means = new double[kept.Count];
        var points = new double[kept.Count];
        Parallel.For(0, threads, new ParallelOptions { MaxDegreeOfParallelism = threads }, t =>
        {
            for (int k = t; k < kept.Count; k += threads)
            {
                double sum = 0, made = 0;
                for (int s = 0; s < level.Samples; s++)
                {
                    var executed = skill.SearchStroke(strokes[kept[k]], new PlannerRandom(PlannerRandom.Derive(seed, kept[k], s + 1)), Table.R);
                    var ruling = JudgeCarom(ref sims[t], records[t], snapshot, position, executed, state, referee, out var after);
                    if (Point(ruling))
                    {
                        made++;
                        sum += 1 + (level.Position && !ruling.GameOver ? CaromPositionWeight * LeaveQuality(after, ruling.Next) : 0);
                    }
                }
                means[k] = sum / level.Samples;
                points[k] = made / level.Samples;
            }
        });
        simulations += kept.Count * level.Samples;
        int pick = 0;
        for (int k = 1; k < kept.Count; k++)
        {
            if (means[k] > means[pick])
            {
                pick = k;
            }
        }
        return CaromDecision(strokes[kept[pick]], firstBalls[kept[pick]], first[kept[pick]], points[pick], means[pick], simulations, clock);
    }

    private static Decision CaromDecision(ShotSpec shot, BallId firstBall, Ruling expected, double chance, double score, int simulations, Stopwatch clock) =>
        new(shot, null, null, false, ShotKind.Carom, firstBall, global::Billiards.Core.Table.PocketId.None, chance, score, simulations, clock.Elapsed.TotalMilliseconds)
        {
            ExpectedRuling = expected,
        };

    private Ruling JudgeCarom(ref Simulation? sim, ShotRecord record, SimulationSnapshot snapshot, TablePosition position, ShotSpec shot, GameState state, IReferee referee, out TablePosition after)
    {
        sim ??= position.CreateSimulation(Model);
        sim.Restore(snapshot);
        sim.Strike(shot, position.CueBall);
        sim.AdvanceTo(MaxShotTime);
        record.Capture(sim, 0, shot);
        after = TablePosition.After(record);
        return referee.Judge(state, record);
    }

    // The strokes of a level, in a fixed order: for each first ball, each cut, speed and tip; then the banks.
    private List<ShotSpec> CaromStrokes(GameState state, TablePosition position, Vec3 cue, CaromLevel level)
    {
        double r = Table.R;
        var strokes = new List<ShotSpec>();
        var firsts = state.Shot == 0 ? [BallSet.Red] : position.ObjectBalls.OrderBy(b => b.Value).ToList();
        void Add(double aimDeg)
        {
            for (int s = 0; s < level.Speeds; s++)
            {
                for (int p = 0; p < level.Spins; p++)
                {
                    var shot = new ShotSpec(CaromSpeeds[s], aimDeg, CaromTips[p].Side, CaromTips[p].Height);
                    strokes.Add(CueClearance.Playable(shot, Table.Table, r, cue, position.Positions));
                }
            }
        }
        foreach (var ball in firsts)
        {
            int i = position.IndexOf(ball);
            if (i < 0)
            {
                continue;
            }
            var to = position.Positions[i] - cue;
            double d = Math.Max(to.LengthXY, 2 * r + 1e-6);
            double centre = DeterministicMath.Atan2(to.Y, to.X) * 180 / Math.PI;
            for (int c = 0; c < level.Cuts; c++)
            {
                // Cut fractions from -0.9 to 0.9 of the full-ball window.
                double f = level.Cuts == 1 ? 0 : -0.9 + (1.8 * c / (level.Cuts - 1));
                Add(centre + (DeterministicMath.Asin(Math.Clamp(f * 2 * r / d, -1, 1)) * 180 / Math.PI));
            }
        }
        if (state.Shot > 0)
        {
            for (int a = 0; a < level.BankAims; a++)
            {
                Add(360.0 * a / level.BankAims);
            }
        }
        return strokes;
    }

    // Scoring strokes among the two neighbouring aims of the same ball, speed and tip.
    private static bool Point(Ruling ruling) => ruling.PartOf<ThreeCushionRulingPart>() is { Point: true };

    private static int Neighbours(int i, Ruling[] first, CaromLevel level)
    {
        int stride = level.Speeds * level.Spins;
        int n = 0;
        foreach (int j in (ReadOnlySpan<int>)[i - stride, i + stride])
        {
            n += j >= 0 && j < first.Length && Point(first[j]) ? 1 : 0;
        }
        return n;
    }

    // Without a point: the most cushions before the second ball; else a legal stroke (the red first on the break).
    private static int Fallback(List<ShotSpec> strokes, Ruling[] first, GameState state, TablePosition position)
    {
        int best = 0;
        double bestScore = double.NegativeInfinity;
        for (int i = 0; i < strokes.Count; i++)
        {
            var r = first[i];
            int cushions = r.PartOf<ThreeCushionRulingPart>()?.Cushions ?? 0;
            double score = (r.Legal ? 10 : 0) + (cushions >= 3 ? 0 : cushions) - (strokes[i].Speed / 10);
            if (score > bestScore)
            {
                (best, bestScore) = (i, score);
            }
        }
        return best;
    }

    /// <summary>
    /// How easy the next point is from <paramref name="after"/> for the shooter of
    /// <paramref name="next"/>, 0 to 1 (ours, a carom player's rule of thumb): the two object balls
    /// close together (1 touching, 0 a table's length apart), halved when the cue ball is frozen to a ball.
    /// </summary>
    public double LeaveQuality(TablePosition after, GameState next)
    {
        ArgumentNullException.ThrowIfNull(after);
        ArgumentNullException.ThrowIfNull(next);
        var cueBall = Ruleset.For(next.Rules).CueBall(next);
        var cue = after.ForCueBall(cueBall);
        var objects = cue.ObjectBalls.Select(b => after.IndexOf(b)).Where(i => i >= 0).Select(i => after.Positions[i]).ToList();
        if (objects.Count < 2 || cue.Cue is not { } c)
        {
            return 0;
        }
        double quality = 1 - Math.Clamp(((objects[0] - objects[1]).LengthXY - (2 * Table.R)) / Table.Table.Length, 0, 1);
        bool frozen = objects.Any(o => (o - c).LengthXY <= (2 * Table.R) + ThreeCushionReferee.FrozenGap);
        return frozen ? quality / 2 : quality;
    }
}
