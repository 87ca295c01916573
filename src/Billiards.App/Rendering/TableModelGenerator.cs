using System.Numerics;
using Billiards.Core.Table;

namespace Billiards.App.Rendering;

/// <summary>
/// Builds the table's mesh from a <see cref="TableSpec"/>: cloth bed with pocket holes,
/// cushions with a real profile (nose at the spec's cushion height, undercut face, jaws cut at the
/// spec's jaw angles), pocket cups, wooden rails with diamond sights, apron, legs and a floor; a
/// carom match table (<see cref="CaromTable"/>) its blue cloth and its sights at 1/8 of the length; a
/// snooker table (<see cref="SnookerTable"/>) has its brighter cloth, the baulk line, the D and the
/// six spots marked on the bed, and no sights (its rails carry none).
/// Metres, z up, origin at the centre of the bed (Core's frame).
/// </summary>
/// <remarks>
/// Every pocket is a circle through the two points where its jaws reach the back of the
/// cushions; by Thales the corner circle then also passes through the rail's inner corner, so
/// the circle's near half notches the bed and its far half notches the rail. The game loads the
/// exported file through Assimp, not this class, so a user can swap in another model.
/// </remarks>
public static class TableModelGenerator
{
    /// <summary>Depth of the cushion from its nose to the rail (m).</summary>
    public const float CushionDepth = 0.05f;

    /// <summary>Width of the wooden rail top (m).</summary>
    public const float RailWidth = 0.13f;

    /// <summary>Height of the bed above the floor (m).</summary>
    public const float BedHeight = 0.77f;

    /// <summary>Depth of the pocket cups below the bed (m).</summary>
    public const float PocketDepth = 0.11f;

    private const float ApronBottom = -0.21f;
    private const int ArcSegments = 10;

    /// <summary>The materials, named as the MTL file names them (colours sRGB).</summary>
    public static class Materials
    {
        public static readonly MeshMaterial Cloth = new("cloth", new(0.07f, 0.42f, 0.20f), new(0.03f, 0.03f, 0.03f), 6);
        // Snooker's cloth is the brighter, yellower green of a championship baize.
        public static readonly MeshMaterial SnookerCloth = new("cloth", new(0.10f, 0.50f, 0.16f), new(0.03f, 0.03f, 0.03f), 6);
        // Carom's match cloth is the blue of the UMB's tournament tables.
        public static readonly MeshMaterial CaromCloth = new("cloth", new(0.06f, 0.24f, 0.62f), new(0.03f, 0.03f, 0.03f), 6);
        public static readonly MeshMaterial CaromCushion = new("cushion", new(0.05f, 0.21f, 0.55f), new(0.04f, 0.04f, 0.04f), 8);
        public static readonly MeshMaterial SnookerCushion = new("cushion", new(0.09f, 0.45f, 0.15f), new(0.04f, 0.04f, 0.04f), 8);
        // The chalked lines and spots of a snooker bed, a little off-white so the cue ball stands out on them.
        public static readonly MeshMaterial Marking = new("marking", new(0.80f, 0.82f, 0.76f), new(0.03f, 0.03f, 0.03f), 6);
        public static readonly MeshMaterial Cushion = new("cushion", new(0.06f, 0.38f, 0.18f), new(0.04f, 0.04f, 0.04f), 8);
        public static readonly MeshMaterial Rail = new("rail", new(0.36f, 0.16f, 0.07f), new(0.12f, 0.1f, 0.09f), 120);
        public static readonly MeshMaterial Frame = new("frame", new(0.26f, 0.11f, 0.045f), new(0.1f, 0.09f, 0.08f), 80);
        public static readonly MeshMaterial Sight = new("sight", new(0.95f, 0.93f, 0.86f), new(0.6f, 0.6f, 0.6f), 80);
        public static readonly MeshMaterial Pocket = new("pocket", new(0.16f, 0.09f, 0.05f), new(0.12f, 0.1f, 0.08f), 30);
        public static readonly MeshMaterial PocketFloor = new("pocket_floor", new(0.035f, 0.022f, 0.014f), new(0.02f, 0.02f, 0.02f), 10);
        public static readonly MeshMaterial Trim = new("trim", new(0.06f, 0.05f, 0.045f), new(0.3f, 0.3f, 0.3f), 40);
        public static readonly MeshMaterial Floor = new("floor", new(0.24f, 0.17f, 0.12f), new(0.06f, 0.06f, 0.06f), 12);
    }

