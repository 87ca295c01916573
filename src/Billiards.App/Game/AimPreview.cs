using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// Where the aimed shot goes first, by ghost-ball geometry on the bed: the first object ball the
/// cue ball's path meets, the ghost ball (the cue ball's centre at contact), the object ball's
/// direction after contact (along the line of centres), and the easiest pocket for that ball
/// (the smallest cut angle, then the shortest distance). Throw, squirt and cushions are ignored:
/// it is an aid for the player and the default call, not a prediction of the physics.
/// </summary>
/// <param name="Ball">The first object ball hit, or null when the path meets none.</param>
/// <param name="Ghost">The cue ball's centre at contact, or the end of the path drawn (m).</param>
/// <param name="ObjectDirection">The object ball's direction after contact (unit, bed plane), zero without a ball.</param>
/// <param name="Pocket">The easiest pocket for <paramref name="Ball"/>, or none.</param>
public sealed record AimPreview(BallId? Ball, Vec3 Ghost, Vec3 ObjectDirection, PocketId Pocket)
{
    /// <summary>How far the path is drawn when it meets no ball (m).</summary>
    public const double FreeLength = 1.0;

    /// <summary>Computes the preview from the cue ball along <paramref name="direction"/> (bed plane).</summary>
    /// <param name="balls">Every ball's state.</param>
    /// <param name="ids">The balls' ids, index for index.</param>
    /// <param name="cueIndex">Index of the cue ball.</param>
    /// <param name="direction">The aim (need not be unit; z is ignored).</param>
    /// <param name="radius">Ball radius (m).</param>
    /// <param name="pockets">The pockets' capture circles.</param>
    public static AimPreview Compute(ReadOnlySpan<BallState> balls, IReadOnlyList<BallId> ids, int cueIndex, Vec3 direction, double radius, ReadOnlySpan<PocketCircle> pockets)
    {
        var start = balls[cueIndex].Position with { Z = 0 };
        var d = (direction with { Z = 0 }).Normalized();
        double best = double.PositiveInfinity;
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
        if (hit < 0)
        {
            return new AimPreview(null, start + FreeLength * d, Vec3.Zero, PocketId.None);
        }
        var ghost = start + best * d;
        var target = balls[hit].Position with { Z = 0 };
        var objectDirection = (target - ghost).Normalized();
        return new AimPreview(ids[hit], ghost, objectDirection, EasiestPocket(target, objectDirection, pockets));
    }

    /// <summary>The pocket whose direction from <paramref name="ball"/> is closest to <paramref name="heading"/>, nearer ones first among equals.</summary>
    public static PocketId EasiestPocket(Vec3 ball, Vec3 heading, ReadOnlySpan<PocketCircle> pockets)
    {
        double bestScore = double.NegativeInfinity;
        var best = PocketId.None;
        foreach (var pocket in pockets)
        {
            var to = (pocket.Centre with { Z = 0 }) - ball;
            double distance = to.Length;
            if (distance < 1e-9)
            {
                return PocketIds.FromIndex(pocket.Pocket);
            }
            // Cosine of the cut, less a little for distance: a straight pot far away beats a thin cut near by.
            double score = Vec3.Dot(to, heading) / distance - 0.05 * distance;
            if (score > bestScore)
            {
                bestScore = score;
                best = PocketIds.FromIndex(pocket.Pocket);
            }
        }
        return best;
    }
}
