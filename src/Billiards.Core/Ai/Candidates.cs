using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>The kinds of shot the planner considers.</summary>
public enum ShotKind
{
    /// <summary>The opening break.</summary>
    Break,
    /// <summary>The cue ball sends the target straight into a pocket.</summary>
    Direct,
    /// <summary>The target goes into the pocket off one cushion.</summary>
    Bank,
    /// <summary>The cue ball reaches the target off one cushion.</summary>
    Kick,
    /// <summary>The target sends another ball into the pocket.</summary>
    Combination,
    /// <summary>The target glances off another ball into the pocket.</summary>
    Carom,
    /// <summary>No pot intended: hit the target legally and leave the opponent little.</summary>
    Safety,
    /// <summary>9-ball and 10-ball: a declared push-out after the break.</summary>
    PushOut,
    /// <summary>The cue ball hops over the balls in the way to the target (an elevated cue into the slate).</summary>
    Jump,
}

/// <summary>What a kind of shot means.</summary>
public static class ShotKinds
{
    /// <summary>
    /// True for a shot meant to pot a ball: a direct shot, bank, combination or carom, and a kick
    /// or jump with a <paramref name="pocket"/> (one without is a safety).
    /// </summary>
    public static bool IsPot(ShotKind kind, PocketId pocket) =>
        kind is ShotKind.Direct or ShotKind.Bank or ShotKind.Combination or ShotKind.Carom
        || (kind is ShotKind.Kick or ShotKind.Jump && pocket != PocketId.None);
}

/// <summary>
/// One candidate shot before the search varies it: which ball the cue ball should contact, where
/// the first ball should go (for a pot), the call, a base speed and a geometric prior.
/// </summary>
/// <param name="Kind">The kind of shot.</param>
/// <param name="Target">The first ball the cue ball should touch.</param>
/// <param name="Called">The ball meant to drop (for a pot), else the target.</param>
/// <param name="Pocket">The pocket meant, or <see cref="PocketId.None"/> for a safety or push-out.</param>
/// <param name="Contact">The target's centre (m).</param>
/// <param name="Direction">Unit direction the target should leave in, for throw correction; zero when the shot aims at <see cref="AimPoint"/> plainly.</param>
/// <param name="AimPoint">Where the cue ball's centre is sent (m): the ghost ball, or its mirror image for a kick.</param>
/// <param name="BaseSpeed">A cue speed (m/s) that gets the balls where they must go; the search scales it.</param>
/// <param name="Prior">The geometric ease (0-1) that ranks candidates before any simulation.</param>
public sealed record Candidate(ShotKind Kind, BallId Target, BallId Called, PocketId Pocket, Vec3 Contact, Vec3 Direction, Vec3 AimPoint, double BaseSpeed, double Prior);

/// <summary>
/// Generates the candidates of a position from ghost-ball geometry: direct shots, banks, kicks,
/// combinations and caroms for every legal target and pocket, and safeties.
/// </summary>
internal static class CandidateGenerator
{
    // Deceleration used to size speeds (m/s^2): rolling resistance plus the sliding phase, rounded up.
    private const double Deceleration = 0.35;

    public static List<Candidate> Pots(PlannerTable table, GameState state, TablePosition position, Vec3 cue)
    {
        var result = new List<Candidate>();
        var targets = PlannerTable.LegalTargets(state, position);
        double r = table.R;
        foreach (var t in targets)
        {
            var o = position.Positions[position.IndexOf(t)];
            bool hittable = !table.Blocked(position, cue, o, t);
            foreach (var pocket in table.Pockets)
            {
                var aim = table.AimPoint(pocket);
                var u = (aim - o).XY.Normalized();
                double window = table.Window(pocket, u);
                double ease = table.Ease(cue, o, aim, window, position, t);
                if (ease > 0.002)
                {
                    result.Add(Pot(ShotKind.Direct, t, t, pocket, o, u, table.Ghost(o, aim), cue, (aim - o).LengthXY, ease));
                }
                else if (!hittable || ease == 0)
                {
                    // Kick to the ghost ball off one rail when the straight way is blocked.
                    var ghost = table.Ghost(o, aim);
                    if (window > 0 && !table.Blocked(position, o, aim, t) && table.Blocked(position, cue, ghost, t))
                    {
                        for (int rail = 0; rail < 4; rail++)
                        {
                            var image = table.Mirror(ghost, rail);
                            var bounce = RailPoint(table, cue, image, rail);
                            if (bounce is { } b && !table.Blocked(position, cue, b, t) && !table.Blocked(position, b, ghost, t))
                            {
                                double d = (b - cue).LengthXY + (ghost - b).LengthXY;
                                double prior = 0.25 * table.Ease(b, o, aim, window, position, t);
                                if (prior > 0.002)
                                {
                                    result.Add(new Candidate(ShotKind.Kick, t, t, pocket, o, Vec3.Zero, image, Speed(d * 1.3, (aim - o).LengthXY, 0.7), prior));
                                }
                            }
                        }
                    }
                }
                // One-rail banks of the target, into pockets off that rail.
                for (int rail = 0; rail < 4; rail++)
                {
                    if (OnRail(table, aim, rail))
                    {
                        continue;
                    }
                    var image = table.Mirror(aim, rail);
                    var bounce = RailPoint(table, o, image, rail);
                    if (bounce is not { } b || table.Blocked(position, b, aim, t))
                    {
                        continue;
                    }
                    var ub = (image - o).XY.Normalized();
                    double bankWindow = 0.6 * table.Window(pocket, (aim - b).XY.Normalized());
                    double prior = 0.6 * table.Ease(cue, o, b, bankWindow * (b - o).LengthXY / (image - o).LengthXY, position, t);
                    if (prior > 0.002)
                    {
                        result.Add(Pot(ShotKind.Bank, t, t, pocket, o, ub, table.Ghost(o, image), cue, (image - o).LengthXY * 1.3, prior));
                    }
                }
            }
        }
        Combinations(table, state, position, cue, targets, result);
        return result;
    }