    /// <summary>One pocket's hole: a circle whose far half cuts the rail and near half the bed.</summary>
    private sealed record Pocket(Vector2 Centre, float Radius, Vector2 Outward, Vector2 JawA, Vector2 JawB, Vector2 OuterSplit)
    {
        public Vector2 FarApex => Centre + (Radius * Outward);
        public Vector2 NearApex => Centre - (Radius * Outward);
    }

    /// <summary>The table as one mesh per material.</summary>
    public static List<MeshBuilder> Generate(TableSpec spec)
    {
        float hx = (float)spec.HalfLength, hy = (float)spec.HalfWidth;
        float nose = (float)spec.CushionHeight;
        float railTop = nose + 0.0065f;
        float inner = CushionDepth, outer = CushionDepth + RailWidth;

        bool snooker = spec.Preset == SnookerTable.Preset, carom = spec.Preset == CaromTable.Preset;
        var cloth = new MeshBuilder(snooker ? Materials.SnookerCloth : carom ? Materials.CaromCloth : Materials.Cloth);
        var cushion = new MeshBuilder(snooker ? Materials.SnookerCushion : carom ? Materials.CaromCushion : Materials.Cushion);
        var rail = new MeshBuilder(Materials.Rail);
        var frame = new MeshBuilder(Materials.Frame);
        var sight = new MeshBuilder(Materials.Sight);
        var pocket = new MeshBuilder(Materials.Pocket);
        var trim = new MeshBuilder(Materials.Trim);
        var pocketFloor = new MeshBuilder(Materials.PocketFloor);
        var floor = new MeshBuilder(Materials.Floor);

        // Pockets in the order a counter-clockwise walk round the bed meets them.
        var pockets = new List<Pocket>();
        foreach (var (end, side) in WalkOrder)
        {
            if (spec.Pockets.At(end, side) is { } p)
            {
                pockets.Add(p.IsCorner ? CornerPocket(p, hx, hy, outer) : SidePocket(p, hy, outer));
            }
        }

        BuildBed(cloth, pockets, hx + inner, hy + inner);
        BuildCushions(cushion, spec, hx, hy, nose, railTop);
        BuildRailTop(rail, pockets, hx, hy, railTop);
        BuildOuterRail(rail, frame, hx + outer, hy + outer, railTop);
        foreach (var p in pockets)
        {
            BuildPocket(pocket, pocketFloor, trim, p, railTop);
        }
        BuildLegsAndFloor(frame, floor, hx + outer, hy + outer);
        if (snooker)
        {
            var marking = new MeshBuilder(Materials.Marking);
            BuildSnookerMarkings(marking, spec);
            return [cloth, cushion, rail, frame, marking, pocket, pocketFloor, trim, floor];
        }
        BuildSights(sight, spec, hx, hy, railTop);
        return [cloth, cushion, rail, frame, sight, pocket, pocketFloor, trim, floor];
    }

    // The places of the outline in the order a counter-clockwise walk round the bed from the head-right corner meets them.
    private static readonly (int End, int Side)[] WalkOrder = [(0, -1), (1, -1), (1, 1), (0, 1), (-1, 1), (-1, -1)];

