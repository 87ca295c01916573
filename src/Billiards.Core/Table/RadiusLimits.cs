using System.Globalization;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Table;

/// <summary>
/// The ball radii a table's collision geometry (<see cref="TableGeometry"/>) can hold on the table,
/// for the standard model. Outside them a scene is refused when it loads, because a ball could
/// leave the table:
/// <list type="bullet">
/// <item>the cushion's contact point must lie at or below the top of the ball and at or above its
/// equator (R &lt;= h &lt;= 2R), or the ball rides over the rail or slips under the nose;</item>
/// <item>a ball must fit through the mouths (2R less than the narrower mouth).</item>
/// </list>
/// A small ball in wide jaws needs no refusal: the pocket's capture circle widens to span the
/// channel between the jaws that its centre can reach (<see cref="TableGeometry.Build"/>), so it
/// cannot roll past the circle and off the table (<see cref="CaptureSpansJaws"/> checks it).
/// </summary>
public static class RadiusLimits
{
    /// <summary>The problem with balls of <paramref name="radius"/> (m) on <paramref name="table"/>, or null when they are supported.</summary>
    public static string? Problem(TableSpec table, double radius)
    {
        double h = table.CushionHeight;
        if (radius > h || 2 * radius < h)
        {
            return Format($"a ball of R = {radius} m does not meet the cushions: their contact height {h:0.#####} m must lie between R and 2R (the ball's equator and its top), so R must lie in [{h / 2:0.#####}, {h:0.#####}] m on this table (table.cushion_height changes the height)");
        }
        if (!table.HasPockets)
        {
            return null;
        }
        double mouth = table.Pockets.Min(p => p.Mouth);
        if (2 * radius >= mouth)
        {
            return Format($"a ball of R = {radius} m does not fit through the pockets: its diameter is not less than the narrowest mouth, {mouth:0.####} m");
        }
        return null;
    }

    /// <summary>
    /// True when, at every pocket, the chord of the capture circle across the jaws covers every
    /// point a ball's centre can reach there (at least R from both jaw faces).
    /// </summary>
    public static bool CaptureSpansJaws(TableSpec table, double radius)
    {
        var geometry = TableGeometry.Build(table, radius);
        foreach (var pocket in geometry.Pockets)
        {
            var middle = table.Pockets[pocket.Pocket].MouthMiddle(table);
            var across = (pocket.Centre - middle).Normalized();
            across = new Vec3(-across.Y, across.X, 0);
            string prefix = geometry.PocketName(pocket.Pocket) + "-jaw-";
            var jaws = new List<CushionSegment>(2);
            foreach (var face in geometry.Segments)
            {
                if (geometry.CushionName(face.Feature).StartsWith(prefix, StringComparison.Ordinal))
                {
                    jaws.Add(face);
                }
            }
            if (TableGeometry.ChannelHalfWidth(jaws, pocket.Centre, across, radius) > pocket.Radius + 1e-12)
            {
                return false;
            }
        }
        return true;
    }

    private static string Format(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
