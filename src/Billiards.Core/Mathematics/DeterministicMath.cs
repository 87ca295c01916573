namespace Billiards.Core.Mathematics;

/// <summary>
/// The elementary functions Core needs, computed by this code alone, so that a result has the
/// same bits on every platform. <see cref="Math.Sin"/>, <see cref="Math.Atan2"/>, <see cref="Math.Exp"/>
/// and the others come from the platform's C runtime (glibc on Linux, the UCRT on Windows, wine's
/// own under wine), whose last bits differ; a shot simulated on Windows then replayed on Linux
/// would drift (docs/determinism.md). Only IEEE 754 operations that every platform rounds alike
/// are used here: + − × ÷, <see cref="Math.Sqrt"/>, <see cref="Math.Round(double)"/> and exact bit
/// manipulation, evaluated in the order written (.NET never contracts a·b + c into a fused
/// multiply-add on its own).
/// </summary>
/// <remarks>
/// Accuracy, measured against glibc's correctly-rounded-in-practice functions by
/// DeterministicMathTests: within 1 ulp for <see cref="Sin"/>, <see cref="Cos"/>, <see cref="Exp"/>,
/// <see cref="Log"/> and <see cref="Atan"/>, within 2 ulp for <see cref="Tan"/>, <see cref="Atan2"/>,
/// <see cref="Asin"/> and <see cref="Acos"/>, within 3 ulp for <see cref="Log10"/>. <see cref="Pow"/> is <c>exp(y·log x)</c>: its error
/// grows with |y·log x| (within 4 ulp while |y·log x| ≤ 1, as for the exponents Core uses). Sine, cosine and tangent reduce
/// their argument with a three-part π/2, accurate for |x| below 2^19·π/2 (about 823,000 rad); above,
/// the argument is first reduced modulo 2π in plain double arithmetic (the same bits everywhere,
/// but not accurate to the last bit). Special values (NaN, ±∞, ±0) follow IEEE 754 and C's
/// Annex F, as the platform functions do.
/// </remarks>
public static class DeterministicMath
{
    // π/2 in three parts of 33, 33 and 53 bits: n·P1 and n·P2 are exact for |n| < 2^20.
    private const double PiOver2Part1 = 1.5707963267341256;
    private const double PiOver2Part2 = 6.077100506303966e-11;
    private const double PiOver2Part3 = 2.0222662487959506e-21;
    private const double TwoOverPi = 0.6366197723675814;
    private const double ReductionLimit = 823549.6;          // 2^19·π/2
    private const double TwoPi = 6.283185307179586;
    private const double PiHi = 3.141592653589793;
    private const double PiLo = 1.2246467991473532e-16;
    private const double PiOver2Hi = 1.5707963267948966;
    private const double PiOver2Lo = 6.123233995736766e-17;
    // ln 2 in two parts: k·Ln2Hi is exact for |k| < 2^21.
    private const double Ln2Hi = 0.6931471803691238;
    private const double Ln2Lo = 1.9082149292705877e-10;
    private const double InvLn2 = 1.4426950408889634;
    private const double Ln10 = 2.302585092994046;
    private const double Sqrt2 = 1.4142135623730951;
    private const double ExpOverflow = 709.782712893384;     // above: +∞
    private const double ExpUnderflow = -745.1332191019412;  // below: +0

    // atan(k/8), k = 0..8, as a double and the rest of its value.
    private static readonly double[] AtanHi =
    [
        0.0, 0.12435499454676144, 0.24497866312686414, 0.35877067027057225, 0.4636476090008061,
        0.5585993153435624, 0.6435011087932844, 0.7188299996216245, 0.7853981633974483,
    ];

    private static readonly double[] AtanLo =
    [
        0.0, -3.1253241424539383e-18, 1.0698755618734451e-17, -2.4623815582638635e-17, 2.2698777452961687e-17,
        -5.4556305485916264e-18, 1.5834785051444286e-17, -2.1478388444456983e-17, 3.061616997868383e-17,
    ];

    // e^r = 1 + r + r²·(1/2! + r/3! + ... + r^11/13!): the coefficients, highest power first.
    private static readonly double[] ExpSeries =
    [
        1.0 / 6227020800,
        1.0 / 479001600,
        1.0 / 39916800,
        1.0 / 3628800,
        1.0 / 362880,
        1.0 / 40320,
        1.0 / 5040,
        1.0 / 720,
        1.0 / 120,
        1.0 / 24,
        1.0 / 6,
        0.5,
    ];

