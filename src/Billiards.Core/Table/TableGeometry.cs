using Billiards.Core.Mathematics;

namespace Billiards.Core.Table;

/// <summary>
/// A straight, one-sided cushion face (a rail's nose line or a pocket jaw) in the bed plane. A
/// ball touches it when its centre is R from the line on the <see cref="Normal"/> side and the
/// foot of the perpendicular lies between <see cref="Start"/> and <see cref="End"/>.
/// </summary>
/// <param name="Start">One end of the face (m, z = 0).</param>
/// <param name="End">The other end (m, z = 0).</param>
/// <param name="Normal">Unit normal in the bed plane, pointing to where the balls are.</param>
/// <param name="Feature">Index of the cushion's name, <see cref="TableGeometry.CushionNames"/>.</param>
public readonly record struct CushionSegment(Vec3 Start, Vec3 End, Vec3 Normal, int Feature)
{
    /// <summary>Unit direction from <see cref="Start"/> to <see cref="End"/>.</summary>
    public Vec3 Direction => (End - Start).Normalized();

    /// <summary>Length of the face (m).</summary>
    public double Length => (End - Start).Length;
}

/// <summary>
/// A circular cushion nose (the rounded tip where a rail meets a pocket jaw), as a vertical
/// cylinder; a ball touches it when its centre is R + <see cref="Radius"/> from the axis.
/// </summary>
/// <param name="Centre">Axis of the nose in the bed plane (m, z = 0).</param>
/// <param name="Radius">Radius of the nose (m).</param>
/// <param name="Feature">Index of the name of the jaw it rounds off.</param>
public readonly record struct CushionNose(Vec3 Centre, double Radius, int Feature);

/// <summary>
/// A pocket's capture circle: a ball is pocketed when its centre enters it.
/// </summary>
/// <param name="Centre">Centre (m, z = 0).</param>
/// <param name="Radius">Radius (m).</param>
/// <param name="Pocket">Index of the pocket in the table's <see cref="TableSpec.Pockets"/>.</param>
public readonly record struct PocketCircle(Vec3 Centre, double Radius, int Pocket);

/// <summary>
/// The collision geometry of a table, built from its <see cref="TableSpec"/>: cushion faces, jaw
/// faces, jaw noses and pocket capture circles, with the names results use. Coordinates as in
/// scene-format.md: origin at the bed's centre, +x towards the foot rail, +y to the left.
/// </summary>
/// <remarks>
/// Pockets (physics-standard-model.md, WPA): the mouth is measured between the points where the
/// rail's nose line meets the jaw's face. Each jaw leaves the rail at the WPA jaw angle (142 deg
/// corner, 104 deg side, measured through the cushion rubber), so the jaws converge towards the
/// back of the pocket. The corner is rounded by a nose of <see cref="TableSpec.JawNoseRadius"/>
/// (pool's sharp <see cref="NoseRadius"/>, snooker's rounder). The
/// capture circle of radius R sits R behind the middle of the mouth line: a ball is pocketed once
/// its centre is past the mouth line and more than half of it hangs over the hole, or it rattles
/// off a jaw first.
/// </remarks>
public sealed partial class TableGeometry
{
    /// <summary>Radius of the rounded jaw tips (m).</summary>
    public const double NoseRadius = 0.005;

    /// <summary>Length of a jaw face from the rail into the pocket (m).</summary>
    public const double JawLength = 0.1;

    private readonly CushionSegment[] _segments;
    private readonly CushionNose[] _noses;
    private readonly PocketCircle[] _pockets;
    private readonly string[] _cushionNames;
    private readonly CushionId[] _cushionIds;

    private TableGeometry(TableSpec spec, double ballRadius, List<CushionSegment> segments, List<CushionNose> noses, List<PocketCircle> pockets, List<string> names, List<CushionId> ids, List<CushionSegment>[] jaws)
    {
        _jaws = [.. jaws.Select(j => j.ToArray())];
        _ballRadius = ballRadius;
        _cushionIds = [.. ids];
        Spec = spec;
        _segments = [.. segments];
        _noses = [.. noses];
        _pockets = [.. pockets];
        _cushionNames = [.. names];
    }

    /// <summary>The table this geometry was built from.</summary>
    public TableSpec Spec { get; }

    /// <summary>Height of the cushion's contact point above the bed (m).</summary>
    public double CushionHeight => Spec.CushionHeight;

    /// <summary>The straight faces: the six rail cushions, then the jaws.</summary>
    public ReadOnlySpan<CushionSegment> Segments => _segments;

    /// <summary>The rounded jaw tips.</summary>
    public ReadOnlySpan<CushionNose> Noses => _noses;

