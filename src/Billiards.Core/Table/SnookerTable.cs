using Billiards.Core.Mathematics;

namespace Billiards.Core.Table;

/// <summary>
/// The WPBSA's full-size snooker table (<c>snooker-12ft</c>, rules.md "Snooker") and its markings:
/// the baulk line, the D and the six colour spots. x runs from the baulk (head) cushion towards
/// the top cushion, y to the left as seen from baulk, the origin at the centre of the bed.
/// </summary>
/// <remarks>
/// Sources: WPBSA, Official Rules of the Games of Snooker and English Billiards, section 1 ("The
/// Standard Table"): playing area 11 ft 8 1/2 in x 5 ft 10 in (3569 x 1778 mm) between the
/// cushion faces, the baulk line 29 in (737 mm) from the bottom cushion, the D of radius 11 1/2 in
/// (292 mm), the black spot 12 3/4 in (324 mm) from the top cushion, the pink midway between the
/// centre and the top cushion. The rules do not print the pocket openings: they "shall conform to
/// the templates authorised by the WPBSA". We take the figures commonly quoted for those templates,
/// a corner opening of 86 mm and a middle opening of 92 mm measured between the cushion noses
/// (rules.md), with jaws running straight into the pocket (parallel to its axis: 135 deg from the
/// rail at a corner, 90 deg at the middle) behind rounded noses of 20 mm radius (ours, in place of
/// the template's curve; pool's jaws converge at the WPA's 142 and 104 deg behind sharp 5 mm tips).
/// The cushion's contact height is 0.64 of the ball's diameter, as on the pool tables
/// (physics-standard-model.md), and the rail's top 0.78 of it.
/// </remarks>
public static class SnookerTable
{
    /// <summary>The preset's name in scene files.</summary>
    public const string Preset = "snooker-12ft";

    /// <summary>Playing length between the cushion noses (m).</summary>
    public const double Length = 3.569;

    /// <summary>Playing width between the cushion noses (m).</summary>
    public const double Width = 1.778;

    /// <summary>Ball diameter of snooker (m, WPBSA: 52.5 mm).</summary>
    public const double BallDiameter = 0.0525;

    /// <summary>Corner pocket opening between the cushion noses (m, ours after the WPBSA template: 86 mm).</summary>
    public const double CornerOpening = 0.086;

    /// <summary>Middle pocket opening between the cushion noses (m, ours after the WPBSA template: 92 mm).</summary>
    public const double MiddleOpening = 0.092;

    /// <summary>Radius of the rounded cushion noses at the pockets (m, ours).</summary>
    public const double JawNoseRadius = 0.02;

    /// <summary>Distance of the baulk line from the baulk cushion (m, WPBSA: 29 in).</summary>
    public const double BaulkLineDistance = 0.737;

    /// <summary>Radius of the D (m, WPBSA: 11 1/2 in).</summary>
    public const double DRadius = 0.292;

    /// <summary>Distance of the black spot from the top cushion (m, WPBSA: 12 3/4 in).</summary>
    public const double BlackSpotDistance = 0.324;

    /// <summary>The preset: 3.569 x 1.778 m, corner openings 86 mm, middle 92 mm, rounded jaws.</summary>
    public static TableSpec Spec { get; } = new(
        Preset, Length, Width, 0.64 * BallDiameter, PocketSet.Six(CornerOpening, MiddleOpening, 135, 90), 0.0937,
        RailHeight: 0.78 * BallDiameter, JawNoseRadius: JawNoseRadius);

    /// <summary>x of the baulk line on <paramref name="table"/> (m).</summary>
    public static double BaulkLineX(TableSpec table)
    {
        ArgumentNullException.ThrowIfNull(table);
        return -table.HalfLength + BaulkLineDistance;
    }

    /// <summary>The colour spots on <paramref name="table"/> by the colour's name (m, z = <paramref name="radius"/>).</summary>
    /// <exception cref="ArgumentException">For a name that is not one of the six colours.</exception>
    public static Vec3 Spot(TableSpec table, string colour, double radius)
    {
        ArgumentNullException.ThrowIfNull(table);
        double baulk = BaulkLineX(table);
        return colour switch
        {
            "yellow" => new Vec3(baulk, -DRadius, radius),
            "green" => new Vec3(baulk, DRadius, radius),
            "brown" => new Vec3(baulk, 0, radius),
            "blue" => new Vec3(0, 0, radius),
            "pink" => new Vec3(table.HalfLength / 2, 0, radius),
            "black" => new Vec3(table.HalfLength - BlackSpotDistance, 0, radius),
            _ => throw new ArgumentException($"\"{colour}\" is not a colour of snooker", nameof(colour)),
        };
    }

    /// <summary>
    /// True when a cue ball centred at <paramref name="position"/> (m) stands in the D: its centre
    /// on or behind the baulk line and within <see cref="DRadius"/> of the brown spot (the line
    /// and the arc count as in, as the rules make the line part of baulk), to
    /// <paramref name="tolerance"/> (m).
    /// </summary>
    public static bool InD(TableSpec table, Vec3 position, double tolerance = 1e-9)
    {
        ArgumentNullException.ThrowIfNull(table);
        double baulk = BaulkLineX(table);
        double dx = position.X - baulk;
        return dx <= tolerance && dx * dx + position.Y * position.Y <= (DRadius + tolerance) * (DRadius + tolerance);
    }
}
