using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// Where the aimed shot goes first, by ghost-ball geometry on the bed: the first object ball the
/// cue ball's path meets, the ghost ball (the cue ball's centre at contact), the object ball's
/// direction after contact (along the line of centres), and the easiest pocket for that ball
/// (the smallest cut angle, then the shortest distance). Given the table, a path that meets no ball
/// ends where the cue ball reaches a cushion, with its mirror bank off it (<see cref="Bank"/>).
/// Throw, squirt, spin and the cushion's own physics are ignored: it is an aid for the player and
/// the default call, not a prediction of the physics.
/// </summary>
/// <param name="Ball">The first object ball hit, or null when the path meets none.</param>
/// <param name="Ghost">The cue ball's centre at contact, or the end of the path drawn: at the cushion when the table is known (m).</param>
/// <param name="ObjectDirection">The object ball's direction after contact (unit, bed plane), zero without a ball.</param>
/// <param name="Pocket">The easiest pocket for <paramref name="Ball"/>, or none.</param>
public sealed record AimPreview(BallId? Ball, Vec3 Ghost, Vec3 ObjectDirection, PocketId Pocket)
{
    /// <summary>How far the path is drawn when it meets no ball and the table is not known (m).</summary>
    public const double FreeLength = 1.0;

    /// <summary>How far the bank off the cushion is drawn at most (m).</summary>
    public const double BankLength = 0.5;

    /// <summary>The end of the bank off the cushion (the mirror of the path, stopped at the next cushion), or null.</summary>
    public Vec3? Bank { get; init; }

    /// <summary>
    /// The distance (m) from a ball's centre at <paramref name="from"/> along <paramref name="direction"/>
    /// (unit, bed plane) to where that ball touches a cushion nose line: its centre one radius inside
    /// the nose rectangle. Infinity for a zero direction.
    /// </summary>
    public static double ToCushion(Vec3 from, Vec3 direction, TableSpec table, double radius)
    {
        ArgumentNullException.ThrowIfNull(table);
        return table.DistanceToCushion(from, direction, radius);
    }

    /// <summary>Computes the preview from the cue ball along <paramref name="direction"/> (bed plane).</summary>
    /// <param name="balls">Every ball's state.</param>
    /// <param name="ids">The balls' ids, index for index.</param>
    /// <param name="cueIndex">Index of the cue ball.</param>
    /// <param name="direction">The aim (need not be unit; z is ignored).</param>
    /// <param name="radius">Ball radius (m).</param>
    /// <param name="pockets">The pockets' capture circles.</param>
    /// <param name="pocketSet">The table's pockets, which the circles' indices name.</param>
    /// <param name="table">The table: the path stops at its cushions and banks off them; null draws <see cref="FreeLength"/>.</param>
    public static AimPreview Compute(ReadOnlySpan<BallState> balls, IReadOnlyList<BallId> ids, int cueIndex, Vec3 direction, double radius, ReadOnlySpan<PocketCircle> pockets, PocketSet pocketSet, TableSpec? table = null)
    {
        var start = balls[cueIndex].Position with { Z = 0 };
        var d = (direction with { Z = 0 }).Normalized();
        double cushion = table is null ? double.PositiveInfinity : ToCushion(start, d, table, radius);
        double best = cushion;
        int hit = -1;
        for (int i = 0; i < balls.Length; i++)
        {
            if (i == cueIndex || balls[i].IsPocketed)
            {
                continue;
            }
            var rel = (balls[i].Position with { Z = 0 }) - start;
            double along = Vec3.Dot(rel, d);
            double side2 = Vec3.Dot(rel, rel) - along * along;
            double reach2 = 4 * radius * radius - side2;
            if (along <= 0 || reach2 < 0)
            {
                continue;
            }
            double t = along - Math.Sqrt(reach2);
            if (t < best)
            {
                best = t;
                hit = i;
            }
        }
        if (hit < 0 && table is null)
        {
            return new AimPreview(null, start + FreeLength * d, Vec3.Zero, PocketId.None);
        }
        if (hit < 0)
        {
            var rail = start + cushion * d;
            // The mirror bank: the component square to the cushion it reached turns round.
            bool end = Math.Abs(Math.Abs(rail.X) - (table!.HalfLength - radius)) < 1e-9;
            var banked = end ? d with { X = -d.X } : d with { Y = -d.Y };
            double run = Math.Min(BankLength, ToCushion(rail, banked, table, radius));
            return new AimPreview(null, rail, Vec3.Zero, PocketId.None) { Bank = rail + run * banked };
        }
        var ghost = start + best * d;
        var target = balls[hit].Position with { Z = 0 };
        var objectDirection = (target - ghost).Normalized();
        return new AimPreview(ids[hit], ghost, objectDirection, EasiestPocket(target, objectDirection, pockets, pocketSet));
    }

    /// <summary>The pocket whose direction from <paramref name="ball"/> is closest to <paramref name="heading"/>, nearer ones first among equals.</summary>
    public static PocketId EasiestPocket(Vec3 ball, Vec3 heading, ReadOnlySpan<PocketCircle> pockets, PocketSet pocketSet, Func<PocketId, bool>? allowed = null)
    {
        ArgumentNullException.ThrowIfNull(pocketSet);
        double bestScore = double.NegativeInfinity;
        var best = PocketId.None;
        foreach (var pocket in pockets)
        {
            if (allowed is not null && !allowed(pocketSet.Id(pocket.Pocket)))
            {
                continue;
            }
            var to = (pocket.Centre with { Z = 0 }) - ball;
            double distance = to.Length;
            if (distance < 1e-9)
            {
                return pocketSet.Id(pocket.Pocket);
            }
            // Cosine of the cut, less a little for distance: a straight pot far away beats a thin cut near by.
            double score = Vec3.Dot(to, heading) / distance - 0.05 * distance;
            if (score > bestScore)
            {
                bestScore = score;
                best = pocketSet.Id(pocket.Pocket);
            }
        }
        return best;
    }
}