    private static Pocket CornerPocket(PocketSpec spec, float hx, float hy, float outer)
    {
        int sx = spec.End, sy = spec.Side;
        float mouth = (float)spec.Mouth / MathF.Sqrt(2);
        float turn = (180 - (float)spec.JawAngleDeg) * MathF.PI / 180;
        float run = CushionDepth / MathF.Sin(turn);
        var tipA = new Vector2(sx * (hx - mouth), sy * hy);
        var jawA = tipA + (run * new Vector2(sx * MathF.Cos(turn), sy * MathF.Sin(turn)));
        var tipB = new Vector2(sx * hx, sy * (hy - mouth));
        var jawB = tipB + (run * new Vector2(sx * MathF.Sin(turn), sy * MathF.Cos(turn)));
        return new Pocket((jawA + jawB) / 2, Vector2.Distance(jawA, jawB) / 2, Vector2.Normalize(new Vector2(sx, sy)),
            jawA, jawB, new Vector2(sx * (hx + outer), sy * (hy + outer)));
    }

    private static Pocket SidePocket(PocketSpec spec, float hy, float outer)
    {
        int sy = spec.Side;
        float mouth = (float)spec.Mouth / 2;
        float turn = (180 - (float)spec.JawAngleDeg) * MathF.PI / 180;
        float run = CushionDepth / MathF.Sin(turn);
        var jawA = new Vector2(-mouth, sy * hy) + (run * new Vector2(MathF.Cos(turn), sy * MathF.Sin(turn)));
        var jawB = new Vector2(mouth, sy * hy) + (run * new Vector2(-MathF.Cos(turn), sy * MathF.Sin(turn)));
        return new Pocket((jawA + jawB) / 2, Vector2.Distance(jawA, jawB) / 2, new Vector2(0, sy), jawA, jawB, new Vector2(0, sy * (hy + outer)));
    }

    /// <summary>Points of the arc from <paramref name="from"/> to <paramref name="to"/> the short way round (both on the circle), excluding <paramref name="from"/>.</summary>
    private static IEnumerable<Vector2> Arc(Vector2 centre, float radius, Vector2 from, Vector2 to, int segments = ArcSegments)
    {
        float a0 = MathF.Atan2(from.Y - centre.Y, from.X - centre.X);
        float a1 = MathF.Atan2(to.Y - centre.Y, to.X - centre.X);
        float delta = a1 - a0;
        while (delta > MathF.PI)
        {
            delta -= 2 * MathF.PI;
        }
        while (delta < -MathF.PI)
        {
            delta += 2 * MathF.PI;
        }
        for (int k = 1; k <= segments; k++)
        {
            float a = a0 + (delta * k / segments);
            yield return k == segments ? to : centre + (radius * new Vector2(MathF.Cos(a), MathF.Sin(a)));
        }
    }

    private static Vector2 Nearer(Vector2 reference, Vector2 a, Vector2 b) =>
        Vector2.DistanceSquared(reference, a) <= Vector2.DistanceSquared(reference, b) ? a : b;

    private static void BuildBed(MeshBuilder cloth, List<Pocket> pockets, float bx, float by)
    {
        if (pockets.Count == 0)
        {
            cloth.Polygon([new(-bx, -by), new(bx, -by), new(bx, by), new(-bx, by)], 0);
            return;
        }
        var outline = new List<Vector2>();
        var previous = new Vector2(-bx, -by);
        foreach (var p in pockets)
        {
            var enter = Nearer(previous, p.JawA, p.JawB);
            var leave = enter == p.JawA ? p.JawB : p.JawA;
            outline.Add(enter);
            outline.AddRange(Arc(p.Centre, p.Radius, enter, p.NearApex));
            outline.AddRange(Arc(p.Centre, p.Radius, p.NearApex, leave));
            previous = leave;
        }
        cloth.Polygon(outline, 0);
    }

    /// <summary>The cushion's cross-section (distance behind the nose, height), from the bed contact to the rail.</summary>
    private static Vector2[] CushionProfile(float nose, float railTop)
    {
        // The face under the nose slopes back at 60 deg to the bed (the seed's cushions), the top
        // rises gently from a rounded nose to the rail.
        float foot = nose / MathF.Tan(60 * MathF.PI / 180);
        return
        [
            new(foot, 0),
            new(0.0015f, nose - 0.0025f),
            new(0, nose),
            new(0.0012f, nose + 0.0025f),
            new(0.005f, nose + 0.004f),
            new(CushionDepth, railTop),
        ];
    }

