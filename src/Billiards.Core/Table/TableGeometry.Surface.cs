using Billiards.Core.Mathematics;

namespace Billiards.Core.Table;

/// <summary>What lies under a ball in the air where it comes down.</summary>
public enum SurfaceKind : byte
{
    /// <summary>The bed: the ball fits there without touching a cushion or jaw (inside the cushion noses, or on the slate of a pocket's mouth).</summary>
    Bed,

    /// <summary>A pocket's hole.</summary>
    Pocket,

    /// <summary>The top of a cushion or rail (a jaw's included), up to the rail's outer edge.</summary>
    Rail,

    /// <summary>The floor beyond the rails: off the table.</summary>
    Floor,
}

/// <summary>What a ball in the air comes down on, and which one.</summary>
/// <param name="Kind">Bed, hole, rail or floor.</param>
/// <param name="Index">For a <see cref="SurfaceKind.Pocket"/>, the index of its capture circle in <see cref="TableGeometry.Pockets"/>; for a <see cref="SurfaceKind.Rail"/>, the cushion feature nearest the ball's centre; else -1.</param>
public readonly record struct TableSurface(SurfaceKind Kind, int Index);

/// <summary>The surfaces a ball in the air comes down on (docs/flight.md).</summary>
public sealed partial class TableGeometry
{
    // How close to a face a ball's centre may come down and still fit on the bed beside it (m): round-off of a ball touching it.
    private const double FitSlack = 1e-9;

    // Each pocket's jaw faces, by pocket index (empty for a pocketless table).
    private readonly CushionSegment[][] _jaws;

    /// <summary>
    /// What a ball of this geometry's radius whose centre is over <paramref name="centre"/> (bed
    /// plane) lands on when it comes down to the top of the rails:
    /// <list type="bullet">
    /// <item>a pocket's hole: inside its capture circle, or past its mouth's line between its jaws' lines, within half the mouth of the capture circle's centre, where a ball does not fit on the mouth's slate (behind the capture circle's centre, or too close to a jaw);</item>
    /// <item>the bed: where a ball on the bed touches no cushion face or jaw nose, inside the noses' rectangle or on the slate between a mouth's jaws;</item>
    /// <item>a rail: anywhere else inside the rails' outer edge (<see cref="TableSpec.RailWidth"/> beyond the noses): the cushions' and jaws' tops (a ball overlapping one included) and the pockets' backs;</item>
    /// <item>the floor: beyond the rails.</item>
    /// </list>
    /// </summary>
    public TableSurface SurfaceUnder(Vec3 centre)
    {
        var spec = Spec;
        double r = _ballRadius;
        double x = Math.Abs(centre.X), y = Math.Abs(centre.Y);
        if (!(x <= spec.HalfLength + spec.RailWidth && y <= spec.HalfWidth + spec.RailWidth))
        {
            return new TableSurface(SurfaceKind.Floor, -1);
        }
        for (int k = 0; k < _pockets.Length; k++)
        {
            var circle = _pockets[k];
            if ((centre - circle.Centre).XY.LengthSquared <= circle.Radius * circle.Radius)
            {
                return new TableSurface(SurfaceKind.Pocket, k);
            }
            var pocket = spec.Pockets[circle.Pocket];
            var fromMouth = (centre - pocket.MouthMiddle(spec)).XY;
            double behind = Vec3.Dot(fromMouth, pocket.Outward);
            double reach = pocket.Mouth / 2 + JawLength;
            if (behind <= 0 || fromMouth.LengthSquared > reach * reach)
            {
                continue;
            }
            // Past the mouth's line: between the jaws' lines the mouth's slate, then the hole (a
            // disc as wide as the mouth around the capture circle's centre), then the pocket's
            // back; outside them the jaws' bodies.
            double gap = double.PositiveInfinity;
            foreach (var jaw in _jaws[circle.Pocket])
            {
                gap = Math.Min(gap, Vec3.Dot(jaw.Normal, centre - jaw.Start));
            }
            double hole = pocket.Mouth / 2;
            if (gap < 0)
            {
                return new TableSurface(SurfaceKind.Rail, NearestFeature(centre));
            }
            if (behind < r && gap >= r - FitSlack)
            {
                return new TableSurface(SurfaceKind.Bed, -1);
            }
            return (centre - circle.Centre).XY.LengthSquared <= hole * hole
                ? new TableSurface(SurfaceKind.Pocket, k)
                : new TableSurface(SurfaceKind.Rail, NearestFeature(centre));
        }
        if (x <= spec.HalfLength && y <= spec.HalfWidth && Fits(centre))
        {
            return new TableSurface(SurfaceKind.Bed, -1);
        }
        return new TableSurface(SurfaceKind.Rail, NearestFeature(centre));
    }

    // True when a ball on the bed centred at `centre` touches no cushion face or jaw nose.
    private bool Fits(Vec3 centre) => CushionDepth(centre) <= FitSlack;

    /// <summary>
    /// How deep a ball of this geometry's radius on the bed with its centre at
    /// <paramref name="centre"/> (bed plane) reaches into the cushions (m): its largest overlap
    /// with a cushion face or jaw nose, 0 when it touches none (a ball resting against a cushion
    /// has 0, give or take round-off).
    /// </summary>
    public double CushionDepth(Vec3 centre)
    {
        double r = _ballRadius;
        double depth = 0;
        foreach (ref readonly var s in _segments.AsSpan())
        {
            var d = centre - s.Start;
            double along = Vec3.Dot(d, s.Direction);
            if (along >= 0 && along <= s.Length)
            {
                depth = Math.Max(depth, r - Vec3.Dot(s.Normal, d.XY));
            }
        }
        foreach (ref readonly var nose in _noses.AsSpan())
        {
            depth = Math.Max(depth, r + nose.Radius - (centre - nose.Centre).XY.Length);
        }
        return depth;
    }

    // The cushion or jaw face nearest `centre` (its feature), for the log of a landing on a rail.
    private int NearestFeature(Vec3 centre)
    {
        double best = double.PositiveInfinity;
        int feature = -1;
        foreach (ref readonly var s in _segments.AsSpan())
        {
            var d = (centre - s.Start).XY;
            double along = Math.Clamp(Vec3.Dot(d, s.Direction), 0, s.Length);
            double distance = (d - s.Direction * along).LengthSquared;
            if (distance < best)
            {
                (best, feature) = (distance, s.Feature);
            }
        }
        return feature;
    }
}
