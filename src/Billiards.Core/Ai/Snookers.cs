using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>One snookered 8-ball position: the shooter on the solids, every straight way to them blocked.</summary>
/// <param name="State">The game before the shot (shooter 0 on the solids, no ball in hand).</param>
/// <param name="Position">The balls at rest.</param>
public sealed record SnookerPosition(GameState State, TablePosition Position);

/// <summary>What the computer player did from a set of snookered positions.</summary>
/// <param name="Positions">Positions played.</param>
/// <param name="Shots">Shots struck (each position's decision, executed with the level's error, several times).</param>
/// <param name="NoContact">Shots that touched no object ball.</param>
/// <param name="Fouls">Shots with any foul.</param>
/// <param name="Jumps">Decisions that were jump strokes (elevation from <see cref="SkillLevel.JumpTipElevationDeg"/>).</param>
/// <param name="Unplayable">Decisions below the cue's clearance (<see cref="Cue.CueClearance"/>): must be 0.</param>
public sealed record SnookerResult(int Positions, int Shots, int NoContact, int Fouls, int Jumps, int Unplayable);

/// <summary>
/// Snookered positions and the computer player's fouls from them: the measure of what jump shots
/// change. Everything follows from the seeds, so a run repeats bit for bit (with a single thread
/// and a budget the search never reaches).
/// </summary>
public static class Snookers
{
    /// <summary>
    /// <paramref name="count"/> positions from <paramref name="seed"/>: the shooter's one or two
    /// solids each hidden behind a stripe lying 0.15-0.35 m before the cue ball on its line, the 8
    /// and three more stripes anywhere; a position is kept only when no straight way to a solid is free.
    /// </summary>
    public static IReadOnlyList<SnookerPosition> Positions(TableSpec table, double radius, int count, ulong seed)
    {
        ArgumentNullException.ThrowIfNull(table);
        var planner = new PlannerTable(table, PhysicsParams.Default with { R = radius });
        var random = new PlannerRandom(seed);
        var result = new List<SnookerPosition>();
        double hx = table.HalfLength - (3 * radius), hy = table.HalfWidth - (3 * radius);
        Vec3 Anywhere() => new(((2 * random.NextDouble()) - 1) * hx, ((2 * random.NextDouble()) - 1) * hy, radius);
        for (int attempt = 0; result.Count < count && attempt < 1000 * count; attempt++)
        {
            var balls = new List<(BallId Id, Vec3 Position)>();
            bool Free(Vec3 p) => Math.Abs(p.X) <= hx && Math.Abs(p.Y) <= hy && balls.All(b => (b.Position - p).LengthXY > (2 * radius) + 0.002);
            var cue = Anywhere();
            var cueBall = BallSet.Pool.CueBalls[0];
            balls.Add((cueBall, cue));
            int solids = 1 + (int)(random.NextDouble() * 2);
            int stripe = 9;
            bool ok = true;
            for (int k = 0; k < solids && ok; k++)
            {
                double angle = 2 * Math.PI * random.NextDouble();
                var u = new Vec3(DeterministicMath.Cos(angle), DeterministicMath.Sin(angle), 0);
                var target = cue + (u * (0.6 + (0.8 * random.NextDouble())));
                var blocker = cue + (u * (0.15 + (0.2 * random.NextDouble()))) + (new Vec3(-u.Y, u.X, 0) * (radius * ((random.NextDouble() * 1.2) - 0.6)));
                ok = Free(target) && Free(blocker);
                balls.Add((new BallId(1 + k), target));
                balls.Add((new BallId(stripe++), blocker));
            }
            for (int k = 0; ok && k < 4; k++)
            {
                var p = Anywhere();
                ok = Free(p);
                balls.Add((k == 0 ? new BallId(8) : new BallId(stripe++), p));
            }
            if (!ok)
            {
                continue;
            }
            var position = new TablePosition(balls, cueBall);
            var state = new GameState(GameRules.EightBall) { Shot = 12, Part = new EightBallPart { Groups = new PerPlayer<BallGroup>(BallGroup.Solids, BallGroup.Stripes) } };
            if (PlannerTable.LegalTargets(state, position).All(t => planner.Blocked(position, cue, position.Positions[position.IndexOf(t)], t)))
            {
                result.Add(new SnookerPosition(state, position));
            }
        }
        return result;
    }

    /// <summary>
    /// Plays each position: the planner's decision at <paramref name="level"/>, struck
    /// <paramref name="tries"/> times with the level's own error, each judged by the referee.
    /// </summary>
    public static SnookerResult Measure(ShotPlanner planner, IReadOnlyList<SnookerPosition> positions, int level, int tries, ulong seed, PlannerBudget budget)
    {
        ArgumentNullException.ThrowIfNull(planner);
        ArgumentNullException.ThrowIfNull(positions);
        var skill = SkillLevel.Of(level);
        var referee = Referee.For(GameRules.EightBall, planner.Table.Table, planner.Table.R);
        var record = new ShotRecord();
        int shots = 0, noContact = 0, fouls = 0, jumps = 0, unplayable = 0;
        for (int i = 0; i < positions.Count; i++)
        {
            var (state, position) = (positions[i].State, positions[i].Position);
            var decision = planner.Decide(state, position, skill, budget, PlannerRandom.Derive(seed, i, 1));
            var cue = position.Cue!.Value;
            var playable = Cue.CueClearance.Playable(decision.Shot, planner.Table.Table, planner.Table.R, cue, position.Positions);
            unplayable += playable.ElevationDeg > decision.Shot.ElevationDeg + 1e-9 ? 1 : 0;
            jumps += decision.Shot.ElevationDeg >= SkillLevel.JumpTipElevationDeg ? 1 : 0;
            var before = state with { Call = decision.Call };
            var sim = position.CreateSimulation(planner.Table.Table, planner.Table.Physics);
            var rest = sim.CreateSnapshot();
            for (int k = 0; k < tries; k++)
            {
                sim.Restore(rest);
                var shot = skill.Execute(decision.Shot, new PlannerRandom(PlannerRandom.Derive(seed, i, 2 + k)));
                sim.Strike(shot, position.CueBall);
                sim.AdvanceTo(120);
                record.Capture(sim, 0, shot);
                var ruling = referee.Judge(before, record);
                shots++;
                noContact += ruling.Fouls.Contains(Foul.NoContact) ? 1 : 0;
                fouls += ruling.Fouls.Count > 0 ? 1 : 0;
            }
        }
        return new SnookerResult(positions.Count, shots, noContact, fouls, jumps, unplayable);
    }
}
