using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>
/// Jump shots: when every straight path to the legal targets is blocked, the strongest levels also
/// try to hop the cue ball over the blocking balls, as they try kicks.
/// </summary>
/// <remarks>
/// A jump stroke's cue passes through the cue ball's centre (tip height sin e at elevation e), so the
/// ball takes no spin from it and the slate's return alone lifts it (<c>StandardSimulation</c>'s
/// strike). The stroke is sized on the engine itself: the cue ball alone is struck at each elevation
/// and cue speed, and its first hop, a parabola from its launch velocity, must pass every blocking
/// ball by <see cref="JumpClearance"/> and land before the target; the slowest such stroke of each
/// elevation is played, and slightly harder. The search then simulates them like any other shot, so
/// a stroke that clips a blocker or misses the target loses to whatever else the position offers.
/// </remarks>
public sealed partial class ShotPlanner
{
    /// <summary>The lowest level that considers jump shots.</summary>
    public const int JumpLevel = 4;

    /// <summary>Cue elevations tried for a jump (deg), steepest last: a steeper cue hops higher and shorter.</summary>
    public static readonly double[] JumpElevationsDeg = [40, 50, 60];

    /// <summary>Gap (m) the hopping cue ball keeps from a blocking ball it passes over, beyond contact.</summary>
    public const double JumpClearance = 0.006;

    /// <summary>Whether the planner considers jump shots at all (levels from <see cref="JumpLevel"/>); off only to measure what they change.</summary>
    public bool ConsiderJumps { get; init; } = true;

    private const double JumpSpeedStep = 0.25;
    private const double JumpMinSpeed = 1.5;
    private const double JumpMaxSpeed = 6.5;

    /// <summary>The cue ball's launch (horizontal speed, upward speed, m/s) from a jump stroke, or null when the stroke does not hop.</summary>
    private (double Horizontal, double Up)? Launch(Physics.Simulation single, Physics.SimulationSnapshot rest, double speed, double elevationDeg)
    {
        single.Restore(rest);
        double h = DeterministicMath.Sin(elevationDeg * Math.PI / 180);
        single.Strike(new ShotSpec(speed, 0, 0, h, elevationDeg), single.Ids[0]);
        // The slate's return is resolved at t = 0; a microsecond later the ball is on its parabola.
        const double After = 1e-6;
        single.AdvanceTo(After);
        var b = single.Balls[0];
        if (b.State != MotionState.Airborne)
        {
            return null;
        }
        return (b.Velocity.XY.Length, b.Velocity.Z + (Table.Physics.G * After));
    }

    /// <summary>
    /// Whether a hop from <paramref name="cue"/> towards <paramref name="aim"/> at the launch
    /// (<paramref name="horizontal"/>, <paramref name="up"/>) passes over every ball near its line
    /// short of the target and comes down before the target, whose centre is <paramref name="target"/>.
    /// </summary>
    private bool Clears(TablePosition position, BallId targetId, Vec3 cue, Vec3 aim, Vec3 target, double horizontal, double up)
    {
        double r = Table.R, g = Table.Physics.G;
        var u = (aim - cue).XY.Normalized();
        double flight = 2 * up / g;
        double landing = horizontal * flight;
        double toTarget = Vec3.Dot((target - cue).XY, u);
        // Down on the bed, and its next, lower hop begun, before it reaches the target: a ball that
        // meets the target in the air may fly over it.
        if (landing > toTarget - (2 * r))
        {
            return false;
        }
        double near = (2 * r) + JumpClearance;
        for (int i = 0; i < position.Count; i++)
        {
            var id = position.Ids[i];
            if (id == position.CueBall || id == targetId)
            {
                continue;
            }
            var w = (position.Positions[i] - cue).XY;
            double s = Vec3.Dot(w, u);
            double d = Math.Abs((w.X * u.Y) - (w.Y * u.X));
            if (d >= near || s <= 0 || s > toTarget)
            {
                continue;
            }
            // A ball in the way: the hop must be past it before landing, and over it all along.
            if (landing < s + near)
            {
                return false;
            }
            const int Steps = 64;
            for (int k = 0; k <= Steps; k++)
            {
                double t = flight * k / Steps;
                double along = (horizontal * t) - s;
                double z = (up * t) - (0.5 * g * t * t);
                if ((along * along) + (d * d) + (z * z) < near * near)
                {
                    return false;
                }
            }
        }
        return true;
    }

