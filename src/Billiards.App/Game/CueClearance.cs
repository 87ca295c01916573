using Billiards.App.Rendering;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// Where the cue and the camera must stay clear of the table: a cue over a rail must be raised
/// until its butt passes above the rail, as a player raises it; the camera stays above the rail's
/// height and above the cue.
/// </summary>
public static class CueClearance
{
    /// <summary>Gap kept between the cue's underside and the rail's top (m).</summary>
    public const double RailGap = 0.005;

    /// <summary>Height of the rail's top above the bed (m): the cushion nose plus the rubber's top (the table model's).</summary>
    public static double RailTop(TableSpec table) => table.CushionHeight + 0.0065;

    /// <summary>
    /// Horizontal distance (m) from a point on the bed backwards along <paramref name="aim"/> (unit,
    /// bed plane) to the nearest cushion nose line; infinity for a zero aim.
    /// </summary>
    public static double DistanceToRail(Vec3 ball, Vec3 aim, TableSpec table)
    {
        double bx = -aim.X, by = -aim.Y, best = double.PositiveInfinity;
        if (Math.Abs(bx) > 1e-12)
        {
            best = Math.Min(best, ((Math.Sign(bx) * table.HalfLength) - ball.X) / bx);
        }
        if (Math.Abs(by) > 1e-12)
        {
            best = Math.Min(best, ((Math.Sign(by) * table.HalfWidth) - ball.Y) / by);
        }
        return Math.Max(best, 0);
    }

    /// <summary>
    /// The least elevation (deg) at which a cue addressing a ball of radius <paramref name="radius"/>
    /// at <paramref name="ball"/> along <paramref name="aim"/> clears the rail behind it: the cue's
    /// underside, rising from the ball's centre height, must be <see cref="RailGap"/> above the rail
    /// top where it crosses the cushion nose (the rail only gets farther and the cue higher beyond).
    /// </summary>
    public static double MinElevationDegrees(Vec3 ball, Vec3 aim, TableSpec table, double radius)
    {
        double s = DistanceToRail(ball, aim, table);
        if (!double.IsFinite(s) || s <= 0)
        {
            return 0;
        }
        // The cue's radius where it crosses the rail (it thickens from tip to butt).
        double along = Math.Min(s, Primitives.CueLength);
        double cueRadius = Primitives.CueTipRadius + ((Primitives.CueButtRadius - Primitives.CueTipRadius) * along / Primitives.CueLength);
        double rise = RailTop(table) + RailGap + cueRadius - radius;
        return rise <= 0 ? 0 : Math.Atan2(rise, s) * 180 / Math.PI;
    }
}
