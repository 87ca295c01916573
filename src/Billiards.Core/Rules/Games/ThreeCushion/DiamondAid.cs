using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

// The diamond aid: the cue ball's path to its third cushion as our physics plays the stroke (not a
// diamond system's formula), with each cushion contact read in the numbers of the corner-5 system,
// the "diamond system" of three-cushion (Alciatore, TP 7.2; Byrne). The stroke is simulated on a
// copy of the table (the object balls included: a ball in the way is met as in the shot) by single
// events, so each cushion contact is taken at its event's time, where the ball touches the nose.

/// <summary>A rail of the carom table, left and right as seen from the head rail (scene-format.md).</summary>
public enum CaromRail
{
    /// <summary>The head (short) rail, at -x.</summary>
    Head,

    /// <summary>The foot (short) rail, at +x.</summary>
    Foot,

    /// <summary>The left long rail seen from the head, at +y.</summary>
    Left,

    /// <summary>The right long rail seen from the head, at -y.</summary>
    Right,
}

/// <summary>One cushion contact of the cue ball on the aid's path.</summary>
/// <param name="Count">Which contact it is, 1 for the first.</param>
/// <param name="Time">When, after the strike (s).</param>
/// <param name="Centre">The ball's centre at the contact (m, table frame).</param>
/// <param name="Rail">The rail it meets.</param>
/// <param name="Diamond">Its place on that rail in diamonds (<see cref="DiamondAid"/> says from where).</param>
public readonly record struct CushionContact(int Count, double Time, Vec3 Centre, CaromRail Rail, double Diamond);

/// <summary>
/// The aid's answer for one stroke: the cue ball's path (centres, from the strike to its last
/// contact), its cushion contacts (up to three), and the corner-5 numbers of the stroke's line.
/// </summary>
/// <param name="Path">The cue ball's centre from the strike, every <see cref="DiamondAid.SampleSeconds"/> and at each event, to the last contact (m).</param>
/// <param name="Contacts">Its cushion contacts, at most <see cref="DiamondAid.Cushions"/>.</param>
/// <param name="Origin">The corner-5 origin number D of the stroke's line (5 at the corner), or null when the system does not number the stroke (a ball before the first cushion, a first cushion on a short rail, a line that starts elsewhere).</param>
/// <param name="FirstRail">The corner-5 first-rail number F where the stroke's line crosses the first rail, or null as for <paramref name="Origin"/>.</param>
public sealed record DiamondPath(IReadOnlyList<Vec3> Path, IReadOnlyList<CushionContact> Contacts, double? Origin, double? FirstRail)
{
    /// <summary>The corner-5 formula's third-rail number, T = D - F (null without D and F).</summary>
    public double? FormulaThirdRail => Origin is { } d && FirstRail is { } f ? d - f : null;

    /// <summary>The third contact's number as the aid reads it (diamonds from the far end on a long rail), or null.</summary>
    public double? ThirdRail => Contacts.Count >= 3 ? Contacts[2].Diamond : null;
}

/// <summary>
/// The diamond aid of three-cushion (F4 in the window): for a stroke, the simulated path of the
/// cue ball to its third cushion, labelled in the corner-5 system's numbers.
/// </summary>
/// <remarks>
/// Numbers (Alciatore, TP 7.2, "traditional corner-5 numbering"; Byrne): on a long rail, the
/// diamonds (1/8 of the length) from the far end, the short rail toward which the cue ball travels
/// along the table when it meets its first cushion (0 at the far end, 8 at the near one); on a
/// short rail, the diamonds (1/4 of the width) from the first rail's side. The stroke's line (the
/// aim from the cue ball's centre) gives the origin D (5 at the near corner, by halves up the long
/// rail opposite the first rail, 6, 7, 8 along the near short rail) and the first-rail number F,
/// where the line crosses those rails. Ours: the lines are read where they cross the cushion
/// noses' lines, with the diamonds projected onto them, not on the sights set into the rail tops.
/// </remarks>
public static class DiamondAid
{
    /// <summary>The cushion contacts the aid follows the path to.</summary>
    public const int Cushions = 3;

    /// <summary>The path's spacing in time between events (s).</summary>
    public const double SampleSeconds = 0.01;

    /// <summary>The longest stroke followed (s): a slow ball may rest before its third cushion.</summary>
    public const double MaxSeconds = 30;

    /// <summary>
    /// The aid for <paramref name="shot"/> on the cue ball <paramref name="position"/> names, simulated
    /// on <paramref name="model"/> (the game's own table model and physics).
    /// </summary>
    public static DiamondPath Trace(TableModel model, TablePosition position, ShotSpec shot)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(position);
        ArgumentNullException.ThrowIfNull(shot);
        var table = model.Table;
        var sim = position.CreateSimulation(model);
        int cue = sim.IndexOf(position.CueBall);
        var path = new List<Vec3>();
        var contacts = new List<CushionContact>();
        if (cue < 0)
        {
            return new DiamondPath(path, contacts, null, null);
        }
        path.Add(sim.Balls[cue].Position);
        sim.Strike(shot, position.CueBall);
        int seen = sim.Events.Count;
        double farEndX = 0;
        bool stepping = false, ballFirst = false;
        for (double t = SampleSeconds; t <= MaxSeconds && contacts.Count < Cushions && !sim.IsAtRest; t += SampleSeconds)
        {
            // One event at a time up to the sample's time: a cushion contact is read where it happens.
            while (!stepping && contacts.Count < Cushions)
            {
                bool? resolved = sim.AdvanceOneEvent(t);
                stepping = resolved is null;
                if (resolved != true)
                {
                    break;
                }
                ReadEvents();
            }
            // A stepping integrator: step by step, a contact read at the end of its step (as
            // AdvanceTo to the event's time would leave the ball).
            while (stepping && contacts.Count < Cushions && sim.Time < t - 1e-12 && !sim.IsAtRest)
            {
                sim.Step();
                ReadEvents();
            }
            if (contacts.Count < Cushions)
            {
                sim.AdvanceTo(t);
                path.Add(sim.Balls[cue].Position);
            }
        }
        // The system numbers a line that meets a cushion first, not a ball.
        var (origin, first) = ballFirst ? (null, null) : CornerFive(table, path[0], shot.AimDeg, contacts);
        return new DiamondPath(path, contacts, origin, first);