    private static void BuildCushions(MeshBuilder mesh, TableSpec spec, float hx, float hy, float nose, float railTop)
    {
        var profile = CushionProfile(nose, railTop);
        if (!spec.HasPockets)
        {
            // A closed rectangle: every cushion runs corner to corner, mitred at 45 deg.
            Cushion(mesh, profile, new(0, -hy), Vector2.UnitX, -Vector2.UnitY, -hx, hx, 45, 45);
            Cushion(mesh, profile, new(hx, 0), Vector2.UnitY, Vector2.UnitX, -hy, hy, 45, 45);
            Cushion(mesh, profile, new(0, hy), -Vector2.UnitX, Vector2.UnitY, -hx, hx, 45, 45);
            Cushion(mesh, profile, new(-hx, 0), -Vector2.UnitY, -Vector2.UnitX, -hy, hy, 45, 45);
            return;
        }
        // Each cushion end at a place of the outline: cut back by the pocket there and turned by
        // its jaw, or (no pocket there) running to the corner mitred at 45 deg, or butting its
        // neighbour square in the middle of a long rail.
        (float Cut, float Turn) End(int end, int side) => spec.Pockets.At(end, side) is { } p
            ? ((float)p.RailCut, 180 - (float)p.JawAngleDeg)
            : (0, end == 0 ? 90 : 45);
        // Long rails: two cushions each, from the corner to the middle and on to the other corner.
        foreach (int sy in new[] { -1, 1 })
        {
            var along = sy < 0 ? Vector2.UnitX : -Vector2.UnitX;
            var outward = new Vector2(0, sy);
            var origin = new Vector2(0, sy * hy);
            // s runs along `along`: on the right rail (sy < 0) from head to foot, on the left from foot to head.
            var (first, middle, last) = (End(sy, sy), End(0, sy), End(-sy, sy));
            Cushion(mesh, profile, origin, along, outward, -hx + first.Cut, -middle.Cut, first.Turn, middle.Turn);
            Cushion(mesh, profile, origin, along, outward, middle.Cut, hx - last.Cut, middle.Turn, last.Turn);
        }
        // Short rails: one cushion each, corner to corner.
        foreach (int sx in new[] { -1, 1 })
        {
            var along = sx > 0 ? Vector2.UnitY : -Vector2.UnitY;
            var (first, last) = (End(sx, -sx), End(sx, sx));
            Cushion(mesh, profile, new Vector2(sx * hx, 0), along, new Vector2(sx, 0), -hy + first.Cut, hy - last.Cut, first.Turn, last.Turn);
        }
    }