    private static void Combinations(PlannerTable table, GameState state, TablePosition position, Vec3 cue, IReadOnlyList<BallId> targets, List<Candidate> result)
    {
        double r = table.R;
        foreach (var t in targets)
        {
            var o = position.Positions[position.IndexOf(t)];
            for (int j = 0; j < position.Count; j++)
            {
                var b = position.Ids[j];
                if (b == position.CueBall || b == t || !MayCall(state, b))
                {
                    continue;
                }
                var ob = position.Positions[j];
                if ((ob - o).LengthXY > 0.8)
                {
                    continue;
                }
                foreach (var pocket in table.Pockets)
                {
                    var aim = table.AimPoint(pocket);
                    var ub = (aim - ob).XY.Normalized();
                    double window = table.Window(pocket, ub);
                    if (window <= 0 || table.Blocked(position, ob, aim, b))
                    {
                        continue;
                    }
                    // Combination: the target drives the second ball in.
                    var ghostB = table.Ghost(ob, aim);
                    double second = table.Ease(o, ob, aim, window, position, b);
                    if (second > 0.05 && !table.Blocked(position, o, ghostB, t))
                    {
                        var ut = (ghostB - o).XY.Normalized();
                        double first = table.Ease(cue, o, ghostB, r * 0.5, position.Without(b), t);
                        double prior = 0.7 * first * second;
                        if (prior > 0.002)
                        {
                            result.Add(Pot(ShotKind.Combination, t, b, pocket, o, ut, table.Ghost(o, ghostB), cue, (ghostB - o).LengthXY + (aim - ob).LengthXY * 1.5, prior));
                        }
                    }
                    // Carom: the target kisses the second ball and leaves at right angles to the line of
                    // centres into the pocket. Its centre at contact lies 2R from the second ball on the
                    // circle over the diameter from the second ball to the pocket (Thales).
                    if (!MayCall(state, t))
                    {
                        continue;
                    }
                    double d = (aim - ob).LengthXY;
                    if (d <= 2 * r)
                    {
                        continue;
                    }
                    double along = 4 * r * r / d;
                    double across = Math.Sqrt(Math.Max(0, 4 * r * r - along * along));
                    var n = new Vec3(-ub.Y, ub.X, 0);
                    foreach (double sign in (ReadOnlySpan<double>)[1, -1])
                    {
                        var contact = ob + ub * along + n * (sign * across);
                        var toPocket = (aim - contact).XY.Normalized();
                        double w = table.Window(pocket, toPocket);
                        if (w <= 0 || table.Blocked(position, contact, aim, t) || table.Blocked(position, o, contact, t))
                        {
                            continue;
                        }
                        var ut = (contact - o).XY.Normalized();
                        double first = table.Ease(cue, o, contact, r * 0.5, position.Without(b), t);
                        double prior = 0.4 * first * Math.Min(1, w / r);
                        if (prior > 0.002)
                        {
                            result.Add(Pot(ShotKind.Carom, t, t, pocket, o, ut, table.Ghost(o, contact), cue, (contact - o).LengthXY + d * 1.5, prior));
                        }
                    }
                }
            }
        }
    }

