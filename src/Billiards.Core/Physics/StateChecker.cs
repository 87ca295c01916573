using System.Diagnostics;
using System.Globalization;
using Billiards.Core.Table;

namespace Billiards.Core.Physics;

/// <summary>Where a ball not in motion is, checked against the table (<see cref="StateChecker.PlaceOf"/>).</summary>
public enum BallPlace : byte
{
    /// <summary>On the bed: inside the cushion noses or in a pocket's mouth, touching no cushion deeper than round-off.</summary>
    Bed,

    /// <summary>In a pocket.</summary>
    Pocket,

    /// <summary>Off the table (state <see cref="Balls.MotionState.OffTable"/>): over a rail, on one, or on the floor.</summary>
    OffTable,

    /// <summary>In the air, or on the bed's height over a rail or the floor: not at rest on anything of the table (an escape).</summary>
    Outside,

    /// <summary>On the bed's height with its centre on the table but inside a cushion or jaw (an escape).</summary>
    InsideCushion,
}

/// <summary>
/// Debug-build checks of a simulation's state after every step, in the manner of bepuphysics'
/// MathChecker: no NaN or infinity in any ball's state, no ball on the bed that is not pocketed off
/// the table (<see cref="TableBounds"/>; a ball in the air may fly over the rails), and, for the
/// integrators that promise it, no two balls inside each other. The calls compile away in Release
/// builds, so they cost nothing there. <see cref="PlaceOf"/>, the table-bound guarantee for a ball
/// at rest, is always compiled.
/// </summary>
public static class StateChecker
{
    /// <summary>How deep a ball at rest may reach into a cushion and still be on the bed (m): round-off of exact contact times.</summary>
    public const double CushionTolerance = 1e-6;

    /// <summary>
    /// Where ball <paramref name="index"/> of <paramref name="simulation"/> is, against the table:
    /// out of play (pocketed or off the table, by its state), on the bed (z = R within
    /// <see cref="CushionTolerance"/>, its centre on the table by <see cref="TableBounds"/> and, in
    /// the standard model, no deeper than <see cref="CushionTolerance"/> in a cushion or jaw), or
    /// not (<see cref="BallPlace.Outside"/>: in the air, or at the bed's height off the table;
    /// <see cref="BallPlace.InsideCushion"/>). A ball at rest must never be either of the last two.
    /// </summary>
    public static BallPlace PlaceOf(Simulation simulation, int index)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        ref readonly var b = ref simulation.Balls[index];
        if (b.IsPocketed)
        {
            return BallPlace.Pocket;
        }
        if (b.State == Balls.MotionState.OffTable)
        {
            return BallPlace.OffTable;
        }
        double r = simulation.BallRadius;
        if (b.State == Balls.MotionState.Airborne || Math.Abs(b.Position.Z - r) > CushionTolerance || !TableBounds.Contains(simulation.Table, b.Position, r))
        {
            return BallPlace.Outside;
        }
        if (simulation is Standard.StandardSimulation standard && standard.Geometry.CushionDepth(b.Position) > CushionTolerance)
        {
            return BallPlace.InsideCushion;
        }
        return BallPlace.Bed;
    }

    /// <summary>Overlap allowed between two balls (m): round-off of exact contact times.</summary>
    public const double OverlapTolerance = 1e-6;

    /// <summary>Throws <see cref="InvalidOperationException"/> naming the first broken invariant.</summary>
    /// <param name="simulation">The simulation after a step.</param>
    /// <param name="radius">Its ball radius (m).</param>
    /// <param name="checkOverlap">False for the integrators that find contacts by overlap (euler, thesis), which overlap inside a step by design.</param>
    [Conditional("DEBUG")]
    public static void Check(Simulation simulation, double radius, bool checkOverlap)
    {
        var balls = simulation.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            ref readonly var b = ref balls[i];
            if (!Finite(b.Position.X, b.Position.Y, b.Position.Z) || !Finite(b.Velocity.X, b.Velocity.Y, b.Velocity.Z) || !Finite(b.Spin.X, b.Spin.Y, b.Spin.Z))
            {
                Fail(simulation, $"ball {simulation.Ids[i]} has a non-finite state: position {b.Position}, velocity {b.Velocity}, spin {b.Spin}");
            }
            if (b.IsPocketed || b.State == Balls.MotionState.OffTable)
            {
                continue;
            }
            if (b.State != Balls.MotionState.Airborne && !TableBounds.Contains(simulation.Table, b.Position, radius))
            {
                Fail(simulation, $"ball {simulation.Ids[i]} left the table: centre {b.Position}");
            }
            if (!checkOverlap)
            {
                continue;
            }
            for (int j = i + 1; j < balls.Length; j++)
            {
                if (balls[j].IsPocketed || balls[j].State == Balls.MotionState.OffTable)
                {
                    continue;
                }
                double gap = (b.Position - balls[j].Position).Length - 2 * radius;
                if (gap < -OverlapTolerance)
                {
                    Fail(simulation, $"balls {simulation.Ids[i]} and {simulation.Ids[j]} overlap by {-gap} m");
                }
            }
        }
    }

    private static bool Finite(double x, double y, double z) => double.IsFinite(x) && double.IsFinite(y) && double.IsFinite(z);

    private static void Fail(Simulation simulation, FormattableString problem) =>
        throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture,
            $"{simulation.Model}/{simulation.Integrator} at t = {simulation.Time} s, step {simulation.StepCount}: {problem.ToString(CultureInfo.InvariantCulture)}"));
}
