using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Cue;

/// <summary>
/// How high a cue must be raised to address the cue ball: a player's cue never passes through a
/// rail or a ball, so over a rail behind the cue ball, or over a ball lying behind it, it is raised
/// until its underside clears them. The one rule the game's cue, the computer player and its hints
/// all play by; the camera also keeps above the rail's top.
/// </summary>
public static class CueClearance
{
    /// <summary>Cue length (m): 145 cm, tip to butt.</summary>
    public const double CueLength = 1.45;

    /// <summary>The cue's radius at the tip (m): 0.5 cm.</summary>
    public const double TipRadius = 0.005;

    /// <summary>The cue's radius at the butt (m): 1.25 cm; it thickens linearly from the tip.</summary>
    public const double ButtRadius = 0.0125;

    /// <summary>Largest elevation a cue is played at (deg): Core's strike accepts up to 90, but the cue would stand on the ball.</summary>
    public const double MaxElevationDegrees = 80;

    /// <summary>Gap kept between the cue's underside and the rail's top (m).</summary>
    public const double RailGap = 0.005;

    /// <summary>Gap kept between the cue's surface and a ball it passes over (m).</summary>
    public const double BallGap = 0.003;

    /// <summary>Height of the rail's top above the bed (m): the cushion nose plus the rubber's top (the table model's).</summary>
    public static double RailTop(TableSpec table)
    {
        ArgumentNullException.ThrowIfNull(table);
        return table.CushionHeight + 0.0065;
    }

    /// <summary>The cue's radius (m) at <paramref name="along"/> metres from its tip (clamped to the cue).</summary>
    public static double RadiusAt(double along) =>
        TipRadius + ((ButtRadius - TipRadius) * Math.Clamp(along, 0, CueLength) / CueLength);

    /// <summary>
    /// Horizontal distance (m) from a point on the bed backwards along <paramref name="aim"/> (unit,
    /// bed plane) to the nearest cushion nose line; infinity for a zero aim.
    /// </summary>
    public static double DistanceToRail(Vec3 ball, Vec3 aim, TableSpec table)
    {
        ArgumentNullException.ThrowIfNull(table);
        return table.DistanceToCushion(ball, -aim);
    }

    /// <summary>
    /// The least elevation (deg) at which a cue addressing a ball of radius <paramref name="radius"/>
    /// at <paramref name="ball"/> along <paramref name="aim"/> clears the rail behind it: the cue's
    /// underside, rising from the height of the tip's contact (the centre plus
    /// <paramref name="tipHeight"/> R), must be <see cref="RailGap"/> above the rail top where it
    /// crosses the cushion nose (the rail only gets farther and the cue higher beyond).
    /// </summary>
    public static double RailElevationDegrees(Vec3 ball, Vec3 aim, TableSpec table, double radius, double tipHeight = 0)
    {
        double s = DistanceToRail(ball, aim, table);
        if (!double.IsFinite(s) || s <= 0)
        {
            return 0;
        }
        double rise = RailTop(table) + RailGap + RadiusAt(s) - radius - (tipHeight * radius);
        return rise <= 0 ? 0 : DeterministicMath.Atan2(rise, s) * 180 / Math.PI;
    }

    /// <summary>
    /// The least elevation (deg) at which the cue addressing the cue ball at <paramref name="cueBall"/>
    /// along <paramref name="aim"/> (unit, bed plane), with the tip at (<paramref name="tipSide"/>,
    /// <paramref name="tipHeight"/>) R, passes <see cref="BallGap"/> clear of a ball of the same radius
    /// at <paramref name="other"/>. 0 for a ball not behind the cue ball, beyond the cue's butt, or
    /// off to the side of the cue; <see cref="MaxElevationDegrees"/> or more when no elevation clears it.
    /// </summary>
    /// <remarks>
    /// The cue's axis passes through the tip's contact point, R·side to the right of the cue ball's
    /// centre and R·height above it, square to the axis. A ball s metres behind the cue ball along the
    /// aim and d to the side of the axis is at distance √((s sin e + R·height)² + d²) from the axis
    /// at elevation e, which must be at least R + the cue's radius there + the gap.
    /// </remarks>
    public static double BallElevationDegrees(Vec3 cueBall, Vec3 aim, Vec3 other, double radius, double tipSide = 0, double tipHeight = 0)
    {
        var w = other - cueBall;
        double s = -((w.X * aim.X) + (w.Y * aim.Y));
        if (s <= 0 || s > CueLength)
        {
            return 0;
        }
        double d = (w.X * aim.Y) - (w.Y * aim.X) - (tipSide * radius);
        double clear = radius + RadiusAt(s) + BallGap;
        if (Math.Abs(d) >= clear)
        {
            return 0;
        }
        double sine = (Math.Sqrt((clear * clear) - (d * d)) - (tipHeight * radius)) / s;
        return sine <= 0 ? 0 : sine >= 1 ? 90 : DeterministicMath.Asin(sine) * 180 / Math.PI;
    }

    /// <summary>
    /// The least elevation (deg) that clears both the rail behind the cue ball and every ball of
    /// <paramref name="balls"/> (centres, m; the cue ball itself may be among them), not above
    /// <see cref="MaxElevationDegrees"/>.
    /// </summary>
    public static double MinElevationDegrees(TableSpec table, double radius, Vec3 cueBall, Vec3 aim, IReadOnlyList<Vec3> balls, double tipSide = 0, double tipHeight = 0)
    {
        ArgumentNullException.ThrowIfNull(balls);
        double e = RailElevationDegrees(cueBall, aim, table, radius, tipHeight);
        for (int i = 0; i < balls.Count; i++)
        {
            var p = balls[i];
            if ((p - cueBall).LengthSquared > 1e-12)
            {
                e = Math.Max(e, BallElevationDegrees(cueBall, aim, p, radius, tipSide, tipHeight));
            }
        }
        return Math.Min(e, MaxElevationDegrees);
    }

    /// <summary>
    /// The shot as the cue can play it from <paramref name="cueBall"/> with <paramref name="balls"/>
    /// on the table: its elevation raised to the clearance along its own aim and tip (see
    /// <see cref="MinElevationDegrees"/>) when it is lower; otherwise the shot itself.
    /// </summary>
    public static ShotSpec Playable(ShotSpec shot, TableSpec table, double radius, Vec3 cueBall, IReadOnlyList<Vec3> balls)
    {
        ArgumentNullException.ThrowIfNull(shot);
        double a = shot.AimDeg * Math.PI / 180;
        var aim = new Vec3(DeterministicMath.Cos(a), DeterministicMath.Sin(a), 0);
        double min = MinElevationDegrees(table, radius, cueBall, aim, balls, shot.TipSide, shot.TipHeight);
        return shot.ElevationDeg >= min ? shot : shot with { ElevationDeg = min };
    }
}
