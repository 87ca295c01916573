using Billiards.Core.Mathematics;
using System.Numerics;
using Billiards.Core.Cue;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Table;

namespace Billiards.Core.Setup;

public static partial class Initializer
{
    /// <summary>
    /// Names of the collision features, indexed by <see cref="CollisionGeometry.Feature"/>: the six
    /// cushions (0..5), the jaws of each pocket (6 + pocket) and the back wall of each pocket
    /// (12 + pocket). Head is -x, foot +x; left is SI +y (seed -z) seen from the head.
    /// </summary>
    public static IReadOnlyList<string> CushionNames { get; } =
    [
        "head", "foot", "left-head", "left-foot", "right-head", "right-foot",
        "head-left-jaw", "head-right-jaw", "side-left-jaw", "side-right-jaw", "foot-left-jaw", "foot-right-jaw",
        "head-left-back", "head-right-back", "side-left-back", "side-right-back", "foot-left-back", "foot-right-back",
    ];

    /// <summary>Lowest point of the collision walls (cm): below the -20 cm at which a dropping ball leaves play, so the pocket's back walls hold it until then.</summary>
    public const float RailBottom = -25f;

    /// <summary>Highest point of the collision walls (cm): above a ball on the bed (centre 2.86).</summary>
    public const float RailTop = 8f;

    private const int Head = 0, Foot = 1, LeftHead = 2, LeftFoot = 3, RightHead = 4, RightFoot = 5;
    /// <summary>The feature of the first pocket's jaw; pocket p's is FirstJaw + p.</summary>
    internal const int FirstJaw = 6;

    /// <summary>The feature of the first pocket's back wall; pocket p's is FirstBack + p.</summary>
    internal const int FirstBack = 12;
    private const int HeadRight = 1, SideRight = 3, FootRight = 5;
    private const int BackChords = 3;

    // A half turn about the centre swaps every feature with its opposite (pocket p with 5 - p).
    private static readonly int[] _halfTurn = [Foot, Head, RightFoot, RightHead, LeftFoot, LeftHead, 11, 10, 9, 8, 7, 6, 17, 16, 15, 14, 13, 12];

    /// <summary>
    /// The seed's <c>initRails</c>: the collision triangles of a table, in the seed's units (cm),
    /// placed one ball radius (2.86) in front of the cushion faces so that a ball collides when
    /// its centre crosses one.
    /// </summary>
    /// <remarks>
    /// <para>Construction (seed 3.1, see <see cref="ThesisTable"/>): the outline of the playing
    /// area is traced counter-clockwise seen with x right and z up: cushion noses, at every pocket
    /// a jaw at 35 deg (corner) or 70 deg (side) to the cushion line from the nose back through
    /// the rail's 6.5 cm to the throat, and behind the throat the pocket's back wall, a half
    /// circle over the throat made of three chords. Every line is moved 2.86 cm towards the
    /// balls; neighbours meet where their moved lines cross. Each piece becomes a vertical
    /// rectangle from <see cref="RailBottom"/> to <see cref="RailTop"/> of two triangles whose
    /// normals point to the balls. Back walls do not bounce.</para>
    /// <para>The thesis table gets 6 noses + 12 jaws + 6 * 3 back chords = 36 rectangles =
    /// 72 triangles, the seed's count (seed 4.3.4); the seed does not show its triangles, so the
    /// match in number says nothing about a match in shape. The pocketless table is a rectangle
    /// of 6 cushions (the long ones split at the middle for their names): 12 triangles.</para>
    /// </remarks>
    /// <exception cref="InvalidOperationException">When a pocket is too small for the construction (a moved line would turn round).</exception>
    public static CollisionGeometry[] InitRails(TableSpec table)
    {
        var t = ThesisTable.From(table);
        var outline = new List<(double X, double Z, int Feature)>();
        HalfOutline(t, outline);
        int half = outline.Count;
        for (int i = 0; i < half; i++)
        {
            var (x, z, feature) = outline[i];
            outline.Add((-x, -z, _halfTurn[feature]));
        }
        RemoveStraightJoints(outline);
        var moved = MoveTowardsBalls(outline, PhysicsEngine.BallRadius);

        var rails = new CollisionGeometry[2 * moved.Count];
        for (int i = 0; i < moved.Count; i++)
        {
            var a = moved[i];
            var b = moved[(i + 1) % moved.Count];
            int feature = outline[i].Feature;
            bool bouncing = feature < FirstBack;
            var aLow = new Vector3((float)a.X, RailBottom, (float)a.Z);
            var bLow = new Vector3((float)b.X, RailBottom, (float)b.Z);
            var aHigh = aLow with { Y = RailTop };
            var bHigh = bLow with { Y = RailTop };
            // (b - a) x up is the left normal of a -> b: towards the balls on a counter-clockwise outline.
            rails[2 * i] = new CollisionGeometry(2 * i, aLow, bLow, aHigh, bouncing, feature);
            rails[2 * i + 1] = new CollisionGeometry(2 * i + 1, bLow, bHigh, aHigh, bouncing, feature);
        }
        return rails;
    }

