using System.Numerics;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Thesis;

/// <summary>
/// The table as the thesis model sees it, in the seed's units (cm) and frame (Y up, x along the
/// length, +x the foot, origin at the centre): the playing area between the cushion noses,
/// the rails and pocket throats that <see cref="Setup.Initializer.InitRails"/> builds the
/// collision triangles from, and the pocket test of Formel 30 / Listing 4.
/// </summary>
/// <remarks>
/// <para>The seed (3.1) gives its table as boxes: rails 6.5 deep, head and foot rail boxes 124.5
/// long on a bed 140 wide, long-rail boxes 115.76 long on a bed 258 long, jaws cut at 35 deg
/// (corner) and 70 deg (side) to the rail. We read the jaw angle as the angle between the jaw
/// face and the cushion line, the only reading that fits the boxes: it makes the gap at the back
/// of the rails (the pocket's throat) 7.75 * sqrt(2) = 10.96 cm at a corner and
/// 258 - 2 * 7.75 - 2 * 115.76 = 10.98 cm at a side, both the "11" the seed gives as its pocket
/// diameter, with the mouth opening wider towards the table, as on a real table.</para>
/// <para>Listing 4 tests the pockets at (124.5, 65.5) and (0, 69) with a radius of 4.5, only when
/// |x| &gt; 117 or |z| &gt; 58. In terms of the construction these are: corner centre 0.625 cm
/// (each axis) in front of the middle of the throat, side centre 1 cm in front of it, and the
/// zone 5.5 cm inside the noses. Other presets use the same construction with their own length,
/// width and mouths (a mouth in <see cref="TableSpec"/> is taken as the throat, as the thesis
/// preset's 11.2 cm pocket diameter is), and the test radius grows with the throat, so that a
/// ball stopped by a pocket's back wall is always inside its test circle.</para>
/// </remarks>
public sealed class ThesisTable
{
    /// <summary>Depth of the rails, cushion nose to the edge of the bed (cm, seed 3.1).</summary>
    public const float RailDepth = 6.5f;

    /// <summary>Angle between a corner jaw and its cushion line (deg, seed 3.1).</summary>
    public const float CornerJawDeg = 35f;

    /// <summary>Angle between a side jaw and its cushion line (deg, seed 3.1).</summary>
    public const float SideJawDeg = 70f;

    /// <summary>Radius of the seed's pocket test (cm, seed 4.3.5): smaller than the pocket so the ball does not fall through the table's edge.</summary>
    public const float SeedPocketTestRadius = 4.5f;

    /// <summary>Throat of the seed's corner pockets along each rail (cm): (140 - 124.5) / 2.</summary>
    public const float SeedCornerGap = 7.75f;

    /// <summary>Throat of the seed's side pockets (cm): 258 - 2 * 7.75 - 2 * 115.76.</summary>
    public const float SeedSideGap = 10.98f;

    private const float CornerCentreInset = 0.625f; // 124.5 = 122.5 + 6.5 - 7.75 / 2 - 0.625
    private const float SideCentreInset = 1f;        // 69 = 63.5 + 6.5 - 1
    private const float ZoneInset = 5.5f;            // 117 = 122.5 - 5.5, 58 = 63.5 - 5.5

    private ThesisTable(float halfLength, float halfWidth, bool hasPockets, float cornerGap, float sideGap)
    {
        HalfLength = halfLength;
        HalfWidth = halfWidth;
        HasPockets = hasPockets;
        CornerGap = cornerGap;
        SideGap = sideGap;
        CornerPocket = new Vector3(halfLength + RailDepth - cornerGap / 2 - CornerCentreInset, 0, halfWidth + RailDepth - cornerGap / 2 - CornerCentreInset);
        SidePocket = new Vector3(0, 0, halfWidth + RailDepth - SideCentreInset);
        // Ratios first: for the thesis table they are exactly 1, so the radius is exactly the seed's 4.5.
        CornerPocketRadius = SeedPocketTestRadius * (cornerGap / SeedCornerGap);
        SidePocketRadius = SeedPocketTestRadius * (sideGap / SeedSideGap);
        PocketZoneX = halfLength - ZoneInset;
        PocketZoneZ = halfWidth - ZoneInset;
    }

    /// <summary>Half the length between the cushion noses (cm); 122.5 for the thesis table.</summary>
    public float HalfLength { get; }

    /// <summary>Half the width between the cushion noses (cm); 63.5 for the thesis table.</summary>
    public float HalfWidth { get; }