    /// <summary>
    /// Safeties on every legal target: full, half and thin contacts on both sides, the object ball
    /// sent a short, a middle and a long way, and one-rail kicks at the target when it cannot be
    /// seen. The list takes the targets in turn (each target's first safety, then each one's
    /// second, ...), so that a search that takes the first few looks at every ball.
    /// </summary>
    public static List<Candidate> Safeties(PlannerTable table, GameState state, TablePosition position, Vec3 cue)
    {
        var perTarget = new List<List<Candidate>>();
        double r = table.R;
        foreach (var t in PlannerTable.LegalTargets(state, position))
        {
            var result = new List<Candidate>();
            perTarget.Add(result);
            var o = position.Positions[position.IndexOf(t)];
            var line = (o - cue).XY;
            double dist = line.Length;
            var u = line / dist;
            var n = new Vec3(-u.Y, u.X, 0);
            if (!table.Blocked(position, cue, o, t))
            {
                foreach (double travel in (ReadOnlySpan<double>)[0.4, 1.2, 0.15])
                {
                    foreach (double offset in (ReadOnlySpan<double>)[0, 0.9, -0.9, 1.7, -1.7])
                    {
                        var aim = o + n * (offset * r);
                        result.Add(new Candidate(ShotKind.Safety, t, t, PocketId.None, o, Vec3.Zero, aim, Speed(dist, travel, 1), 0.1));
                    }
                }
            }
            else
            {
                for (int rail = 0; rail < 4; rail++)
                {
                    var image = table.Mirror(o, rail);
                    if (RailPoint(table, cue, image, rail) is { } b && !table.Blocked(position, cue, b, t) && !table.Blocked(position, b, o, t))
                    {
                        double d = (b - cue).LengthXY + (o - b).LengthXY;
                        result.Add(new Candidate(ShotKind.Kick, t, t, PocketId.None, o, Vec3.Zero, image, Speed(d * 1.3, 0.5, 1), 0.05));
                    }
                }
            }
        }
        var interleaved = new List<Candidate>();
        for (int k = 0; perTarget.Any(l => k < l.Count); k++)
        {
            interleaved.AddRange(perTarget.Where(l => k < l.Count).Select(l => l[k]));
        }
        return interleaved;
    }

    /// <summary>The cue ball's way to a rail when no shot is possible: straight at each legal target.</summary>
    public static List<Candidate> LastResort(PlannerTable table, GameState state, TablePosition position, Vec3 cue)
    {
        var result = new List<Candidate>();
        foreach (var t in PlannerTable.LegalTargets(state, position))
        {
            var o = position.Positions[position.IndexOf(t)];
            result.Add(new Candidate(ShotKind.Safety, t, t, PocketId.None, o, Vec3.Zero, o, Speed((o - cue).LengthXY, 0.5, 1), 0.01));
        }
        return result;
    }

    /// <summary>
    /// A cue speed (m/s) that rolls the cue ball <paramref name="d1"/> to contact and sends the first
    /// ball <paramref name="d2"/> further with a margin, for a contact of cosine <paramref name="cos"/>.
    /// </summary>
    public static double Speed(double d1, double d2, double cos)
    {
        double objectSpeed = Math.Sqrt(2 * Deceleration * (d2 + 0.2));
        double atContact = objectSpeed / Math.Max(0.25, cos * 0.9);
        double ballSpeed = Math.Sqrt(atContact * atContact + 2 * Deceleration * d1);
        // A centre hit gives the ball about 1.5 times the cue's speed (TP A-30 with these masses).
        return Math.Clamp(ballSpeed / 1.5, 0.4, 6.5);
    }

    private static Candidate Pot(ShotKind kind, BallId target, BallId called, PocketId pocket, Vec3 o, Vec3 u, Vec3 ghost, Vec3 cue, double d2, double prior)
    {
        var path = (ghost - cue).XY;
        double cos = Math.Max(0.2, Vec3.Dot(path.Normalized(), u));
        return new Candidate(kind, target, called, pocket, o, u, ghost, Speed(path.Length, d2, cos), prior);
    }

    private static bool MayCall(GameState state, BallId ball) => Ruleset.For(state.Rules).MayCall(state, ball);

    private static bool OnRail(PlannerTable table, Vec3 aim, int rail) => rail switch
    {
        0 => aim.X < 0 && Math.Abs(aim.X) > table.Table.HalfLength * 0.9,
        1 => aim.X > 0 && Math.Abs(aim.X) > table.Table.HalfLength * 0.9,
        2 => aim.Y < 0,
        _ => aim.Y > 0,
    };

    // Where the straight line from p to the mirror image crosses the rail's centre line, if it does so on the table.
    private static Vec3? RailPoint(PlannerTable table, Vec3 p, Vec3 image, int rail)
    {
        double hx = table.Table.HalfLength - table.R;
        double hy = table.Table.HalfWidth - table.R;
        double s;
        if (rail <= 1)
        {
            double x = rail == 0 ? -hx : hx;
            if (Math.Abs(image.X - p.X) < 1e-9)
            {
                return null;
            }
            s = (x - p.X) / (image.X - p.X);
        }
        else
        {
            double y = rail == 2 ? -hy : hy;
            if (Math.Abs(image.Y - p.Y) < 1e-9)
            {
                return null;
            }
            s = (y - p.Y) / (image.Y - p.Y);
        }
        if (s <= 0 || s >= 1)
        {
            return null;
        }
        var b = p + (image - p) * s;
        // Bounces too near a pocket would meet a jaw, not the rail.
        if (Math.Abs(b.X) > hx - 0.08 && Math.Abs(b.Y) > hy - 0.08 || (rail >= 2 && Math.Abs(b.X) < 0.09))
        {
            return null;
        }
        return b;
    }
}