    /// <summary>
    /// One cushion: the profile swept along its nose line from s0 to s1, each end cut by the
    /// vertical plane of its jaw, turned by the given angle (deg) from the nose line.
    /// </summary>
    private static void Cushion(MeshBuilder mesh, Vector2[] profile, Vector2 origin, Vector2 along, Vector2 outward,
        float s0, float s1, float turnStartDeg, float turnEndDeg)
    {
        float cotStart = 1 / MathF.Tan(turnStartDeg * MathF.PI / 180), cotEnd = 1 / MathF.Tan(turnEndDeg * MathF.PI / 180);
        Vector3 World(float s, float u, float z) => new(origin + (s * along) + (u * outward), z);
        Vector3 Normal(Vector2 n) => Vector3.Normalize(new Vector3(n.X * outward, n.Y));

        // Normals of the profile segments, (-dz, du) points to the table and up; vertex normals average them.
        var segmentNormals = new Vector2[profile.Length - 1];
        for (int k = 0; k + 1 < profile.Length; k++)
        {
            var d = profile[k + 1] - profile[k];
            segmentNormals[k] = Vector2.Normalize(new Vector2(-d.Y, d.X));
        }
        Vector2 VertexNormal(int k, int segment) =>
            k == segment ? (k == 0 ? segmentNormals[0] : Vector2.Normalize(segmentNormals[k - 1] + segmentNormals[k]))
                         : (k == profile.Length - 1 ? segmentNormals[^1] : Vector2.Normalize(segmentNormals[k - 1] + segmentNormals[k]));
        for (int k = 0; k + 1 < profile.Length; k++)
        {
            var p = profile[k];
            var q = profile[k + 1];
            var np = Normal(VertexNormal(k, k));
            var nq = Normal(VertexNormal(k + 1, k));
            // The nose is a crease only below it: the undercut face is flat-shaded against the top.
            if (k == 0)
            {
                np = nq = Normal(segmentNormals[0]);
            }
            mesh.Quad(World(s0 - (p.X * cotStart), p.X, p.Y), World(s1 + (p.X * cotEnd), p.X, p.Y),
                      World(s1 + (q.X * cotEnd), q.X, q.Y), World(s0 - (q.X * cotStart), q.X, q.Y), np, np, nq, nq);
        }
        // Jaw faces: the profile closed at the back of the cushion, in each jaw's vertical plane.
        var start = new List<Vector3>();
        var end = new List<Vector3>();
        foreach (var p in profile)
        {
            start.Add(World(s0 - (p.X * cotStart), p.X, p.Y));
            end.Add(World(s1 + (p.X * cotEnd), p.X, p.Y));
        }
        start.Add(World(s0 - (CushionDepth * cotStart), CushionDepth, 0));
        end.Add(World(s1 + (CushionDepth * cotEnd), CushionDepth, 0));
        float a = turnStartDeg * MathF.PI / 180, b = turnEndDeg * MathF.PI / 180;
        mesh.ConvexPolygon(start, Vector3.Normalize(new Vector3((-MathF.Sin(a) * along) - (MathF.Cos(a) * outward), 0)));
        mesh.ConvexPolygon(end, Vector3.Normalize(new Vector3((MathF.Sin(b) * along) - (MathF.Cos(b) * outward), 0)));
    }

    private static void BuildRailTop(MeshBuilder rail, List<Pocket> pockets, float hx, float hy, float railTop)
    {
        float ix = hx + CushionDepth, iy = hy + CushionDepth, ox = ix + RailWidth, oy = iy + RailWidth;
        if (pockets.Count == 0)
        {
            // Four trapezoids split at the diagonals.
            rail.Polygon([new(-ix, -iy), new(ix, -iy), new(ox, -oy), new(-ox, -oy)], railTop);
            rail.Polygon([new(ix, -iy), new(ix, iy), new(ox, oy), new(ox, -oy)], railTop);
            rail.Polygon([new(ix, iy), new(-ix, iy), new(-ox, oy), new(ox, oy)], railTop);
            rail.Polygon([new(-ix, iy), new(-ix, -iy), new(-ox, -oy), new(-ox, oy)], railTop);
            return;
        }
        // Six pieces, each from one pocket's far apex to the next one's, split at the pockets.
        for (int i = 0; i < pockets.Count; i++)
        {
            var p = pockets[(i + pockets.Count - 1) % pockets.Count];
            var q = pockets[i];
            // The jaw points of p and q that lie on the shared rail line.
            var (jp, jq) = SharedSide(p, q);
            var outline = new List<Vector2> { p.OuterSplit, p.FarApex };
            outline.AddRange(Arc(p.Centre, p.Radius, p.FarApex, jp));
            outline.AddRange(Arc(q.Centre, q.Radius, jq, q.FarApex).Prepend(jq));
            outline.Add(q.OuterSplit);
            rail.Polygon(outline, railTop);
        }
    }