    /// <summary>The pockets' capture circles (empty for a pocketless table).</summary>
    public ReadOnlySpan<PocketCircle> Pockets => _pockets;

    /// <summary>Names of cushions and jaws, by feature index: "head", "foot", "left-head", ..., "foot-left-jaw-foot".</summary>
    public IReadOnlyList<string> CushionNames => _cushionNames;

    /// <summary>The model-independent identity of a cushion or jaw feature (both jaws of a pocket are its jaw), or <see cref="CushionId.None"/>.</summary>
    public CushionId CushionOf(int feature) => (uint)feature < (uint)_cushionIds.Length ? _cushionIds[feature] : CushionId.None;

    /// <summary>The name of a cushion or jaw feature, or "?" for an unknown index.</summary>
    public string CushionName(int feature) => (uint)feature < (uint)_cushionNames.Length ? _cushionNames[feature] : "?";

    /// <summary>The name of a pocket of the table, or "?" for an unknown index.</summary>
    public string PocketName(int pocket) => Spec.Pockets.NameOf(pocket);

    // The last geometry this thread built: loading and running one scene builds its table's
    // geometry several times (the radius check, the placement check, the model), and a batch or
    // a planner builds the same table scene after scene. A geometry never changes once built,
    // and each thread keeps its own, so nothing is shared between threads.
    [ThreadStatic]
    private static TableGeometry? t_last;

    private readonly double _ballRadius;

    /// <summary>
    /// The geometry of a table for balls of radius <paramref name="ballRadius"/> (m): built, or the
    /// one this thread built last when the table and the radius are the same to the bit.
    /// </summary>
    public static TableGeometry Build(TableSpec spec, double ballRadius)
    {
        ArgumentNullException.ThrowIfNull(spec);
        if (t_last is { } last && SameBits(last.Spec, spec) && BitConverter.DoubleToInt64Bits(last._ballRadius) == BitConverter.DoubleToInt64Bits(ballRadius))
        {
            return last;
        }
        var built = BuildNew(spec, ballRadius);
        t_last = built;
        return built;
    }

    // Record equality (every field, a new one too, the pockets by value) takes 0 for -0, and the
    // geometry keeps its spec: the bits of the table's own numbers decide as well (a pocket's
    // mouth and jaw angle are never 0).
    private static bool SameBits(TableSpec a, TableSpec b) =>
        ReferenceEquals(a, b) ||
        (a == b &&
         Bits(a.Length) == Bits(b.Length) && Bits(a.Width) == Bits(b.Width) &&
         Bits(a.CushionHeight) == Bits(b.CushionHeight) && Bits(a.SightOffset) == Bits(b.SightOffset) &&
         Bits(a.RailHeight) == Bits(b.RailHeight) && Bits(a.JawNoseRadius) == Bits(b.JawNoseRadius) &&
         Bits(a.RailWidth) == Bits(b.RailWidth));

    private static long Bits(double x) => BitConverter.DoubleToInt64Bits(x);