    // R/s² = 2/3 + 2s²/5 + ... + 2s^20/23 (log(1 + f) = 2·atanh s), in powers of s², highest first.
    private static readonly double[] LogSeries =
    [
        2.0 / 23,
        2.0 / 21,
        2.0 / 19,
        2.0 / 17,
        2.0 / 15,
        2.0 / 13,
        2.0 / 11,
        2.0 / 9,
        2.0 / 7,
        2.0 / 5,
        2.0 / 3,
    ];

    // sin x = x + x³·(−1/3! + x²/5! − ... + x^14/17!), in powers of x², highest first.
    private static readonly double[] SinSeries =
    [
        1.0 / 355687428096000,
        -1.0 / 1307674368000,
        1.0 / 6227020800,
        -1.0 / 39916800,
        1.0 / 362880,
        -1.0 / 5040,
        1.0 / 120,
        -1.0 / 6,
    ];

    // cos x = 1 − x²/2 + x⁴·(1/4! − x²/6! + ... − x^14/18!), in powers of x², highest first.
    private static readonly double[] CosSeries =
    [
        -1.0 / 6402373705728000,
        1.0 / 20922789888000,
        -1.0 / 87178291200,
        1.0 / 479001600,
        -1.0 / 3628800,
        1.0 / 40320,
        -1.0 / 720,
        1.0 / 24,
    ];

    // atan t = t + t³·(−1/3 + t²/5 − ... − t^12/15), in powers of t², highest first.
    private static readonly double[] AtanSeries =
    [
        -1.0 / 15,
        1.0 / 13,
        -1.0 / 11,
        1.0 / 9,
        -1.0 / 7,
        1.0 / 5,
        -1.0 / 3,
    ];

    /// <summary>The sine of <paramref name="x"/> (rad), the same bits on every platform.</summary>
    public static double Sin(double x) => x == 0 ? x : SineOfQuarterTurns(x, 0);

    /// <summary>The cosine of <paramref name="x"/> (rad), the same bits on every platform.</summary>
    public static double Cos(double x) => SineOfQuarterTurns(x, 1);

    /// <summary>The tangent of <paramref name="x"/> (rad), the same bits on every platform.</summary>
    public static double Tan(double x)
    {
        if (x == 0 || !double.IsFinite(x))
        {
            return x == 0 ? x : double.NaN;   // ±0 keeps its sign
        }
        int n = Reduce(x, out double hi, out double lo);
        double s = SinKernel(hi, lo);
        double c = CosKernel(hi, lo);
        return (n & 1) == 0 ? s / c : -c / s;
    }

    /// <summary>sin(x + <paramref name="quarterTurns"/>·π/2): the sine (0) or the cosine (1).</summary>
    private static double SineOfQuarterTurns(double x, int quarterTurns)
    {
        if (!double.IsFinite(x))
        {
            return double.NaN;
        }
        int n = Reduce(x, out double hi, out double lo) + quarterTurns;
        return (n & 3) switch
        {
            0 => SinKernel(hi, lo),
            1 => CosKernel(hi, lo),
            2 => -SinKernel(hi, lo),
            _ => -CosKernel(hi, lo),
        };
    }

    /// <summary>The arc tangent of <paramref name="x"/>, in [−π/2, π/2], the same bits on every platform.</summary>
    public static double Atan(double x)
    {
        if (double.IsNaN(x))
        {
            return x;
        }
        double a = Math.Abs(x);
        double r = a <= 1 ? AtanUnit(a) : PiOver2Hi - (AtanUnit(1 / a) - PiOver2Lo);
        return x < 0 || (x == 0 && double.IsNegative(x)) ? -r : r;
    }

    /// <summary>The angle of the point (<paramref name="x"/>, <paramref name="y"/>), in [−π, π], the same bits on every platform.</summary>
    public static double Atan2(double y, double x)
    {
        if (double.IsNaN(x) || double.IsNaN(y))
        {
            return double.NaN;
        }
        bool negativeY = double.IsNegative(y);
        bool negativeX = double.IsNegative(x);
        double ay = Math.Abs(y);
        double ax = Math.Abs(x);
        double r;
        if (ay == 0)
        {
            r = negativeX ? PiHi : 0;
        }
        else if (ax == 0)
        {
            r = PiOver2Hi;
        }
        else if (double.IsInfinity(ax) && double.IsInfinity(ay))
        {
            r = negativeX ? 3 * PiOver2Hi / 2 : PiOver2Hi / 2;
        }
        else if (double.IsInfinity(ax))
        {
            r = negativeX ? PiHi : 0;
        }
        else if (double.IsInfinity(ay))
        {
            r = PiOver2Hi;
        }
        else
        {
            // The angle of (ax, ay) in [0, π/2], then mirrored for x < 0: π − a with π's low part.
            double a = ay <= ax ? AtanUnit(ay / ax) : PiOver2Hi - (AtanUnit(ax / ay) - PiOver2Lo);
            r = negativeX ? PiHi - (a - PiLo) : a;
        }
        return negativeY ? -r : r;
    }