    private static (Vector2 P, Vector2 Q) SharedSide(Pocket p, Pocket q)
    {
        // The closest pair (one jaw point of each) on a common line x = const or y = const.
        (Vector2, Vector2)? best = null;
        float bestDistance = float.MaxValue;
        foreach (var a in new[] { p.JawA, p.JawB })
        {
            foreach (var b in new[] { q.JawA, q.JawB })
            {
                float distance = Vector2.Distance(a, b);
                if ((MathF.Abs(a.X - b.X) < 1e-4f || MathF.Abs(a.Y - b.Y) < 1e-4f) && distance < bestDistance)
                {
                    best = (a, b);
                    bestDistance = distance;
                }
            }
        }
        return best ?? throw new InvalidOperationException("pockets do not share a rail");
    }

    private static void BuildOuterRail(MeshBuilder rail, MeshBuilder frame, float ox, float oy, float railTop)
    {
        // Profile of the rail's outer edge (offset beyond the rail top's outer line, height): a
        // rounded edge, then the apron, stepped in a little.
        Vector2[] railEdge =
        [
            new(0, railTop), new(0.004f, railTop - 0.0015f), new(0.008f, railTop - 0.006f),
            new(0.010f, railTop - 0.014f), new(0.010f, -0.035f), new(0.004f, -0.035f),
        ];
        Vector2[] apron = [new(0.004f, -0.035f), new(0.004f, ApronBottom), new(-0.03f, ApronBottom)];
        Sweep(rail, railEdge, ox, oy);
        Sweep(frame, apron, ox, oy);
    }

    /// <summary>Sweeps a profile (outward offset, height) round the rectangle with half sizes (ox, oy), flat along each side.</summary>
    private static void Sweep(MeshBuilder mesh, Vector2[] profile, float ox, float oy)
    {
        (Vector2 Normal, Vector2 From, Vector2 To)[] sides =
        [
            (-Vector2.UnitY, new(-1, -1), new(1, -1)),
            (Vector2.UnitX, new(1, -1), new(1, 1)),
            (Vector2.UnitY, new(1, 1), new(-1, 1)),
            (-Vector2.UnitX, new(-1, 1), new(-1, -1)),
        ];
        foreach (var (normal, from, to) in sides)
        {
            for (int k = 0; k + 1 < profile.Length; k++)
            {
                var p = profile[k];
                var q = profile[k + 1];
                var d = q - p;
                // Outward-and-up normal of this profile segment.
                var n2 = Vector2.Normalize(new Vector2(-d.Y, d.X));
                if (n2.X < 0 || (MathF.Abs(n2.X) < 1e-6f && n2.Y > 0 && d.X > 0))
                {
                    n2 = -n2;
                }
                if (MathF.Abs(d.X) > 1e-6f && MathF.Abs(d.Y) < 1e-6f)
                {
                    n2 = d.X < 0 ? -Vector2.UnitY : Vector2.UnitY;
                }
                var n = Vector3.Normalize(new Vector3(n2.X * normal, n2.Y));
                Vector3 Corner(Vector2 c, Vector2 offset) => new(c.X * (ox + offset.X), c.Y * (oy + offset.X), offset.Y);
                mesh.Quad(Corner(from, p), Corner(to, p), Corner(to, q), Corner(from, q), n);
            }
        }
    }

    private static void BuildSights(MeshBuilder mesh, TableSpec spec, float hx, float hy, float railTop)
    {
        float offset = (float)spec.SightOffset;
        float z = railTop + 0.0006f;
        void Diamond(Vector2 centre, Vector2 along)
        {
            var across = new Vector2(-along.Y, along.X);
            const float Long = 0.011f, Short = 0.0065f;
            mesh.Polygon([centre - (Long * along), centre - (Short * across), centre + (Long * along), centre + (Short * across)], z);
        }
        for (int k = -3; k <= 3; k++)
        {
            if (k == 0)
            {
                continue;
            }
            float x = k * hx / 4;
            Diamond(new Vector2(x, hy + offset), Vector2.UnitX);
            Diamond(new Vector2(x, -hy - offset), Vector2.UnitX);
        }
        for (int k = -1; k <= 1; k++)
        {
            float y = k * hy / 2;
            Diamond(new Vector2(hx + offset, y), Vector2.UnitY);
            Diamond(new Vector2(-hx - offset, y), Vector2.UnitY);
        }
    }