    /// <summary>
    /// The seed's <c>resetGame</c>: every ball back to where the game started, at rest, out of
    /// no pocket, with a fresh random orientation; the cue back to its rest state.
    /// </summary>
    /// <remarks>
    /// The seed re-racks with new jitter; we restore the positions the game started with, so that a
    /// headless run stays a function of its scene. The seed also puts the camera back; Core has no
    /// camera, so we return the cue ball's start, the centre of interest the App's camera returns to.
    /// </remarks>
    /// <param name="balls">The balls, changed in place.</param>
    /// <param name="startPositions">Start position of each ball (cm), index-aligned with <paramref name="balls"/>.</param>
    /// <param name="queue">The cue, reset.</param>
    /// <param name="random">Source of the new orientations.</param>
    /// <returns>The cue ball's start position (cm), or the origin if there is no cue ball.</returns>
    public static Vector3 ResetGame(IReadOnlyList<Ball> balls, ReadOnlySpan<Vector3> startPositions, ThesisCue queue, Random random)
    {
        var cueStart = Vector3.Zero;
        for (int i = 0; i < balls.Count; i++)
        {
            var ball = balls[i];
            ball.Position = startPositions[i];
            ball.Velocity = Vector3.Zero;
            ball.Pocket = -1;
            ball.IsPocketed = false;
            ball.RandomizeOrientation(random);
            if (ball.IsCueBall)
            {
                cueStart = startPositions[i];
            }
        }
        queue.Reset();
        return cueStart;
    }

    // The outline from the middle of the foot cushion, counter-clockwise, to the middle of the head
    // cushion (x = +-L, the right side z = +W); the other half is this one turned half round.
    // Each entry is a vertex and the feature of the piece that starts there.
    private static void HalfOutline(ThesisTable t, List<(double X, double Z, int Feature)> outline)
    {
        double l = t.HalfLength, w = t.HalfWidth, d = ThesisTable.RailDepth;
        if (!t.HasPockets)
        {
            outline.Add((l, 0, Foot));
            outline.Add((l, w, RightFoot));
            outline.Add((0, w, RightHead));
            outline.Add((-l, w, Head));
            return;
        }
        double gc = t.CornerGap, gs = t.SideGap;
        double cornerJaw = d / DeterministicMath.Tan(ThesisTable.CornerJawDeg * Math.PI / 180); // how far the jaw leans along the rail
        double sideJaw = d / DeterministicMath.Tan(ThesisTable.SideJawDeg * Math.PI / 180);
        double cornerNose = w + d - gc - cornerJaw; // where a short cushion's nose ends
        double longNose = l + d - gc - cornerJaw;   // where a long cushion's nose ends at a corner
        double sideNose = gs / 2 + sideJaw;         // where a long cushion's nose ends at a side pocket

        outline.Add((l, 0, Foot));
        outline.Add((l, cornerNose, FirstJaw + FootRight));
        Back(outline, l + d - gc / 2, w + d - gc / 2, gc / Math.Sqrt(2), -45, FootRight);
        outline.Add((longNose, w, RightFoot));
        outline.Add((sideNose, w, FirstJaw + SideRight));
        Back(outline, 0, w + d, gs / 2, 0, SideRight);
        outline.Add((-sideNose, w, RightHead));
        outline.Add((-longNose, w, FirstJaw + HeadRight));
        Back(outline, -(l + d - gc / 2), w + d - gc / 2, gc / Math.Sqrt(2), 45, HeadRight);
        outline.Add((-l, cornerNose, Head));
    }

