using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard.Events;

/// <summary>
/// The table features' bounding boxes (xmin, ymin, xmax, ymax), grown by R, that the predictor
/// tests a ball's path box against before solving for a contact. Immutable: shared by every
/// simulation of one table.
/// </summary>
internal sealed class FeatureBoxes
{
    /// <summary>The boxes of the geometry's features for balls of radius <paramref name="r"/> (m).</summary>
    public FeatureBoxes(TableGeometry geometry, double r)
    {
        var segments = geometry.Segments;
        Segments = new (double, double, double, double)[segments.Length];
        for (int s = 0; s < segments.Length; s++)
        {
            var g = segments[s];
            Segments[s] = (Math.Min(g.Start.X, g.End.X) - r, Math.Min(g.Start.Y, g.End.Y) - r,
                Math.Max(g.Start.X, g.End.X) + r, Math.Max(g.Start.Y, g.End.Y) + r);
        }
        var noses = geometry.Noses;
        Noses = new (double, double, double, double)[noses.Length];
        for (int s = 0; s < noses.Length; s++)
        {
            double e = noses[s].Radius + r;
            Noses[s] = (noses[s].Centre.X - e, noses[s].Centre.Y - e, noses[s].Centre.X + e, noses[s].Centre.Y + e);
        }
        var pockets = geometry.Pockets;
        Pockets = new (double, double, double, double)[pockets.Length];
        for (int s = 0; s < pockets.Length; s++)
        {
            double e = pockets[s].Radius;
            Pockets[s] = (pockets[s].Centre.X - e, pockets[s].Centre.Y - e, pockets[s].Centre.X + e, pockets[s].Centre.Y + e);
        }
    }

    /// <summary>Cushion and jaw faces.</summary>
    public (double X0, double Y0, double X1, double Y1)[] Segments { get; }

    /// <summary>Jaw noses.</summary>
    public (double X0, double Y0, double X1, double Y1)[] Noses { get; }

    /// <summary>Pocket capture circles.</summary>
    public (double X0, double Y0, double X1, double Y1)[] Pockets { get; }
}
