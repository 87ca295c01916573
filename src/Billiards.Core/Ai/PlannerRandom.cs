using Billiards.Core.Mathematics;
namespace Billiards.Core.Ai;

/// <summary>
/// The planner's random numbers: SplitMix64, fixed here rather than taken from the runtime so that a
/// seed gives the same games on every machine and .NET version. Streams are derived from a seed and
/// indices (<see cref="Derive"/>), so every simulation of a search has its own stream whatever
/// thread runs it.
/// </summary>
public sealed class PlannerRandom
{
    private ulong _state;

    /// <summary>A generator started from <paramref name="seed"/>.</summary>
    public PlannerRandom(ulong seed) => _state = seed;

    /// <summary>A seed mixed from a parent seed and two indices (for per-candidate, per-sample streams).</summary>
    public static ulong Derive(ulong seed, long a, long b = 0)
    {
        ulong x = seed ^ Mix((ulong)a + 0x9E3779B97F4A7C15UL) ^ Mix(((ulong)b << 1) + 0xD1B54A32D192ED03UL);
        return Mix(x);
    }

    /// <summary>The next 64 random bits.</summary>
    public ulong NextUInt64()
    {
        _state += 0x9E3779B97F4A7C15UL;
        return Mix(_state);
    }

    /// <summary>Uniform in [0, 1).</summary>
    public double NextDouble() => (NextUInt64() >> 11) * (1.0 / (1UL << 53));

    /// <summary>A standard normal sample (Box-Muller).</summary>
    public double NextGaussian()
    {
        double u = 1.0 - NextDouble();
        double v = NextDouble();
        return Math.Sqrt(-2.0 * DeterministicMath.Log(u)) * DeterministicMath.Cos(2 * Math.PI * v);
    }

    /// <summary>A standard normal sample clamped to [-4, 4] (the clamp changes the standard deviation by less than 0.2 %).</summary>
    public double NextClampedGaussian() => Math.Clamp(NextGaussian(), -4, 4);

    private static ulong Mix(ulong z)
    {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }
}