    /// <summary>The arc sine of <paramref name="x"/>, in [−π/2, π/2] (NaN outside [−1, 1]), the same bits on every platform.</summary>
    public static double Asin(double x) =>
        double.IsNaN(x) || Math.Abs(x) > 1 ? double.NaN : Atan2(x, Math.Sqrt((1 - x) * (1 + x)));

    /// <summary>The arc cosine of <paramref name="x"/>, in [0, π] (NaN outside [−1, 1]), the same bits on every platform.</summary>
    public static double Acos(double x) =>
        double.IsNaN(x) || Math.Abs(x) > 1 ? double.NaN : Atan2(Math.Sqrt((1 - x) * (1 + x)), x);

    /// <summary>e to the power <paramref name="x"/>, the same bits on every platform.</summary>
    public static double Exp(double x)
    {
        if (double.IsNaN(x))
        {
            return x;
        }
        if (x > ExpOverflow)
        {
            return double.PositiveInfinity;
        }
        if (x < ExpUnderflow)
        {
            return 0;
        }
        // x = k·ln 2 + r, |r| <= ln 2 / 2; e^r by its series to r^13 (the rest is below 2^-57).
        double k = Math.Round(x * InvLn2);
        double r = (x - k * Ln2Hi) - k * Ln2Lo;
        double p = Horner(r, ExpSeries);
        double e = 1 + (r + r * r * p);
        return ScaleByPowerOfTwo(e, (int)k);
    }

    /// <summary>The natural logarithm of <paramref name="x"/>, the same bits on every platform.</summary>
    public static double Log(double x)
    {
        if (double.IsNaN(x) || x < 0)
        {
            return double.NaN;
        }
        if (x == 0)
        {
            return double.NegativeInfinity;
        }
        if (double.IsPositiveInfinity(x))
        {
            return x;
        }
        // x = 2^k·m, m in [√2/2, √2); log m = log(1 + f) = f − (f²/2 − s·(f²/2 + R)), s = f/(2 + f),
        // R = 2s²/3 + 2s⁴/5 + ... (log(1 + f) = 2·atanh s).
        int k = 0;
        if (x < 2.2250738585072014e-308)
        {
            x *= 18014398509481984.0;   // 2^54: subnormal to normal, exactly
            k = -54;
        }
        long bits = BitConverter.DoubleToInt64Bits(x);
        k += (int)(bits >> 52) - 1023;
        double m = BitConverter.Int64BitsToDouble((bits & 0x000F_FFFF_FFFF_FFFFL) | 0x3FF0_0000_0000_0000L);
        if (m >= Sqrt2)
        {
            m *= 0.5;
            k++;
        }
        double f = m - 1;
        double s = f / (2 + f);
        double z = s * s;
        double q = Horner(z, LogSeries);
        double rest = z * q;
        double halfSquare = 0.5 * f * f;
        return k * Ln2Hi - ((halfSquare - (s * (halfSquare + rest) + k * Ln2Lo)) - f);
    }

    /// <summary>The base-10 logarithm of <paramref name="x"/>, the same bits on every platform.</summary>
    public static double Log10(double x) => Log(x) / Ln10;

    /// <summary>
    /// <paramref name="x"/> to the power <paramref name="y"/>, the same bits on every platform:
    /// exp(y·log x) (its error grows with |y·log x|), with C's special cases.
    /// </summary>
    public static double Pow(double x, double y)
    {
        if (y == 0 || x == 1)
        {
            return 1;
        }
        if (double.IsNaN(x) || double.IsNaN(y))
        {
            return double.NaN;
        }
        bool integer = Math.Floor(y) == y;
        bool odd = integer && Math.Abs(y) < 9007199254740992.0 && Math.Abs(y % 2) == 1;
        if (x == 0)
        {
            double magnitude = y > 0 ? 0 : double.PositiveInfinity;
            return odd && double.IsNegative(x) ? -magnitude : magnitude;
        }
        if (double.IsInfinity(y))
        {
            double ax = Math.Abs(x);
            return ax == 1 ? 1 : (ax > 1) == (y > 0) ? double.PositiveInfinity : 0;
        }
        if (double.IsInfinity(x))
        {
            double magnitude = y > 0 ? double.PositiveInfinity : 0;
            return odd && x < 0 ? -magnitude : magnitude;
        }
        if (x < 0)
        {
            if (!integer)
            {
                return double.NaN;
            }
            double magnitude = Exp(y * Log(-x));
            return odd ? -magnitude : magnitude;
        }
        return Exp(y * Log(x));
    }

