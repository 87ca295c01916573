using System.Diagnostics;
using System.Globalization;
using Billiards.Core.Table;

namespace Billiards.Core.Physics;

/// <summary>
/// Debug-build checks of a simulation's state after every step, in the manner of bepuphysics'
/// MathChecker: no NaN or infinity in any ball's state, no ball that is not pocketed off the table
/// (<see cref="TableBounds"/>), and, for the integrators that promise it, no two balls inside each
/// other. The calls compile away in Release builds, so they cost nothing there.
/// </summary>
public static class StateChecker
{
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
            if (!TableBounds.Contains(simulation.Table, b.Position, radius))
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
