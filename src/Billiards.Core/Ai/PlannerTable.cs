using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>
/// What the planner knows of a table without simulating: the pockets' aim points, the rails, and
/// a geometric estimate of how makeable a shot is. Immutable; shared by every search thread.
/// </summary>
/// <remarks>
/// The estimate (<see cref="Ease"/>) is ghost-ball geometry: the object ball must leave within
/// the pocket's window (half its mouth, less a little of the ball, narrowed by the angle of
/// approach), and a cue aim error turns into an object-ball error multiplied by
/// d1 / (2R cos(cut)). The probability that a Gaussian aim error of <see cref="ReferenceAimStdDeg"/>
/// stays inside that tolerance ranks shots and positions; the simulations decide.
/// </remarks>
public sealed class PlannerTable
{
    /// <summary>The aim error (deg) of the player that positions are judged for.</summary>
    public const double ReferenceAimStdDeg = 0.5;

    /// <summary>The largest cut angle the planner tries (deg).</summary>
    public const double MaxCutDeg = 80;

    private readonly Vec3[] _aim;
    private readonly Vec3[] _axis;
    private readonly double[] _mouth;

    /// <summary>The planner's view of <paramref name="table"/> for balls with <paramref name="physics"/>.</summary>
    public PlannerTable(TableSpec table, PhysicsParams physics)
    {
        ArgumentNullException.ThrowIfNull(table);
        ArgumentNullException.ThrowIfNull(physics);
        Table = table;
        Physics = physics;
        R = physics.R;
        var geometry = TableGeometry.Build(table, R);
        int count = table.Pockets.Count;
        (_aim, _axis, _mouth) = (new Vec3[count], new Vec3[count], new double[count]);
        foreach (var circle in geometry.Pockets)
        {
            int k = circle.Pocket;
            var pocket = table.Pockets[k];
            _aim[k] = circle.Centre with { Z = R };
            // Into the table through the mouth.
            _axis[k] = pocket.IsCorner ? new Vec3(-pocket.End, -pocket.Side, 0).Normalized() : new Vec3(0, -pocket.Side, 0);
            _mouth[k] = pocket.Mouth;
        }
        Pockets = table.Pockets.Ids;
    }

    /// <summary>The table.</summary>
    public TableSpec Table { get; }

    /// <summary>The model parameters the planner simulates with.</summary>
    public PhysicsParams Physics { get; }

    /// <summary>
    /// 2 / (1 + e_tip): the planner's cue speeds (its breaks, break-offs and speed ladder) are set
    /// for an elastic tip and scaled by this, so that a leather tip's cue gives the ball the speeds
    /// they were chosen for (1 with an elastic tip).
    /// </summary>
    public double TipScale => 2 / (1 + Physics.ETip);

    /// <summary>Ball radius (m).</summary>
    public double R { get; }

    /// <summary>The table's pockets (none on a pocketless table).</summary>
    public IReadOnlyList<PocketId> Pockets { get; }

    /// <summary>Where an object ball is sent to fall into <paramref name="pocket"/> (m, z = R).</summary>
    public Vec3 AimPoint(PocketId pocket) => _aim[pocket.Index];

    /// <summary>
    /// Half the window (m) an object ball's centre must pass through to drop, arriving along
    /// <paramref name="direction"/> (unit); 0 when the pocket cannot be reached from there.
    /// </summary>
    public double Window(PocketId pocket, Vec3 direction)
    {
        int k = pocket.Index;
        double cos = -Vec3.Dot(direction, _axis[k]);
        if (cos < 0.3)
        {
            return 0;
        }
        return Math.Max(0, _mouth[k] * cos / 2 - 0.6 * R);
    }

    /// <summary>
    /// The ghost ball: where the cue ball's centre must be at contact to send an object ball at
    /// <paramref name="objectBall"/> towards <paramref name="target"/>.
    /// </summary>
    public Vec3 Ghost(Vec3 objectBall, Vec3 target) => objectBall - (target - objectBall).XY.Normalized() * (2 * R);