    // A pocket's back: from the throat's first end (at startDeg about the centre) half round to its
    // other end, in three chords; the piece after it is the pocket's second jaw.
    private static void Back(List<(double X, double Z, int Feature)> outline, double cx, double cz, double radius, double startDeg, int pocket)
    {
        for (int k = 0; k <= BackChords; k++)
        {
            double a = (startDeg + k * 180.0 / BackChords) * Math.PI / 180;
            outline.Add((cx + radius * DeterministicMath.Cos(a), cz + radius * DeterministicMath.Sin(a), k < BackChords ? FirstBack + pocket : FirstJaw + pocket));
        }
    }

    // Joins two neighbouring pieces of one feature that run straight on (the halves of the head and
    // foot cushions meet in the middle).
    private static void RemoveStraightJoints(List<(double X, double Z, int Feature)> outline)
    {
        for (int i = outline.Count - 1; i >= 0 && outline.Count > 3; i--)
        {
            var prev = outline[(i - 1 + outline.Count) % outline.Count];
            var cur = outline[i];
            var next = outline[(i + 1) % outline.Count];
            double turn = (cur.X - prev.X) * (next.Z - cur.Z) - (cur.Z - prev.Z) * (next.X - cur.X);
            if (prev.Feature == cur.Feature && Math.Abs(turn) < 1e-9)
            {
                outline.RemoveAt(i);
            }
        }
    }

    // Moves every piece of the outline by `offset` to its left (towards the balls) and joins
    // neighbours where the moved lines cross.
    private static List<(double X, double Z)> MoveTowardsBalls(List<(double X, double Z, int Feature)> outline, double offset)
    {
        int n = outline.Count;
        var moved = new List<(double X, double Z)>(n);
        for (int i = 0; i < n; i++)
        {
            var (px, pz, _) = outline[(i - 1 + n) % n];
            var (cx, cz, _) = outline[i];
            var (nx, nz, _) = outline[(i + 1) % n];
            var (dpx, dpz) = Unit(cx - px, cz - pz);
            var (dnx, dnz) = Unit(nx - cx, nz - cz);
            // Left normals (-dz, dx); a point on each moved line.
            double ax = cx - dpz * offset, az = cz + dpx * offset;
            double bx = cx - dnz * offset, bz = cz + dnx * offset;
            double cross = dpx * dnz - dpz * dnx;
            if (Math.Abs(cross) < 1e-9)
            {
                moved.Add((bx, bz));
                continue;
            }
            double s = ((bx - ax) * dnz - (bz - az) * dnx) / cross;
            moved.Add((ax + s * dpx, az + s * dpz));
        }
        for (int i = 0; i < n; i++)
        {
            var (ox, oz, _) = outline[i];
            var (qx, qz, _) = outline[(i + 1) % n];
            var a = moved[i];
            var b = moved[(i + 1) % n];
            if ((b.X - a.X) * (qx - ox) + (b.Z - a.Z) * (qz - oz) <= 0)
            {
                throw new InvalidOperationException($"the pocket throats are too small for the thesis rails (piece {i}, {CushionNames[outline[i].Feature]})");
            }
        }
        return moved;
    }

    private static (double X, double Z) Unit(double x, double z)
    {
        double length = Math.Sqrt(x * x + z * z);
        return (x / length, z / length);
    }
}
