namespace Billiards.Core.Physics.Collisions;

/// <summary>An impact integrated over its normal impulse: the state's rates per unit impulse and its normal approach speed.</summary>
/// <typeparam name="TState">The bodies' velocities and spins (a value type).</typeparam>
internal interface IImpact<TState>
    where TState : struct
{
    /// <summary>The rates of change of the state per unit normal impulse (N s).</summary>
    TState Slopes(in TState state);

    /// <summary>The normal approach speed at the contact (m/s; negative when separating), linear in the state (so also the rate of approach of the slopes).</summary>
    double Approach(in TState state);

    /// <summary>The state plus <paramref name="h"/> times the rates.</summary>
    TState Add(in TState state, in TState rates, double h);
}

/// <summary>
/// Explicit Euler in the normal impulse, through compression (until the normal approach speed
/// vanishes) and restitution (until the normal force has given back e^2 of the compression work:
/// Stronge's energetic restitution), the integration the Mathavan models share. Each step takes
/// the slopes of its start; the last step of each phase is cut to end it exactly, since within a
/// step the normal speed is linear in the impulse and its work quadratic. A phase that reaches
/// <see cref="MaxStepsPerPhase"/> is cut short: the impact is returned as it stands and counted in
/// <see cref="Truncated"/> (per thread; the standard simulation reports it as
/// <see cref="Simulation.TruncatedImpacts"/>), never silently. Generic over value types, so nothing
/// is allocated.
/// </summary>
internal static class ImpulseIntegration
{
    /// <summary>A ceiling on the steps of one phase, so that a degenerate impact cannot loop forever.</summary>
    public const int MaxStepsPerPhase = 100_000;

    [ThreadStatic]
    private static long t_truncated;

    /// <summary>How many impacts this thread has cut short at <see cref="MaxStepsPerPhase"/> (ever; callers take differences).</summary>
    public static long Truncated => t_truncated;

    /// <summary>Integrates an approaching impact with impulse steps of <paramref name="step"/> (N s) and restitution <paramref name="e"/>.</summary>
    public static TState Run<TState, TImpact>(TState state, in TImpact impact, double step, double e)
        where TState : struct
        where TImpact : struct, IImpact<TState>
    {
        double work = 0;
        bool compressed = false;
        for (int i = 0; i < MaxStepsPerPhase; i++)
        {
            var rates = impact.Slopes(state);
            double c = impact.Approach(state);
            double dc = impact.Approach(rates);
            double h = step;
            bool last = c + dc * h <= 0;
            if (last)
            {
                h = dc < 0 ? c / -dc : 0;
            }
            work += (c + 0.5 * dc * h) * h;
            state = impact.Add(state, rates, h);
            if (last)
            {
                compressed = true;
                break;
            }
        }

        double remaining = e * e * work;
        for (int i = 0; i < MaxStepsPerPhase && remaining > 0; i++)
        {
            var rates = impact.Slopes(state);
            double s = -impact.Approach(state);
            double ds = -impact.Approach(rates);
            double h = step;
            double stepWork = (s + 0.5 * ds * h) * h;
            if (stepWork >= remaining)
            {
                // 0.5 ds h^2 + s h = remaining, in the form that stays exact as ds -> 0.
                double root = s + Math.Sqrt(Math.Max(0, s * s + 2 * ds * remaining));
                h = root > 0 ? Math.Min(h, 2 * remaining / root) : h;
                stepWork = remaining;
            }
            remaining -= stepWork;
            state = impact.Add(state, rates, h);
        }
        if (!compressed || remaining > 0)
        {
            t_truncated++;
        }
        return state;
    }
}