    private static TableGeometry BuildNew(TableSpec spec, double ballRadius)
    {
        double hx = spec.HalfLength;
        double hy = spec.HalfWidth;
        var segments = new List<CushionSegment>();
        var noses = new List<CushionNose>();
        var pockets = new List<PocketCircle>();
        var names = new List<string>(CushionId.RailNames);
        var ids = new List<CushionId> { CushionId.Head, CushionId.Foot, CushionId.LeftHead, CushionId.LeftFoot, CushionId.RightHead, CushionId.RightFoot };

        // How far each rail stops short of a pocket at its corner or the middle of its long rail.
        var set = spec.Pockets;
        double Cut(int end, int side) => set.At(end, side)?.RailCut ?? 0;

        // Rail faces, walked so that each runs from its head or right end to its foot or left end.
        var rails = new (Vec3 A, Vec3 B, Vec3 N)[]
        {
            (new Vec3(-hx, -hy + Cut(-1, -1), 0), new Vec3(-hx, hy - Cut(-1, 1), 0), new Vec3(1, 0, 0)),   // head
            (new Vec3(hx, -hy + Cut(1, -1), 0), new Vec3(hx, hy - Cut(1, 1), 0), new Vec3(-1, 0, 0)),      // foot
            (new Vec3(-hx + Cut(-1, 1), hy, 0), new Vec3(-Cut(0, 1), hy, 0), new Vec3(0, -1, 0)),          // left-head
            (new Vec3(Cut(0, 1), hy, 0), new Vec3(hx - Cut(1, 1), hy, 0), new Vec3(0, -1, 0)),             // left-foot
            (new Vec3(-hx + Cut(-1, -1), -hy, 0), new Vec3(-Cut(0, -1), -hy, 0), new Vec3(0, 1, 0)),       // right-head
            (new Vec3(Cut(0, -1), -hy, 0), new Vec3(hx - Cut(1, -1), -hy, 0), new Vec3(0, 1, 0)),          // right-foot
        };

        // Each rail end at a pocket's place: (rail, which end, the place, rail word of the jaw name).
        var ends = new (int Rail, bool AtB, int End, int Side, string RailWord)[]
        {
            (0, true, -1, 1, "head"), (0, false, -1, -1, "head"),
            (1, true, 1, 1, "foot"), (1, false, 1, -1, "foot"),
            (2, false, -1, 1, "left"), (2, true, 0, 1, "head"),
            (3, false, 0, 1, "foot"), (3, true, 1, 1, "left"),
            (4, false, -1, -1, "right"), (4, true, 0, -1, "head"),
            (5, false, 0, -1, "foot"), (5, true, 1, -1, "right"),
        };
        var trimmed = rails.Select(r => (r.A, r.B)).ToArray();
        var jaws = Enumerable.Range(0, set.Count).Select(_ => new List<CushionSegment>(2)).ToArray();
        foreach (var (rail, atB, end, side, railWord) in ends)
        {
            int pocket = set.IndexAt(end, side);
            if (pocket < 0)
            {
                continue;
            }
            var (a, b, nIn) = rails[rail];
            var tip = atB ? b : a;
            var back = ((atB ? a : b) - tip).Normalized(); // along the rail, away from the pocket
            double angle = set[pocket].JawAngleDeg * Math.PI / 180;
            // The jaw turns from the rail through the cushion body (away from the balls) by the
            // jaw angle measured from the direction back along the rail.
            var jaw = back * DeterministicMath.Cos(angle) - nIn * DeterministicMath.Sin(angle);
            // Its face looks to the same side of the boundary as the rail's face does.
            var walk = -back;
            bool leftHanded = walk.X * nIn.Y - walk.Y * nIn.X > 0;
            var jawNormal = leftHanded ? new Vec3(-jaw.Y, jaw.X, 0) : new Vec3(jaw.Y, -jaw.X, 0);

            // Round the corner with a nose tangent to both faces, inside the cushion body.
            double nose = spec.JawNoseRadius;
            double tangent = nose / DeterministicMath.Tan(angle / 2);
            var bisector = (back + jaw).Normalized();
            var noseCentre = tip + bisector * (nose / DeterministicMath.Sin(angle / 2));
            int feature = names.Count;
            names.Add($"{set[pocket].Name}-jaw-{railWord}");
            ids.Add(CushionId.Jaw(set.Id(pocket)));
            noses.Add(new CushionNose(noseCentre, nose, feature));
            var face = new CushionSegment(tip + jaw * tangent, tip + jaw * JawLength, jawNormal, feature);
            segments.Add(face);
            jaws[pocket].Add(face);
            var rt = trimmed[rail];
            trimmed[rail] = atB ? (rt.A, tip + back * tangent) : (tip + back * tangent, rt.B);
        }
        for (int i = 0; i < rails.Length; i++)
        {
            segments.Insert(i, new CushionSegment(trimmed[i].A, trimmed[i].B, rails[i].N, i));
        }

        // Capture circles: R behind the middle of each mouth line, radius R, or wider where the
        // channel a ball's centre can reach between the jaws is wider than the circle there (a
        // small ball in wide jaws): the circle then spans the channel, so no ball can roll past
        // it between the jaws and off the table.
        for (int i = 0; i < set.Count; i++)
        {
            var outward = set[i].Outward;
            var centre = set[i].MouthMiddle(spec) + outward * ballRadius;
            var across = new Vec3(-outward.Y, outward.X, 0);
            pockets.Add(new PocketCircle(centre, Math.Max(ballRadius, ChannelHalfWidth(jaws[i], centre, across, ballRadius)), i));
        }
        return new TableGeometry(spec, ballRadius, segments, noses, pockets, names, ids, jaws);
    }

    /// <summary>
    /// How far from <paramref name="centre"/>, along the line <paramref name="across"/> the
    /// pocket's mouth, a ball's centre can be while at least R from both jaw faces' lines (m).
    /// </summary>
    internal static double ChannelHalfWidth(IReadOnlyList<CushionSegment> jaws, Vec3 centre, Vec3 across, double radius)
    {
        double widest = 0;
        foreach (var face in jaws)
        {
            // Where along the chord the centre is exactly R from this jaw face's line.
            widest = Math.Max(widest, Math.Abs((radius - Vec3.Dot(face.Normal, centre - face.Start)) / Vec3.Dot(face.Normal, across)));
        }
        return widest;
    }
}