    /// <summary>False for a plain cushioned rectangle.</summary>
    public bool HasPockets { get; }

    /// <summary>Gap a corner pocket leaves at the back of each of its two rails (cm).</summary>
    public float CornerGap { get; }

    /// <summary>Gap a side pocket leaves at the back of its rail (cm).</summary>
    public float SideGap { get; }

    /// <summary>Centre of the corner pocket test in the (+x, +z) quadrant (cm); (124.5, 0, 65.5) for the thesis table.</summary>
    public Vector3 CornerPocket { get; }

    /// <summary>Centre of the side pocket test on the +z side (cm); (0, 0, 69) for the thesis table.</summary>
    public Vector3 SidePocket { get; }

    /// <summary>Radius of the corner pocket test (cm); 4.5 for the thesis table.</summary>
    public float CornerPocketRadius { get; }

    /// <summary>Radius of the side pocket test (cm); 4.5 for the thesis table.</summary>
    public float SidePocketRadius { get; }

    /// <summary>The pocket test only runs when |x| exceeds this (cm); 117 for the thesis table.</summary>
    public float PocketZoneX { get; }

    /// <summary>The pocket test only runs when |z| exceeds this (cm); 58 for the thesis table.</summary>
    public float PocketZoneZ { get; }

    /// <summary>The thesis model's view of a table.</summary>
    /// <exception cref="ArgumentException">
    /// For a table whose pockets are not the six of <see cref="PocketSet.Six"/> in its order, with
    /// one mouth for the corners and one for the sides: the seed's construction and its pocket
    /// test know no other (a pocketless table is fine).
    /// </exception>
    public static ThesisTable From(TableSpec table)
    {
        ArgumentNullException.ThrowIfNull(table);
        var pockets = table.Pockets;
        bool six = pockets.Count == 0 || (pockets.Count == 6 && pockets.Equals(PocketSet.Six(pockets[0].Mouth, pockets[2].Mouth, pockets[0].JawAngleDeg, pockets[2].JawAngleDeg)));
        if (!six)
        {
            throw new ArgumentException($"the thesis model knows tables with the six pockets of a pool table (one corner mouth, one side mouth), not {pockets}", nameof(table));
        }
        float halfLength = (float)(table.HalfLength * 100);
        float halfWidth = (float)(table.HalfWidth * 100);
        // The thesis table keeps the seed's box-derived throats; any other table its own mouths
        // (a corner mouth is measured across the diagonal, so each rail leaves mouth / sqrt 2).
        bool seedTable = table.Preset == "thesis";
        // A pocketless table has no throats; its pocket test never runs.
        float cornerGap = seedTable ? SeedCornerGap : pockets.Count == 0 ? 0 : (float)(pockets[0].Mouth * 100 / Math.Sqrt(2));
        float sideGap = seedTable ? SeedSideGap : pockets.Count == 0 ? 0 : (float)(pockets[2].Mouth * 100);
        return new ThesisTable(halfLength, halfWidth, table.HasPockets, cornerGap, sideGap);
    }

    /// <summary>
    /// The pocket test of Formel 30 and Listing 4: only near the cushions (|x| &gt; 117 or
    /// |z| &gt; 58), mirror the ball into the (+x, +z) quadrant and measure the distance to the
    /// corner and then the side pocket centre; closer than the test radius means pocketed.
    /// </summary>
    /// <param name="position">Centre of the ball (cm); its height is ignored.</param>
    /// <returns>The pocket index (0 head-left, 1 head-right, 2 side-left, 3 side-right, 4 foot-left, 5 foot-right), or -1.</returns>
    public int PocketAt(Vector3 position)
    {
        if (!HasPockets)
        {
            return -1;
        }
        float ax = MathF.Abs(position.X);
        float az = MathF.Abs(position.Z);
        if (ax > PocketZoneX || az > PocketZoneZ)
        {
            var mirrored = new Vector3(ax, 0, az);
            // +z is the right-hand side seen from the head (SI +y, "left", is seed -z).
            bool right = position.Z >= 0;
            if ((CornerPocket - mirrored).Length() < CornerPocketRadius)
            {
                return position.X >= 0 ? (right ? 5 : 4) : (right ? 1 : 0);
            }
            if ((SidePocket - mirrored).Length() < SidePocketRadius)
            {
                return right ? 3 : 2;
            }
        }
        return -1;
    }
}
