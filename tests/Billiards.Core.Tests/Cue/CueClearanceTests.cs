using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Cue;

public class CueClearanceTests
{
    private static readonly TableSpec s_table = TableSpec.FromPreset("pool-9ft");
    private const double R = 0.028575;

    // The cue's axis as the renderer builds it: through the tip's contact point on the cue ball,
    // R·side to the right and R·height along the tilted up vector, pointing down into the ball.
    private static double DistanceToAxis(Vec3 cueBall, Vec3 aim, double elevationDeg, double side, double height, Vec3 point)
    {
        double e = elevationDeg * Math.PI / 180;
        var forward = (aim * Math.Cos(e)) - (new Vec3(0, 0, 1) * Math.Sin(e));
        var up = (aim * Math.Sin(e)) + (new Vec3(0, 0, 1) * Math.Cos(e));
        var right = new Vec3(aim.Y, -aim.X, 0);
        var through = cueBall + (R * ((side * right) + (height * up)));
        var w = point - through;
        double along = Vec3.Dot(w, forward);
        return (w - (forward * along)).Length;
    }

    [Fact]
    public void ACueOverOpenBedNeedsNoRaiseAndNearARailItClearsTheRailTop()
    {
        // Far from the rail behind: 1 m of bed; the cue rising from the ball's centre is above the rail top after 1 m at 1 deg or so.
        var aim = new Vec3(1, 0, 0);
        double far = CueClearance.RailElevationDegrees(new Vec3(0, 0, R), aim, s_table, R);
        Assert.InRange(far, 0, 2);
        // 2 cm from the head cushion's nose, aiming away from it.
        var ball = new Vec3(-s_table.HalfLength + R + 0.02, 0, R);
        double s = CueClearance.DistanceToRail(ball, aim, s_table);
        Assert.Equal(R + 0.02, s, 12);
        double e = CueClearance.RailElevationDegrees(ball, aim, s_table, R);
        // Where it crosses the nose line the cue's underside is the rail top plus the gap.
        double underside = R + (s * Math.Tan(e * Math.PI / 180)) - (CueClearance.TipRadius + ((CueClearance.ButtRadius - CueClearance.TipRadius) * s / CueClearance.CueLength));
        Assert.Equal(CueClearance.RailTop(s_table) + CueClearance.RailGap, underside, 9);
        Assert.True(e > 20, $"{e} deg");
        // Drawing the ball (tip below centre) starts the cue lower: it must rise more.
        Assert.True(CueClearance.RailElevationDegrees(ball, aim, s_table, R, tipHeight: -0.5) > e + 5);
    }

    [Theory]
    [InlineData(2.0, 0.0, 0.0, 0.0)]     // frozen right behind, centre hit
    [InlineData(2.5, 0.01, 0.0, 0.0)]    // a little off the line
    [InlineData(3.0, 0.0, 0.0, -0.4)]    // draw: the axis starts lower
    [InlineData(4.0, -0.015, 0.3, 0.2)]  // side and follow
    public void OverABallBehindTheCuePassesItByTheGap(double behindRadii, double sideways, double tipSide, double tipHeight)
    {
        var cueBall = new Vec3(0, 0, R);
        var aim = new Vec3(Math.Cos(0.3), Math.Sin(0.3), 0);
        var right = new Vec3(aim.Y, -aim.X, 0);
        var other = cueBall - (aim * (behindRadii * R)) + (right * sideways);
        double e = CueClearance.BallElevationDegrees(cueBall, aim, other, R, tipSide, tipHeight);
        Assert.InRange(e, 1, 80);
        // At that elevation the cue's surface is the gap from the ball (the cue's radius taken where it passes).
        double s = behindRadii * R;
        double expected = R + CueClearance.RadiusAt(s) + CueClearance.BallGap;
        Assert.Equal(expected, DistanceToAxis(cueBall, aim, e, tipSide, tipHeight, other), 9);
        Assert.True(DistanceToAxis(cueBall, aim, e - 1, tipSide, tipHeight, other) < expected);
    }

    [Fact]
    public void BallsInFrontBesideTheCueOrBeyondItsButtDoNotRaiseIt()
    {
        var cueBall = new Vec3(0, 0, R);
        var aim = new Vec3(1, 0, 0);
        Assert.Equal(0, CueClearance.BallElevationDegrees(cueBall, aim, new Vec3(3 * R, 0, R), R));
        Assert.Equal(0, CueClearance.BallElevationDegrees(cueBall, aim, new Vec3(-3 * R, R + CueClearance.RadiusAt(3 * R) + CueClearance.BallGap + 0.001, R), R));
        Assert.Equal(0, CueClearance.BallElevationDegrees(cueBall, aim, new Vec3(-CueClearance.CueLength - 0.01, 0, R), R));
    }

    [Fact]
    public void APlayableShotIsRaisedToTheHigherOfTheRailAndTheBallsAndNeverLowered()
    {
        var cueBall = new Vec3(0, 0, R);
        var behind = new Vec3(-2.2 * R, 0, R);
        var level = new ShotSpec(3, 0);
        var raised = CueClearance.Playable(level, s_table, R, cueBall, [cueBall, behind]);
        var aim = new Vec3(1, 0, 0);
        double ball = CueClearance.BallElevationDegrees(cueBall, aim, behind, R);
        Assert.True(ball > CueClearance.RailElevationDegrees(cueBall, aim, s_table, R));
        Assert.Equal(ball, raised.ElevationDeg, 12);
        Assert.Equal(level with { ElevationDeg = raised.ElevationDeg }, raised);
        var steep = level with { ElevationDeg = 60 };
        Assert.Same(steep, CueClearance.Playable(steep, s_table, R, cueBall, [behind]));
        // Nothing behind: on open bed only the far rail, 1.27 m away, lifts a level cue (by about 1.4 deg).
        var open = CueClearance.Playable(level, s_table, R, cueBall, [new Vec3(0.5, 0, R)]);
        Assert.Equal(CueClearance.RailElevationDegrees(cueBall, aim, s_table, R), open.ElevationDeg, 12);
        Assert.InRange(open.ElevationDeg, 1, 2);
    }
}