    /// <summary>Width of the baulk line and the D's arc on a snooker bed (m): a chalk line, drawn wide enough to read from the overhead view.</summary>
    public const float MarkingWidth = 0.006f;

    /// <summary>Radius of a marked colour spot (m).</summary>
    public const float SpotRadius = 0.005f;

    // The baulk line from cushion to cushion, the D's half circle on its baulk side and the six
    // spots, just above the cloth (z 0.3 mm: above it in depth, far below a ball's contact).
    private static void BuildSnookerMarkings(MeshBuilder mesh, TableSpec spec)
    {
        const float Z = 0.0003f;
        float hy = (float)spec.HalfWidth;
        float baulk = (float)SnookerTable.BaulkLineX(spec);
        float w = MarkingWidth / 2;
        mesh.Polygon([new(baulk - w, -hy), new(baulk + w, -hy), new(baulk + w, hy), new(baulk - w, hy)], Z);
        float d = (float)SnookerTable.DRadius;
        const int Segments = 48;
        var c = new Vector2(baulk, 0);
        for (int k = 0; k < Segments; k++)
        {
            // From the yellow spot's end (y < 0) round the baulk side (x < the line) to the green's.
            float a0 = MathF.PI * ((k / (float)Segments) - 0.5f), a1 = MathF.PI * (((k + 1) / (float)Segments) - 0.5f);
            var u0 = new Vector2(-MathF.Cos(a0), MathF.Sin(a0));
            var u1 = new Vector2(-MathF.Cos(a1), MathF.Sin(a1));
            mesh.Polygon([c + ((d - w) * u0), c + ((d + w) * u0), c + ((d + w) * u1), c + ((d - w) * u1)], Z);
        }
        foreach (string colour in Billiards.Core.Balls.BallSet.Colours)
        {
            var spot = SnookerTable.Spot(spec, colour, 0);
            var centre = new Vector2((float)spot.X, (float)spot.Y);
            var disc = new List<Vector2>();
            for (int k = 0; k < 12; k++)
            {
                float a = 2 * MathF.PI * k / 12;
                disc.Add(centre + (SpotRadius * new Vector2(MathF.Cos(a), MathF.Sin(a))));
            }
            mesh.Polygon(disc, Z + 0.0001f);
        }
    }

    private static void BuildPocket(MeshBuilder cup, MeshBuilder bottomOf, MeshBuilder trim, Pocket p, float railTop)
    {
        float bottom = -PocketDepth;
        // The cup's rim follows the hole exactly, on the very points of the bed's and the rail's
        // outlines: its near half from jaw to jaw at the bed, its far half at the rail's top. A wall
        // cut in angular steps instead stood up over the cloth at one jaw and left a gap under the
        // rail at the other, and its edge did not meet the hole's.
        var near = new List<Vector2> { p.JawA };
        near.AddRange(Arc(p.Centre, p.Radius, p.JawA, p.NearApex));
        near.AddRange(Arc(p.Centre, p.Radius, p.NearApex, p.JawB));
        var far = new List<Vector2> { p.JawB };
        far.AddRange(Arc(p.Centre, p.Radius, p.JawB, p.FarApex));
        far.AddRange(Arc(p.Centre, p.Radius, p.FarApex, p.JawA));
        // A leather trim round the rail's cut: a thin flat ring on the rail, and its outer edge; the
        // far wall rises to the ring's top, so that nothing lies in the wall's own surface (which
        // fought with it for depth and speckled the rim).
        const float Width = 0.01f, Rise = 0.001f;
        float z = railTop + Rise;
        Wall(cup, p, near, 0, bottom);
        Wall(cup, p, far, z, bottom);
        var rim = near.Concat(far.Skip(1)).ToList();
        var centre3 = new Vector3(p.Centre, bottom);
        for (int k = 0; k + 1 < rim.Count; k++)
        {
            // Darker than the walls, which the lamps light: the hole reads as deep, not as a disc.
            bottomOf.ConvexPolygon([centre3, new Vector3(rim[k + 1], bottom), new Vector3(rim[k], bottom)], Vector3.UnitZ);
        }
        for (int k = 0; k + 1 < far.Count; k++)
        {
            var d0 = Vector2.Normalize(far[k] - p.Centre);
            var d1 = Vector2.Normalize(far[k + 1] - p.Centre);
            var q0 = far[k] + (Width * d0);
            var q1 = far[k + 1] + (Width * d1);
            trim.Quad(new Vector3(far[k], z), new Vector3(far[k + 1], z), new Vector3(q1, z), new Vector3(q0, z), Vector3.UnitZ);
            trim.Quad(new Vector3(q0, z), new Vector3(q1, z), new Vector3(q1, railTop), new Vector3(q0, railTop),
                new Vector3(d0, 0), new Vector3(d1, 0), new Vector3(d1, 0), new Vector3(d0, 0));
        }
    }