    /// <summary>
    /// x = n·π/2 + (hi + lo), |hi + lo| ≤ π/4 (a little more at the rounding's edge); returns n.
    /// </summary>
    private static int Reduce(double x, out double hi, out double lo)
    {
        if (Math.Abs(x) <= Math.PI / 4)
        {
            hi = x;
            lo = 0;
            return 0;
        }
        if (Math.Abs(x) > ReductionLimit)
        {
            x -= TwoPi * Math.Round(x / TwoPi);
        }
        double n = Math.Round(x * TwoOverPi);
        double a = x - n * PiOver2Part1;              // exact
        double b = n * PiOver2Part2;                  // exact
        double t = a - b;
        double tail = (a - t) - b;                    // what t lost (|a| ≥ |b| here)
        double c = n * PiOver2Part3;
        hi = t - c;
        lo = ((t - hi) - c) + tail;
        return (int)(long)n;
    }

    /// <summary>sin(hi + lo) for |hi| ≤ π/4 (a little more), lo the tail of the reduced argument.</summary>
    private static double SinKernel(double hi, double lo)
    {
        // sin x = x + x³·S(x²), S's series to x^17 (the rest is below 2^-60 of x);
        // sin(hi + lo) ≈ sin hi + lo·cos hi, and cos hi ≈ 1 − hi²/2 is enough for lo's few bits.
        double z = hi * hi;
        double p = Horner(z, SinSeries);
        return hi + (hi * z * p + lo * (1 - 0.5 * z));
    }

    /// <summary>cos(hi + lo) for |hi| ≤ π/4 (a little more), lo the tail of the reduced argument.</summary>
    private static double CosKernel(double hi, double lo)
    {
        // cos x = 1 − x²/2 + x⁴·C(x²), C's series to x^18; cos(hi + lo) ≈ cos hi − lo·hi.
        double z = hi * hi;
        double q = Horner(z, CosSeries);
        double halfZ = 0.5 * z;
        double w = 1 - halfZ;
        // What 1 − z/2 rounded off, added back with the series and the tail's term.
        double roundedOff = (1 - w) - halfZ;
        return w + (roundedOff + (z * z * q - hi * lo));
    }

    /// <summary>atan(a) for a in [0, 1]: atan(k/8) + atan(t), t = (a − k/8)/(1 + a·k/8), |t| ≤ 1/16.</summary>
    private static double AtanUnit(double a)
    {
        int k = (int)Math.Round(a * 8);
        double c = k / 8.0;
        double t = (a - c) / (1 + a * c);
        double z = t * t;
        // atan t = t + t·z·P(z), P's series to t^15 (the rest is below 2^-64 of t).
        double p = Horner(z, AtanSeries);
        return AtanHi[k] + (t + (t * z * p + AtanLo[k]));
    }

    /// <summary>e·2^k for an e near 1, into the subnormal range when it must.</summary>
    private static double ScaleByPowerOfTwo(double e, int k)
    {
        if (k > 1023)
        {
            return e * 2.0 * BitConverter.Int64BitsToDouble((long)(k - 1 + 1023) << 52);
        }
        if (k >= -1022)
        {
            return e * BitConverter.Int64BitsToDouble((long)(k + 1023) << 52);
        }
        // Two steps: 2^(k + 54), normal, then 2^-54 (one rounding, into the subnormal result).
        return e * BitConverter.Int64BitsToDouble((long)(k + 54 + 1023) << 52) * (1.0 / 18014398509481984.0);
    }

    /// <summary>c[0]·z^(n−1) + ... + c[n−1] by Horner's rule, in this order on every platform.</summary>
    private static double Horner(double z, double[] coefficients)
    {
        double p = coefficients[0];
        for (int i = 1; i < coefficients.Length; i++)
        {
            p = coefficients[i] + z * p;
        }
        return p;
    }
}
