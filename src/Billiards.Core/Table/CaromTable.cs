using Billiards.Core.Mathematics;

namespace Billiards.Core.Table;

/// <summary>
/// The UMB's match table for three-cushion carom (<c>carom-match</c>, rules.md "Three-cushion
/// carom"): a pocketless rectangle of 2.84 x 1.42 m between the cushion noses with a K-55 carom
/// cushion whose nose stands 37 mm above the cloth, its spots and its diamonds.
/// </summary>
/// <remarks>
/// Sources: the UMB's World Rules of Carom Billiards (the table article) as rules.md's section
/// takes them: the playing surface between the cushion noses 2.84 m x 1.42 m, the cushion nose
/// 37 mm above the cloth, balls of 61.5 mm; the sights (diamonds) divide the length in eight and
/// the width in four; the foot (red) spot and the head spot a quarter of the length from the
/// short cushions on the long axis, and the breaker's ball on the head string 18.26 cm to either
/// side of the head spot (rules.md, after the USBA 2009 wording). K-55 is the cushion profile of
/// carom tables (pool's is K-66): a lower, harder nose for the larger ball. What the physics needs
/// from the profile is the height of its nose, where the ball meets the cushion, at
/// sin(theta) = (h - R) / R above the ball's equator (<see cref="ContactAngle"/>): 11.7 deg for
/// h = 37 mm and R = 30.75 mm, where pool's nose at 0.64 of the diameter gives 16.3 deg. The
/// rails' top (45 mm) and the sights' distance behind the nose are ours.
/// </remarks>
public static class CaromTable
{
    /// <summary>The preset's name in scene files.</summary>
    public const string Preset = "carom-match";

    /// <summary>Playing length between the cushion noses (m, UMB: 2.84 m).</summary>
    public const double Length = 2.84;

    /// <summary>Playing width between the cushion noses (m, UMB: 1.42 m).</summary>
    public const double Width = 1.42;

    /// <summary>Height of the K-55 cushion's nose above the cloth (m, UMB: 37 mm), where a ball meets it.</summary>
    public const double NoseHeight = 0.037;

    /// <summary>Top of the rails above the cloth (m, ours).</summary>
    public const double RailHeight = 0.045;

    /// <summary>Distance of the sights behind the cushion nose (m, ours: the rail's width to the diamond inlays).</summary>
    public const double SightOffset = 0.0937;

    /// <summary>Sights on a long rail: the length in <see cref="DiamondDivisions"/> (the diamonds at 1/8 .. 7/8).</summary>
    public const int DiamondDivisions = 8;

    /// <summary>Distance of the breaker's ball from the head spot along the head string (m, 182.6 mm).</summary>
    public const double BreakOffset = 0.1826;

    /// <summary>The preset: 2.84 x 1.42 m, no pockets, the nose at 37 mm.</summary>
    public static TableSpec Spec { get; } = new(Preset, Length, Width, NoseHeight, PocketSet.None, SightOffset, RailHeight: RailHeight);

    /// <summary>The spacing of the diamonds on <paramref name="table"/> (m): 1/8 of its length, which is also 1/4 of its width.</summary>
    public static double DiamondSpacing(TableSpec table)
    {
        ArgumentNullException.ThrowIfNull(table);
        return table.Length / DiamondDivisions;
    }

    /// <summary>
    /// The angle (rad) above a ball's equator at which a cushion of contact height
    /// <paramref name="noseHeight"/> meets a ball of radius <paramref name="radius"/>: asin((h - R) / R).
    /// </summary>
    public static double ContactAngle(double noseHeight, double radius) => DeterministicMath.Asin((noseHeight - radius) / radius);

    /// <summary>The foot spot (the red's): a quarter of the length from the foot cushion (m, z = <paramref name="radius"/>).</summary>
    public static Vec3 FootSpot(TableSpec table, double radius) => new(table.HalfLength / 2, 0, radius);

    /// <summary>The head spot (the opponent's ball at the break): a quarter of the length from the head cushion.</summary>
    public static Vec3 HeadSpot(TableSpec table, double radius) => new(-table.HalfLength / 2, 0, radius);

    /// <summary>The centre spot.</summary>
    public static Vec3 CentreSpot(double radius) => new(0, 0, radius);

    /// <summary>The breaker's spot: on the head string, <see cref="BreakOffset"/> from the head spot (to +y, ours; the rules let the breaker take either side).</summary>
    public static Vec3 BreakerSpot(TableSpec table, double radius) => HeadSpot(table, radius) with { Y = BreakOffset };
}