    // The cup's wall under a run of rim points, from their height down to the bottom, facing the centre.
    private static void Wall(MeshBuilder cup, Pocket p, List<Vector2> points, float top, float bottom)
    {
        for (int k = 0; k + 1 < points.Count; k++)
        {
            var p0 = points[k];
            var p1 = points[k + 1];
            var n0 = new Vector3(Vector2.Normalize(p.Centre - p0), 0);
            var n1 = new Vector3(Vector2.Normalize(p.Centre - p1), 0);
            cup.Quad(new Vector3(p0, top), new Vector3(p1, top), new Vector3(p1, bottom), new Vector3(p0, bottom), n0, n1, n1, n0);
        }
    }

    private static void BuildLegsAndFloor(MeshBuilder frame, MeshBuilder floor, float ox, float oy)
    {
        float floorZ = -BedHeight;
        foreach (int sx in new[] { -1, 1 })
        {
            foreach (int sy in new[] { -1, 1 })
            {
                var c = new Vector2(sx * (ox - 0.16f), sy * (oy - 0.16f));
                Leg(frame, c, ApronBottom, floorZ);
            }
        }
        const float Extent = 6;
        floor.Quad(new(-Extent, -Extent, floorZ), new(Extent, -Extent, floorZ), new(Extent, Extent, floorZ), new(-Extent, Extent, floorZ), Vector3.UnitZ);
    }

    private static void Leg(MeshBuilder mesh, Vector2 centre, float top, float bottom)
    {
        // A square leg, tapered, with a wider foot.
        (float Z, float Half)[] rings = [(top, 0.075f), (top - 0.06f, 0.075f), (top - 0.08f, 0.06f), (bottom + 0.1f, 0.05f), (bottom + 0.08f, 0.07f), (bottom, 0.07f)];
        Vector2[] corners = [new(-1, -1), new(1, -1), new(1, 1), new(-1, 1)];
        for (int r = 0; r + 1 < rings.Length; r++)
        {
            var (z0, h0) = rings[r];
            var (z1, h1) = rings[r + 1];
            for (int s = 0; s < 4; s++)
            {
                var a = corners[s];
                var b = corners[(s + 1) % 4];
                var sideNormal = Vector2.Normalize(a + b);
                float slope = (h0 - h1) / MathF.Max(1e-4f, z0 - z1);
                var n = Vector3.Normalize(new Vector3(sideNormal, -slope));
                mesh.Quad(new Vector3(centre + (h0 * a), z0), new Vector3(centre + (h0 * b), z0),
                          new Vector3(centre + (h1 * b), z1), new Vector3(centre + (h1 * a), z1), n);
            }
        }
    }
}
