using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Setup;

/// <summary>Where a ball may be placed by hand (rules.md, "Ball in hand").</summary>
public enum PlacementRegion
{
    /// <summary>Anywhere on the bed.</summary>
    Table,
    /// <summary>Behind the head string: the quarter of the table at the head end, x &lt;= -L/4.</summary>
    Kitchen,
}

/// <summary>
/// The one test of where a resting ball may stand, used by the scene loader and by
/// <see cref="Physics.Simulation"/>'s placing calls alike: its centre on the bed inside the cushions
/// (at least R from every rail's nose line), not over a pocket (outside every capture circle of
/// <see cref="TableGeometry"/>), inside its region, and overlapping no other ball. Each test returns
/// null when the placement is fine, else one sentence naming the ball and the problem.
/// </summary>
public static class Placement
{
    /// <summary>Slack of every test (m), so that a ball placed exactly touching a cushion or a ball is accepted.</summary>
    public const double Tolerance = 1e-9;

    /// <summary>The x of the head string (m): -L/4; the kitchen is x at or below it.</summary>
    public static double HeadString(TableSpec table) => -table.HalfLength / 2;

    /// <summary>
    /// What is wrong with ball <paramref name="id"/> resting at <paramref name="position"/> (m; z is
    /// ignored, a resting ball's centre is at z = R) on <paramref name="table"/>, with balls of
    /// radius <paramref name="radius"/> (m), in <paramref name="region"/>; null when nothing is.
    /// </summary>
    public static string? OnTable(TableSpec table, double radius, BallId id, Vec3 position, PlacementRegion region = PlacementRegion.Table)
    {
        ArgumentNullException.ThrowIfNull(table);
        if (!double.IsFinite(position.X) || !double.IsFinite(position.Y))
        {
            return $"ball \"{id}\" has no finite position on the bed";
        }
        double maxX = table.HalfLength - radius;
        double maxY = table.HalfWidth - radius;
        if (Math.Abs(position.X) > maxX + Tolerance || Math.Abs(position.Y) > maxY + Tolerance)
        {
            // A ball in a pocket's mouth is refused in both models: the standard model's jaws and
            // capture circles and the thesis model's rail triangles and pocket test decide about
            // balls arriving from the bed, and a ball starting between them is on neither.
            return Text($"ball \"{id}\" at [{position.X}, {position.Y}] is off the table (the centre must stay within [{-maxX:0.######}, {maxX:0.######}] x [{-maxY:0.######}, {maxY:0.######}]: on the bed, R inside the cushion noses; in both models a ball starts on the bed, never in a pocket's mouth)");
        }
        if (region == PlacementRegion.Kitchen && position.X > HeadString(table) + Tolerance)
        {
            return Text($"ball \"{id}\" at [{position.X}, {position.Y}] is outside the kitchen (x must be at most the head string, {HeadString(table):0.######} m)");
        }
        if (table.HasPockets)
        {
            foreach (var pocket in TableGeometry.Build(table, radius).Pockets)
            {
                if ((position - pocket.Centre).XY.Length < pocket.Radius - Tolerance)
                {
                    return Text($"ball \"{id}\" at [{position.X}, {position.Y}] is over the {PocketIds.FromIndex(pocket.Pocket).ToName()} pocket");
                }
            }
        }
        return null;
    }

    /// <summary>What is wrong with ball <paramref name="id"/> at <paramref name="position"/> next to ball <paramref name="other"/> at <paramref name="otherPosition"/> (m); null when they do not overlap.</summary>
    public static string? Overlap(double radius, BallId id, Vec3 position, BallId other, Vec3 otherPosition)
    {
        double d = (position - otherPosition).Length;
        return d < 2 * radius - Tolerance
            ? Text($"ball \"{id}\" overlaps ball \"{other}\" (centres {d:0.######} m apart, less than 2R = {2 * radius:0.######} m)")
            : null;
    }

    /// <summary>
    /// The first problem of a whole set of resting balls, in order: each ball on the table
    /// (<see cref="OnTable"/>, whole table), then each ball against every ball before it
    /// (<see cref="Overlap"/>); null when there is none. <paramref name="culprit"/> is the index
    /// of the ball the problem is reported on.
    /// </summary>
    public static string? Check(TableSpec table, double radius, IReadOnlyList<(BallId Id, Vec3 Position)> balls, out int culprit)
    {
        ArgumentNullException.ThrowIfNull(balls);
        for (int i = 0; i < balls.Count; i++)
        {
            if (OnTable(table, radius, balls[i].Id, balls[i].Position) is { } problem)
            {
                culprit = i;
                return problem;
            }
        }
        for (int i = 0; i < balls.Count; i++)
        {
            for (int j = i + 1; j < balls.Count; j++)
            {
                if (Overlap(radius, balls[j].Id, balls[j].Position, balls[i].Id, balls[i].Position) is { } problem)
                {
                    culprit = j;
                    return problem;
                }
            }
        }
        culprit = -1;
        return null;
    }

    /// <summary>
    /// The free spot for ball <paramref name="id"/> nearest <paramref name="near"/> (m): the point
    /// itself when <see cref="OnTable"/> in <paramref name="region"/> and <see cref="Overlap"/> with
    /// every ball of <paramref name="others"/> allow it, else the first allowed point on rings R apart
    /// around it (8k points on ring k, from angle 0 counter-clockwise); <paramref name="near"/> when
    /// the table is full. The one search for a free place: the cue ball in hand and a returned ball.
    /// </summary>
    public static Vec3 FreeSpotNear(TableSpec table, double radius, BallId id, Vec3 near, IEnumerable<(BallId Id, Vec3 Position)> others, PlacementRegion region = PlacementRegion.Table)
    {
        ArgumentNullException.ThrowIfNull(others);
        var balls = others.Where(b => b.Id != id).ToList();
        bool Free(Vec3 p) => OnTable(table, radius, id, p, region) is null && balls.All(b => Overlap(radius, id, p, b.Id, b.Position) is null);
        for (int ring = 0; ring < MaxRings; ring++)
        {
            int count = ring == 0 ? 1 : 8 * ring;
            for (int k = 0; k < count; k++)
            {
                double a = 2 * Math.PI * k / count;
                var p = near + new Vec3(ring * radius * Math.Cos(a), ring * radius * Math.Sin(a), 0);
                if (Free(p))
                {
                    return p;
                }
            }
        }
        return near;
    }

    // Rings of the free-spot search: 200 R reaches every corner of the largest table.
    private const int MaxRings = 200;

    private static string Text(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
