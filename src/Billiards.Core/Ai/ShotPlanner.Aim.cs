using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;

namespace Billiards.Core.Ai;

/// <summary>Aim correction: the geometric aim corrected for throw and squirt, and aiming by trial.</summary>
public sealed partial class ShotPlanner
{
    /// <summary>
    /// The cue's aim (deg) that sends the candidate's first ball along its direction with the given
    /// tip, corrected for throw (the object ball dragged towards the cue ball's path by ball-ball
    /// friction) and for squirt (the cue ball leaving off the cue's line with side spin).
    /// </summary>
    internal double AimFor(Candidate c, Vec3 cue, double tipSide, double tipHeight)
    {
        var p = Table.Physics;
        double r = Table.R;
        var aimPoint = c.AimPoint;
        if (c.Direction != Vec3.Zero)
        {
            var u = c.Direction;
            var ghost = c.Contact - u * (2 * r);
            double mu = p.MuBModel == BallBallFriction.Constant ? p.MuB : 0.06;
            for (int iteration = 0; iteration < 3; iteration++)
            {
                var v = (ghost - cue).XY.Normalized();
                double sin = v.X * c.Direction.Y - v.Y * c.Direction.X;
                double cos = Vec3.Dot(v, c.Direction);
                if (cos <= 0.05)
                {
                    break;
                }
                double s = Math.Abs(sin);
                // A stunned ball slides across the object ball; a rolling one also slides vertically,
                // which takes friction away from the sideways throw (Alciatore, TP A.14).
                double roll = Math.Abs(tipHeight) > 0.1 ? 1 : 0.5;
                double slip = Math.Sqrt(s * s + roll * roll * cos * cos);
                double tan = Math.Min(mu * s / Math.Max(slip, 1e-9), 2 * s / (7 * (1 + p.EB) * cos));
                double throwAngle = DeterministicMath.Atan(tan) * Math.Sign(sin);
                double ca = DeterministicMath.Cos(throwAngle);
                double sa = DeterministicMath.Sin(throwAngle);
                var turned = new Vec3(c.Direction.X * ca - c.Direction.Y * sa, c.Direction.X * sa + c.Direction.Y * ca, 0);
                ghost = c.Contact - turned * (2 * r);
            }
            aimPoint = ghost;
        }
        var d = aimPoint - cue;
        double aim = DeterministicMath.Atan2(d.Y, d.X) * 180 / Math.PI;
        aim -= CueStrike.SquirtAngle(tipSide, p.M / p.CueEndMass) * 180 / Math.PI;
        return aim;
    }

    /// <summary>The step (deg) between the aims tried without error either side of a pot's geometric aim.</summary>
    public const double AimTrialStepDeg = 0.3;

    // Halvings of the step at each end of the potting range: its ends are then known to a quarter step.
    private const int EdgeHalvings = 2;

    /// <summary>
    /// The aim (deg) in the middle of the range of aims that pot: <paramref name="pots"/> says whether
    /// the shot aimed at an angle pots without error. It is tried at <paramref name="trials"/> steps of
    /// <see cref="AimTrialStepDeg"/> either side of <paramref name="aim"/>; of the runs of potting aims the
    /// one whose middle is nearest <paramref name="aim"/> is taken, and each of its ends inside the tried
    /// range is found to a quarter step by halving. Without a potting aim, <paramref name="aim"/> itself.
    /// </summary>
    /// <returns>The centred aim and the number of trials it took.</returns>
    internal static (double AimDeg, int Trials) CentredAim(Func<double, bool> pots, double aim, int trials)
    {
        ArgumentNullException.ThrowIfNull(pots);
        int n = 2 * trials + 1;
        Span<bool> made = stackalloc bool[n];
        for (int j = 0; j < n; j++)
        {
            made[j] = pots(aim + (j - trials) * AimTrialStepDeg);
        }
        int tried = n;
        int lo = -1, hi = -1;
        double nearest = double.MaxValue;
        for (int j = 0; j < n;)
        {
            if (!made[j])
            {
                j++;
                continue;
            }
            int start = j;
            while (j < n && made[j])
            {
                j++;
            }
            double off = Math.Abs((start + j - 1) / 2.0 - trials);
            if (off < nearest)
            {
                (nearest, lo, hi) = (off, start, j - 1);
            }
        }
        if (lo < 0)
        {
            return (aim, tried);
        }
        double At(int j) => aim + (j - trials) * AimTrialStepDeg;
        double Edge(double inside, double outside)
        {
            for (int k = 0; k < EdgeHalvings; k++)
            {
                double middle = (inside + outside) / 2;
                tried++;
                if (pots(middle))
                {
                    inside = middle;
                }
                else
                {
                    outside = middle;
                }
            }
            return (inside + outside) / 2;
        }
        double lower = lo > 0 ? Edge(At(lo), At(lo - 1)) : At(lo);
        double upper = hi < n - 1 ? Edge(At(hi), At(hi + 1)) : At(hi);
        return ((lower + upper) / 2, tried);
    }
}