    /// <summary>
    /// The chance (0-1) that a player with the reference aim error makes the shot of the ball at
    /// <paramref name="objectBall"/> to <paramref name="target"/> with the cue ball at
    /// <paramref name="cue"/>, given the window <paramref name="window"/> (m) at the target;
    /// 0 if the cut is too thin or a ball of <paramref name="position"/> blocks either path.
    /// </summary>
    public double Ease(Vec3 cue, Vec3 objectBall, Vec3 target, double window, TablePosition position, BallId objectId, double aimStdDeg = ReferenceAimStdDeg)
    {
        ArgumentNullException.ThrowIfNull(position);
        var toTarget = (target - objectBall).XY;
        double d2 = toTarget.Length;
        if (d2 < 1e-9 || window <= 0)
        {
            return 0;
        }
        var u = toTarget / d2;
        var ghost = objectBall - u * (2 * R);
        var path = (ghost - cue).XY;
        double d1 = path.Length;
        if (d1 < 1e-9)
        {
            return 0;
        }
        double cos = Vec3.Dot(path / d1, u);
        if (cos < DeterministicMath.Cos(MaxCutDeg * Math.PI / 180))
        {
            return 0;
        }
        if (Blocked(position, cue, ghost, objectId) || Blocked(position, objectBall, target, objectId))
        {
            return 0;
        }
        double objectTolerance = DeterministicMath.Atan(window / d2);
        double cueTolerance = objectTolerance * 2 * R * cos / Math.Max(d1, 2 * R);
        double sigma = aimStdDeg * Math.PI / 180;
        return Erf(cueTolerance / (sigma * Math.Sqrt(2)));
    }

    /// <summary>The ease of a direct shot of <paramref name="objectId"/> into <paramref name="pocket"/>.</summary>
    public double DirectEase(TablePosition position, Vec3 cue, BallId objectId, PocketId pocket, double aimStdDeg = ReferenceAimStdDeg)
    {
        ArgumentNullException.ThrowIfNull(position);
        var o = position.Positions[position.IndexOf(objectId)];
        var target = AimPoint(pocket);
        var dir = (target - o).XY.Normalized();
        return Ease(cue, o, target, Window(pocket, dir), position, objectId, aimStdDeg);
    }

    /// <summary>
    /// The best direct shot the player at the table has in <paramref name="state"/>: the largest
    /// <see cref="DirectEase"/> over legal targets and pockets, 0 without a cue ball.
    /// </summary>
    public double BestEase(TablePosition position, GameState state, double aimStdDeg = ReferenceAimStdDeg) =>
        Shots(position, state, aimStdDeg).Best;

    /// <summary>
    /// How good <paramref name="position"/> is for the player at the table in <paramref name="state"/>
    /// whose aim error is <paramref name="aimStdDeg"/>: the one-shot look-ahead of the search.
    /// The run ahead: mostly the best next shot's <see cref="DirectEase"/> b, and a little the best
    /// shot on another ball s, 0.85 b + 0.15 s, so that of two leaves with the same next shot the one
    /// whose next-but-one choice is easier wins (a run goes on when the first way is missed in
    /// position). With one legal ball (9-ball, or the last of a group) it is b.
    /// </summary>
    public double PositionQuality(TablePosition position, GameState state, double aimStdDeg) =>
        PositionQuality(position, state, aimStdDeg, BestShotWeight, SecondShotWeight);

    /// <summary>The weight of the best next shot in <see cref="PositionQuality(TablePosition, GameState, double)"/>.</summary>
    public const double BestShotWeight = 0.85;

    /// <summary>The weight of the best shot on another ball in <see cref="PositionQuality(TablePosition, GameState, double)"/>.</summary>
    public const double SecondShotWeight = 0.15;

    /// <summary>
    /// <see cref="PositionQuality(TablePosition, GameState, double)"/> with the weights of the best next
    /// shot and of the best shot on another ball given: <paramref name="bestWeight"/> b + <paramref name="secondWeight"/> s
    /// with more than one legal ball, else b.
    /// </summary>
    public double PositionQuality(TablePosition position, GameState state, double aimStdDeg, double bestWeight, double secondWeight)
    {
        var (best, second) = Shots(position, state, aimStdDeg);
        return LegalTargets(state, position).Count > 1 ? bestWeight * best + secondWeight * second : best;
    }

    /// <summary>
    /// The balls the player at the table must still pot (the legal targets, and in 8-ball the 8)
    /// that no pocket can take straight from where they lie: every way to a pocket is blocked or
    /// outside its window. Each needs a bank, a combination or a break-out to clear the table.
    /// </summary>
    public int ProblemBalls(TablePosition position, GameState state)
    {
        ArgumentNullException.ThrowIfNull(position);
        ArgumentNullException.ThrowIfNull(state);
        var balls = Ruleset.For(state.Rules).StillToPot(state, position.ObjectBalls);
        int problems = 0;
        foreach (var ball in balls)
        {
            var o = position.Positions[position.IndexOf(ball)];
            bool open = false;
            foreach (var pocket in Pockets)
            {
                var aim = AimPoint(pocket);
                if (Window(pocket, (aim - o).XY.Normalized()) > 0 && !Blocked(position, o, aim, ball))
                {
                    open = true;
                    break;
                }
            }
            problems += open ? 0 : 1;
        }
        return problems;
    }