    /// <summary>Jump strokes (cue speed, elevation) from the cue ball of <paramref name="position"/> at <paramref name="aim"/> over the balls in the way to <paramref name="targetId"/>.</summary>
    internal List<(double Speed, double ElevationDeg)> JumpStrokes(TablePosition position, BallId targetId, Vec3 aim)
    {
        var cue = position.Cue!.Value;
        var single = new TablePosition([(position.CueBall, cue)], position.CueBall).CreateSimulation(Model);
        return JumpStrokes(single, single.CreateSnapshot(), position, targetId, cue, aim, position.Positions[position.IndexOf(targetId)]);
    }

    /// <summary>
    /// Jump strokes (cue speed, elevation) for a hop from <paramref name="cue"/> at
    /// <paramref name="aim"/> over the balls in the way to <paramref name="target"/>: for each of
    /// <see cref="JumpElevationsDeg"/>, the slowest cue speed whose hop clears them.
    /// </summary>
    internal List<(double Speed, double ElevationDeg)> JumpStrokes(Physics.Simulation single, Physics.SimulationSnapshot rest, TablePosition position, BallId targetId, Vec3 cue, Vec3 aim, Vec3 target)
    {
        var strokes = new List<(double, double)>();
        foreach (double e in JumpElevationsDeg)
        {
            for (double v = JumpMinSpeed; v <= JumpMaxSpeed + 1e-9; v += JumpSpeedStep)
            {
                if (Launch(single, rest, v, e) is { } launch && Clears(position, targetId, cue, aim, target, launch.Horizontal, launch.Up))
                {
                    strokes.Add((v, e));
                    break;
                }
            }
        }
        return strokes;
    }

    private sealed partial class Search
    {
        /// <summary>
        /// Jump shots from levels <see cref="JumpLevel"/> on, only when no legal target can be
        /// reached straight: at each target's centre (a safe first contact) and at its ghost ball
        /// for every pocket it has a clear way to, at the slowest clearing stroke of each elevation
        /// and a tenth harder (the executed speed varies).
        /// </summary>
        private void AddJumps(int rootIndex, Root root, GameState before, bool call, List<Variation> variations)
        {
            if (!planner.ConsiderJumps || level.Level < JumpLevel)
            {
                return;
            }
            var position = root.Position;
            var cue = root.Cue;
            var targets = PlannerTable.LegalTargets(state, position);
            if (targets.Count == 0 || targets.Any(t => !_table.Blocked(position, cue, position.Positions[position.IndexOf(t)], t)))
            {
                return;
            }
            var single = new TablePosition([(position.CueBall, cue)], position.CueBall).CreateSimulation(planner.Model);
            int dbg0 = variations.Count;
            var rest = single.CreateSnapshot();
            foreach (var t in targets)
            {
                var o = position.Positions[position.IndexOf(t)];
                var aims = new List<(Vec3 Aim, PocketId Pocket, Vec3 Direction)> { (o, PocketId.None, Vec3.Zero) };
                foreach (var pocket in _table.Pockets)
                {
                    var mouth = _table.AimPoint(pocket);
                    var u = (mouth - o).XY.Normalized();
                    if (_table.Window(pocket, u) <= 0 || _table.Blocked(position, o, mouth, t))
                    {
                        continue;
                    }
                    // A hopping ball carries the side spin of the tip's error into a massé curve
                    // at the slate: only cuts whose ghost ball lies within R of the line of centres
                    // (about 30 deg) keep a margin for it; a thinner one misses the target outright.
                    var ghost = _table.Ghost(o, mouth);
                    var line = (o - cue).XY.Normalized();
                    var off = (ghost - cue).XY;
                    if (Math.Abs((off.X * line.Y) - (off.Y * line.X)) <= _table.R)
                    {
                        aims.Add((ghost, pocket, u));
                    }
                }
                foreach (var (aim, pocket, direction) in aims)
                {
                    var c = new Candidate(ShotKind.Jump, t, t, pocket, o, direction, aim, 0, 0.05);
                    var withCall = before with { Call = call ? (pocket == PocketId.None ? Call.Safety : new Call(t, pocket)) : null };
                    foreach (var (speed, elevation) in planner.JumpStrokes(single, rest, position, t, cue, aim, o))
                    {
                        double h = DeterministicMath.Sin(elevation * Math.PI / 180);
                        double aimDeg = planner.AimFor(c, cue, 0, h);
                        foreach (double f in (ReadOnlySpan<double>)[1.0, 1.1])
                        {
                            variations.Add(new Variation(rootIndex, c, new ShotSpec(Math.Min(JumpMaxSpeed, speed * f), aimDeg, 0, h, elevation), withCall));
                        }
                    }
                }
            }
        }
    }
}