        void ReadEvents()
        {
            var events = sim.Events;
            for (; seen < events.Count && contacts.Count < Cushions; seen++)
            {
                var e = events[seen];
                if (e.Kind == EventKind.BallBall && contacts.Count == 0 && (e.A == position.CueBall || e.B == position.CueBall))
                {
                    ballFirst = true;
                }
                if (e.Kind != EventKind.BallCushion || e.A != position.CueBall)
                {
                    continue;
                }
                var centre = sim.Balls[cue].Position;
                var rail = RailAt(table, centre);
                if (contacts.Count == 0)
                {
                    // The far end: where the ball heads along the table as it meets the first cushion.
                    double dx = centre.X - path[0].X;
                    farEndX = rail is CaromRail.Foot || (rail is not CaromRail.Head && dx >= 0) ? table.HalfLength : -table.HalfLength;
                }
                var firstRail = contacts.Count == 0 ? rail : contacts[0].Rail;
                contacts.Add(new CushionContact(contacts.Count + 1, e.Time, centre, rail, Number(table, centre, rail, farEndX, firstRail)));
                path.Add(centre);
            }
        }
    }

    /// <summary>The rail nearest to a ball centre touching a cushion.</summary>
    public static CaromRail RailAt(TableSpec table, Vec3 centre)
    {
        ArgumentNullException.ThrowIfNull(table);
        double toEnd = table.HalfLength - Math.Abs(centre.X), toSide = table.HalfWidth - Math.Abs(centre.Y);
        return toEnd < toSide ? (centre.X > 0 ? CaromRail.Foot : CaromRail.Head) : (centre.Y > 0 ? CaromRail.Left : CaromRail.Right);
    }

    /// <summary>True for the two long rails.</summary>
    public static bool IsLong(CaromRail rail) => rail is CaromRail.Left or CaromRail.Right;

    // A point's number on its rail: a long rail's diamonds from the far end; a short rail's from the first rail's side.
    private static double Number(TableSpec table, Vec3 p, CaromRail rail, double farEndX, CaromRail firstRail)
    {
        double spacing = CaromTable.DiamondSpacing(table);
        if (IsLong(rail))
        {
            return Math.Abs(farEndX - p.X) / spacing;
        }
        double sideY = firstRail == CaromRail.Right ? -table.HalfWidth : table.HalfWidth;
        return Math.Abs(sideY - p.Y) / spacing;
    }

    // D and F of the stroke's line (the aim from the cue ball's centre): F where it crosses the first
    // rail's nose line, D where it crosses, backwards, the long rail opposite or the near short rail.
    private static (double? Origin, double? First) CornerFive(TableSpec table, Vec3 cue, double aimDeg, List<CushionContact> contacts)
    {
        if (contacts.Count == 0 || !IsLong(contacts[0].Rail))
        {
            return (null, null);
        }
        double a = aimDeg * Math.PI / 180;
        double dx = DeterministicMath.Cos(a), dy = DeterministicMath.Sin(a);
        double railY = contacts[0].Rail == CaromRail.Left ? table.HalfWidth : -table.HalfWidth;
        if (Math.Abs(dy) < 1e-9 || Math.Sign(dy) != Math.Sign(railY))
        {
            return (null, null);
        }
        double spacing = CaromTable.DiamondSpacing(table);
        double farX = contacts[0].Centre.X >= cue.X ? table.HalfLength : -table.HalfLength;
        double s = (railY - cue.Y) / dy;
        double first = Math.Abs(farX - (cue.X + (s * dx))) / spacing;
        if (first > CaromTable.DiamondDivisions)
        {
            return (null, null);
        }
        // Backwards: the opposite long rail (y = -railY) or the near short rail (x = -farX), whichever comes first.
        double back = double.PositiveInfinity;
        double toLong = (-railY - cue.Y) / -dy;
        double toShort = Math.Abs(dx) < 1e-9 ? double.PositiveInfinity : (-farX - cue.X) / -dx;
        back = Math.Min(toLong >= 0 ? toLong : back, toShort >= 0 ? toShort : back);
        if (double.IsInfinity(back))
        {
            return (null, first);
        }
        double bx = cue.X - (back * dx), by = cue.Y - (back * dy);
        double origin = back == toLong
            ? 5 - (0.5 * Math.Abs(bx - (-farX)) / spacing)
            : 5 + (Math.Abs(by - (-railY)) / spacing);
        return (origin, first);
    }
}