    // The best direct ease, and the best on a ball other than the best's.
    private (double Best, double Second) Shots(TablePosition position, GameState state, double aimStdDeg)
    {
        ArgumentNullException.ThrowIfNull(position);
        ArgumentNullException.ThrowIfNull(state);
        if (position.Cue is not { } cue)
        {
            return (0, 0);
        }
        double best = 0, second = 0;
        foreach (var target in LegalTargets(state, position))
        {
            double ball = 0;
            foreach (var pocket in Pockets)
            {
                ball = Math.Max(ball, DirectEase(position, cue, target, pocket, aimStdDeg));
            }
            if (ball > best)
            {
                second = best;
                best = ball;
            }
            else if (ball > second)
            {
                second = ball;
            }
        }
        return (best, second);
    }

    /// <summary>
    /// The balls the shooter of <paramref name="state"/> may hit first (<see cref="Ruleset.LegalTargets"/>);
    /// before a nomination, every ball the shooter may nominate (snooker's colours after a red, any
    /// ball with a free ball), since the shot nominates the ball it strikes.
    /// </summary>
    public static IReadOnlyList<BallId> LegalTargets(GameState state, TablePosition position)
    {
        ArgumentNullException.ThrowIfNull(state);
        ArgumentNullException.ThrowIfNull(position);
        var ruleset = Ruleset.For(state.Rules);
        var objects = position.ObjectBalls;
        if (state.Call is null && ruleset.Nominates(state))
        {
            return [.. objects.Where(b => ruleset.MayCall(state, b)).OrderBy(b => b.Value)];
        }
        return ruleset.LegalTargets(state, objects);
    }

    /// <summary>
    /// True when the player at the table in <paramref name="state"/> is snookered in
    /// <paramref name="position"/>: no straight line of the cue ball reaches any part of any ball
    /// they may strike first (<see cref="Sightlines.AnyPart"/>, the referee's own test), in the
    /// games whose planner policy sees snookers (<see cref="PlannerPolicy.SeesSnookers"/>); false without a cue ball.
    /// </summary>
    public bool Snookered(TablePosition position, GameState state)
    {
        ArgumentNullException.ThrowIfNull(position);
        ArgumentNullException.ThrowIfNull(state);
        if (!Ruleset.For(state.Rules).Policy.SeesSnookers || position.Cue is not { } cue)
        {
            return false;
        }
        var targets = LegalTargets(state, position);
        var obstacles = new List<Vec3>(position.Count);
        foreach (var target in targets)
        {
            obstacles.Clear();
            for (int i = 0; i < position.Count; i++)
            {
                if (position.Ids[i] != position.CueBall && position.Ids[i] != target)
                {
                    obstacles.Add(position.Positions[i]);
                }
            }
            if (Sightlines.AnyPart(cue, position.Positions[position.IndexOf(target)], obstacles, R))
            {
                return false;
            }
        }
        return targets.Count > 0;
    }

    /// <summary>True when a ball of <paramref name="position"/> (other than the cue ball and <paramref name="ignore"/>) lies within 2R of the segment.</summary>
    public bool Blocked(TablePosition position, Vec3 from, Vec3 to, BallId ignore)
    {
        ArgumentNullException.ThrowIfNull(position);
        var d = (to - from).XY;
        double len2 = d.LengthSquared;
        double limit = 4 * R * R * 0.98;
        for (int i = 0; i < position.Count; i++)
        {
            var id = position.Ids[i];
            if (id == position.CueBall || id == ignore)
            {
                continue;
            }
            var p = (position.Positions[i] - from).XY;
            double t = len2 > 0 ? Math.Clamp(Vec3.Dot(p, d) / len2, 0, 1) : 0;
            if ((p - d * t).LengthSquared < limit)
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>Mirror image of <paramref name="p"/> in the line a ball's centre follows along rail <paramref name="rail"/> (0 head, 1 foot, 2 right y &lt; 0, 3 left y &gt; 0).</summary>
    public Vec3 Mirror(Vec3 p, int rail)
    {
        double hx = Table.HalfLength - R;
        double hy = Table.HalfWidth - R;
        return rail switch
        {
            0 => p with { X = -2 * hx - p.X },
            1 => p with { X = 2 * hx - p.X },
            2 => p with { Y = -2 * hy - p.Y },
            _ => p with { Y = 2 * hy - p.Y },
        };
    }

    // Abramowitz-Stegun 7.1.26 (error below 1.5e-7): ample for ranking shots.
    private static double Erf(double x)
    {
        double t = 1 / (1 + 0.3275911 * x);
        double y = 1 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t * DeterministicMath.Exp(-x * x);
        return x >= 0 ? y : -y;
    }
}
