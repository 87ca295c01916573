using Billiards.Core.Mathematics;

namespace Billiards.Core.Table;

/// <summary>
/// Where a ball that is not pocketed may be, in either model: the table-bound guarantee's test.
/// A ball on the table has its centre on the bed between the cushion noses, or in a pocket's
/// mouth (rattling in the jaws, or come to rest there before dropping). Anything else has escaped.
/// </summary>
public static class TableBounds
{
    /// <summary>Slack for round-off at the nose lines (m).</summary>
    public const double Tolerance = 1e-9;

    /// <summary>
    /// True when a ball of radius <paramref name="radius"/> (m) with its centre at
    /// <paramref name="centre"/> lies on <paramref name="table"/>: inside the rectangle of the
    /// cushion noses, or (on a table with pockets) within half the mouth plus a ball's diameter of
    /// the middle of a pocket's mouth.
    /// </summary>
    public static bool Contains(TableSpec table, Vec3 centre, double radius)
    {
        if (!double.IsFinite(centre.X) || !double.IsFinite(centre.Y))
        {
            return false;
        }
        double x = Math.Abs(centre.X), y = Math.Abs(centre.Y);
        if (x <= table.HalfLength + Tolerance && y <= table.HalfWidth + Tolerance)
        {
            return true;
        }
        if (!table.HasPockets)
        {
            return false;
        }
        foreach (var pocket in table.Pockets)
        {
            var middle = pocket.MouthMiddle(table);
            double reach = pocket.Mouth / 2 + 2 * radius;
            if (Square(centre.X - middle.X) + Square(centre.Y - middle.Y) <= reach * reach)
            {
                return true;
            }
        }
        return false;
    }

    private static double Square(double v) => v * v;
}
