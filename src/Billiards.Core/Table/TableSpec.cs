namespace Billiards.Core.Table;

/// <summary>
/// Configuration of a table: the playing area between the cushion noses and its pockets.
/// Immutable; build one from a preset with <see cref="FromPreset"/> and override with `with`.
/// Origin at the centre of the bed, x along the length towards the foot rail, y across, z up.
/// </summary>
/// <param name="Preset">The preset this table came from.</param>
/// <param name="Length">Playing length between the cushion noses (m).</param>
/// <param name="Width">Playing width between the cushion noses (m).</param>
/// <param name="CushionHeight">Height of the cushion nose's contact point above the bed (m).</param>
/// <param name="Pockets">
/// The table's pockets, each with its name, place and mouth (<see cref="PocketSet.Six"/> for a
/// pool or snooker table, <see cref="PocketSet.None"/> for a pocketless, carom-style rectangle).
/// </param>
/// <param name="SightOffset">Distance of the sights behind the cushion nose (m).</param>
/// <param name="RailHeight">
/// Height of the top of the rails above the bed (m): a ball in the air whose bottom is above it
/// passes over the cushions. Default <see cref="DefaultRailHeight"/>.
/// </param>
/// <param name="JawNoseRadius">
/// Radius of the rounded tips where a rail turns into a pocket's jaw (m): pool's sharp 5 mm
/// (<see cref="TableGeometry.NoseRadius"/>), snooker's rounded pockets more.
/// </param>
/// <param name="RailWidth">
/// Width of a rail from the cushion's nose to the rail's outer edge, cushion included (m): a ball
/// in the air that comes down beyond it lands on the floor, off the table. Default
/// <see cref="DefaultRailWidth"/>.
/// </param>
public sealed record TableSpec(
    string Preset,
    double Length,
    double Width,
    double CushionHeight,
    PocketSet Pockets,
    double SightOffset,
    double RailHeight = TableSpec.DefaultRailHeight,
    double JawNoseRadius = TableGeometry.NoseRadius,
    double RailWidth = TableSpec.DefaultRailWidth)
{
    /// <summary>
    /// Default width of a rail, cushion included: 5.5 in (139.7 mm) from the cushion's nose to the
    /// rail's outer edge, every preset's (ours: the WPA asks for 4 to 7.5 in; the sights, 93.7 mm
    /// behind the nose, sit on the rail cap inside it).
    /// </summary>
    public const double DefaultRailWidth = 5.5 * 0.0254;

    /// <summary>
    /// Default top of the rails: 1.75 in (44.45 mm) above the bed, every preset's (ours: the WPA
    /// gives no figure; the rail cap of a pool table stands a little above the cushion's nose, at
    /// about 0.78 of the ball's diameter).
    /// </summary>
    public const double DefaultRailHeight = 1.75 * 0.0254;

    /// <summary>False for a pocketless (carom-style) rectangle.</summary>
    public bool HasPockets => Pockets.Count > 0;

    /// <summary>Default cushion contact height: 0.64 of the ball diameter (physics-standard-model.md).</summary>
    public const double DefaultCushionHeight = 0.64 * 2 * 0.028575;

    /// <summary>The names accepted by <see cref="FromPreset"/>.</summary>
    public static IReadOnlyList<string> PresetNames { get; } = ["pool-9ft", "pool-8ft", "pool-7ft", "snooker-12ft", CaromTable.Preset, "thesis", "pocketless"];

    private const double Inch = 0.0254;

    /// <summary>
    /// A table preset: WPA 9, 8 and 7 ft pool tables, the WPBSA's 12 ft snooker table
    /// (<see cref="SnookerTable"/>), the UMB's carom match table (<see cref="CaromTable"/>), the thesis table (245 x 127 cm nose to nose, pockets of
    /// 11.2 cm, seed 3.1), and a pocketless 9 ft rectangle.
    /// </summary>
    /// <exception cref="ArgumentException">For an unknown preset name.</exception>
    public static TableSpec FromPreset(string preset) => preset switch
    {
        "pool-9ft" => Pool(preset, 100 * Inch, 50 * Inch),
        "pool-8ft" => Pool(preset, 92 * Inch, 46 * Inch),
        "pool-7ft" => Pool(preset, 78 * Inch, 39 * Inch),
        SnookerTable.Preset => SnookerTable.Spec,
        CaromTable.Preset => CaromTable.Spec,
        // The seed's table (seed 3.1): bed 258 x 140 less two 6.5 cm rails; pockets are cylinders of 11.2 cm.
        // The seed's cushion faces are 60 deg to the bed; its jaws 35 deg (corner) and 70 deg (side) to the rail.
        "thesis" => new TableSpec(preset, 2.45, 1.27, DefaultCushionHeight, PocketSet.Six(0.112, 0.112, 142, 104), 0.0937),
        "pocketless" => Pool(preset, 100 * Inch, 50 * Inch) with { Pockets = PocketSet.None },
        _ => throw new ArgumentException($"unknown table preset '{preset}' (expected one of {string.Join(", ", PresetNames)})", nameof(preset)),
    };

    // WPA: corner mouth 4.5-4.625 in at 142 deg, side mouth 5-5.125 in at 104 deg; sights 93.7 mm behind the nose.
    private static TableSpec Pool(string preset, double length, double width) =>
        new(preset, length, width, DefaultCushionHeight, PocketSet.Six(4.5625 * Inch, 5.0625 * Inch, 142, 104), 0.0937);

    /// <summary>Half the length (m).</summary>
    public double HalfLength => Length / 2;

    /// <summary>Half the width (m).</summary>
    public double HalfWidth => Width / 2;

    /// <summary>
    /// The distance (m) from <paramref name="from"/> along <paramref name="direction"/> (unit, bed
    /// plane) to the cushion nose rectangle shrunk by <paramref name="inset"/> on every side (a
    /// ball's radius: where its centre is when it touches a cushion); infinity for a zero
    /// direction, 0 from outside. Pockets are not gaps here: the rectangle is closed.
    /// </summary>
    public double DistanceToCushion(Mathematics.Vec3 from, Mathematics.Vec3 direction, double inset = 0)
    {
        double hx = HalfLength - inset, hy = HalfWidth - inset, best = double.PositiveInfinity;
        if (Math.Abs(direction.X) > 1e-12)
        {
            best = Math.Min(best, ((Math.Sign(direction.X) * hx) - from.X) / direction.X);
        }
        if (Math.Abs(direction.Y) > 1e-12)
        {
            best = Math.Min(best, ((Math.Sign(direction.Y) * hy) - from.Y) / direction.Y);
        }
        return Math.Max(best, 0);
    }
}
