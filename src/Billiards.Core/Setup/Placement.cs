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
    /// <summary>Snooker's D: behind the baulk line, within the D's radius of the brown spot (<see cref="SnookerTable.InD"/>).</summary>
    D,
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
        return Where(table, radius, position, region, 0) switch
        {
            Problem.None => null,
            Problem.NotFinite => $"ball \"{id}\" has no finite position on the bed",
            // A ball in a pocket's mouth is refused in both models: the standard model's jaws and
            // capture circles and the thesis model's rail triangles and pocket test decide about
            // balls arriving from the bed, and a ball starting between them is on neither.
            Problem.OffTable => Text($"ball \"{id}\" at [{position.X}, {position.Y}] is off the table (the centre must stay within [{-(table.HalfLength - radius):0.######}, {table.HalfLength - radius:0.######}] x [{-(table.HalfWidth - radius):0.######}, {table.HalfWidth - radius:0.######}]: on the bed, R inside the cushion noses; in both models a ball starts on the bed, never in a pocket's mouth)"),
            Problem.OutsideKitchen => Text($"ball \"{id}\" at [{position.X}, {position.Y}] is outside the kitchen (x must be at most the head string, {HeadString(table):0.######} m)"),
            Problem.OutsideD => Text($"ball \"{id}\" at [{position.X}, {position.Y}] is outside the D (at most {SnookerTable.DRadius} m from the brown spot [{SnookerTable.BaulkLineX(table):0.######}, 0], on the baulk side)"),
            _ => Text($"ball \"{id}\" at [{position.X}, {position.Y}] is over the {table.Pockets.NameOf(OverPocket(table, radius, position, 0))} pocket"),
        };
    }

    /// <summary>
    /// True when a ball of radius <paramref name="radius"/> (m) may rest at <paramref name="position"/>
    /// in <paramref name="region"/>, <paramref name="margin"/> (m) clear of every limit (the
    /// planner keeps a margin so that its placements are never on an edge): the same test as
    /// <see cref="OnTable"/>, without a message.
    /// </summary>
    public static bool FitsOnTable(TableSpec table, double radius, Vec3 position, PlacementRegion region, double margin = 0)
    {
        ArgumentNullException.ThrowIfNull(table);
        return Where(table, radius, position, region, margin) == Problem.None;
    }

    /// <summary>True when balls of radius <paramref name="radius"/> (m) at <paramref name="a"/> and <paramref name="b"/> overlap, or come within <paramref name="margin"/> (m) of it.</summary>
    public static bool Overlaps(double radius, Vec3 a, Vec3 b, double margin = 0)
    {
        // In space when a ball is above the bed (a scene's ball in the air); on the bed the height
        // is left out, since callers give bed positions at z = 0 or z = R alike.
        double dz = Math.Max(a.Z, b.Z) > radius + 1e-9 ? a.Z - b.Z : 0;
        var d = (a - b).XY;
        return Math.Sqrt(d.X * d.X + d.Y * d.Y + dz * dz) < 2 * radius + margin - Tolerance;
    }

    private enum Problem
    {
        None,
        NotFinite,
        OffTable,
        OutsideKitchen,
        OutsideD,
        OverPocket,
    }

    private static Problem Where(TableSpec table, double radius, Vec3 position, PlacementRegion region, double margin)
    {
        if (!double.IsFinite(position.X) || !double.IsFinite(position.Y))
        {
            return Problem.NotFinite;
        }
        double maxX = table.HalfLength - radius - margin;
        double maxY = table.HalfWidth - radius - margin;
        if (Math.Abs(position.X) > maxX + Tolerance || Math.Abs(position.Y) > maxY + Tolerance)
        {
            return Problem.OffTable;
        }
        if (region == PlacementRegion.Kitchen && position.X > HeadString(table) - margin + Tolerance)
        {
            return Problem.OutsideKitchen;
        }
        if (region == PlacementRegion.D && !InD(table, position, margin))
        {
            return Problem.OutsideD;
        }
        return OverPocket(table, radius, position, margin) >= 0 ? Problem.OverPocket : Problem.None;
    }

    // In the D with the margin inside the line and the arc.
    private static bool InD(TableSpec table, Vec3 position, double margin)
    {
        double dx = position.X - SnookerTable.BaulkLineX(table);
        double reach = SnookerTable.DRadius - margin + Tolerance;
        return dx <= -margin + Tolerance && (dx * dx) + (position.Y * position.Y) <= reach * reach;
    }

    // The index of the pocket whose capture circle (grown by the margin) holds the centre, or -1.
    private static int OverPocket(TableSpec table, double radius, Vec3 position, double margin)
    {
        if (!table.HasPockets)
        {
            return -1;
        }
        foreach (var pocket in Pockets(table, radius))
        {
            if ((position - pocket.Centre).XY.Length < pocket.Radius + margin - Tolerance)
            {
                return pocket.Pocket;
            }
        }
        return -1;
    }

    // The last table's capture circles: a placement search asks for the same table many times.
    // A reference, swapped whole, so that threads searching at once never see half of one.
    private sealed record PocketCache(TableSpec Table, double Radius, PocketCircle[] Pockets);

    private static PocketCache? s_pockets;

    private static PocketCircle[] Pockets(TableSpec table, double radius)
    {
        var cached = s_pockets;
        if (cached is not null && ReferenceEquals(cached.Table, table) && cached.Radius == radius)
        {
            return cached.Pockets;
        }
        var pockets = TableGeometry.Build(table, radius).Pockets.ToArray();
        s_pockets = new PocketCache(table, radius, pockets);
        return pockets;
    }

    /// <summary>What is wrong with ball <paramref name="id"/> at <paramref name="position"/> next to ball <paramref name="other"/> at <paramref name="otherPosition"/> (m); null when they do not overlap.</summary>
    public static string? Overlap(double radius, BallId id, Vec3 position, BallId other, Vec3 otherPosition)
    {
        double d = (position - otherPosition).Length;
        return Overlaps(radius, position, otherPosition)
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
                var p = near + new Vec3(ring * radius * DeterministicMath.Cos(a), ring * radius * DeterministicMath.Sin(a), 0);
                if (Free(p))
                {
                    return p;
                }
            }
        }
        return near;
    }

    /// <summary>
    /// The free point on the long axis (y = 0) nearest <paramref name="startX"/> (m) in
    /// <paramref name="direction"/> (+1 towards the foot rail, -1 towards the head rail) where a ball
    /// of radius <paramref name="radius"/> (m) touches none of <paramref name="others"/>: each ball
    /// in the way pushes the point to just past it, until none is (the spotting rule of rules.md).
    /// The caller checks the result against the cushion.
    /// </summary>
    public static double FreeOnLongAxis(double radius, IReadOnlyList<Vec3> others, double startX, int direction)
    {
        ArgumentNullException.ThrowIfNull(others);
        double x = startX;
        bool moved = true;
        while (moved)
        {
            moved = false;
            foreach (var other in others)
            {
                double dy = other.Y;
                double reach = 4 * radius * radius - dy * dy;
                if (reach <= 0)
                {
                    continue;
                }
                double half = Math.Sqrt(reach);
                if (Math.Abs(x - other.X) < half - Tolerance)
                {
                    x = other.X + direction * half;
                    moved = true;
                }
            }
        }
        return x;
    }

    // Rings of the free-spot search: 200 R reaches every corner of the largest table.
    private const int MaxRings = 200;

    private static string Text(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
