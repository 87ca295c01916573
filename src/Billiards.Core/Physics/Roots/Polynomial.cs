using System.Runtime.CompilerServices;

namespace Billiards.Core.Physics.Roots;

/// <summary>
/// Real roots of polynomials of degree at most 4 on a finite interval, for exact contact times.
/// Coefficients are ascending: <c>c[0] + c[1] t + c[2] t^2 + ...</c>.
/// </summary>
/// <remarks>
/// Method: recursive isolation by critical points (Yuksel, "High-Performance Polynomial Root
/// Finding for Graphics", HPG 2022). The roots of the derivative split the interval into pieces
/// on which the polynomial is monotone; each piece holds at most one root, which a safeguarded
/// Newton iteration (bisection when Newton leaves the bracket) finds to round-off. Unlike a
/// closed-form quartic this never loses a root to cancellation, and a leading coefficient that is
/// negligible on the interval simply lowers the degree (a quartic becomes a cubic, quadratic,
/// linear or constant), which is how degenerate cases (equal accelerations, a shot parallel to a
/// rail) are handled without special code.
/// </remarks>
public static class Polynomial
{
    /// <summary>Highest degree handled.</summary>
    public const int MaxDegree = 4;

    // A term whose largest magnitude on the interval is below this fraction of the largest term
    // changes no value beyond round-off, so it is dropped.
    private const double NegligibleTerm = 1e-15;

    /// <summary>Value of the polynomial at <paramref name="t"/> (Horner).</summary>
    public static double Evaluate(ReadOnlySpan<double> c, double t)
    {
        double r = 0;
        for (int k = c.Length - 1; k >= 0; k--)
        {
            r = r * t + c[k];
        }
        return r;
    }

    /// <summary>
    /// The degree that matters on [0, <paramref name="tMax"/>]: leading terms whose largest
    /// magnitude on the interval is negligible next to the largest term are ignored.
    /// </summary>
    public static int EffectiveDegree(ReadOnlySpan<double> c, double tMax)
    {
        var p = Load(c);
        return EffectiveDegree(ref p, c.Length - 1, tMax);
    }

    /// <summary>
    /// All real roots in [<paramref name="lo"/>, <paramref name="hi"/>] at which the polynomial
    /// changes sign (or is exactly zero at a piece boundary), ascending. Returns their number.
    /// Double roots that touch zero without crossing are not reported.
    /// </summary>
    /// <param name="c">Ascending coefficients; its length minus one is the degree used.</param>
    /// <param name="lo">Start of the interval.</param>
    /// <param name="hi">End of the interval.</param>
    /// <param name="roots">Receives the roots; needs room for the degree's count.</param>
    public static int RealRoots(ReadOnlySpan<double> c, double lo, double hi, Span<double> roots)
    {
        var p = Load(c);
        Coefficients found = default;
        int count = RealRoots(ref p, c.Length - 1, lo, hi, ref found);
        ((ReadOnlySpan<double>)found)[..count].CopyTo(roots);
        return count;
    }

    /// <summary>
    /// The first time in [0, <paramref name="tMax"/>] at which the polynomial enters the region
    /// p &lt;= 0 while decreasing: the contact time when p is a gap function (distance squared
    /// minus contact distance squared, or signed distance minus R). Returns +infinity if there is
    /// none.
    /// </summary>
    /// <remarks>
    /// A gap that is (within round-off) zero at the start and increasing is a pair touching but
    /// separating: no contact. A gap already at or below zero where it starts to decrease (at 0,
    /// or at a local maximum that never became positive) is a contact at that instant; that keeps
    /// frozen balls from passing through each other. A gap below -<paramref name="overlapTolerance"/>
    /// is not a new contact (the ball is already behind that feature).
    /// </remarks>
    /// <param name="c">Ascending coefficients, degree at most 4.</param>
    /// <param name="tMax">End of the interval (s).</param>
    /// <param name="overlapTolerance">How far below zero a gap may start and still count as a contact.</param>
    public static double FirstEntry(ReadOnlySpan<double> c, double tMax, double overlapTolerance)
    {
        var p = Load(c);
        return FirstEntry(ref p, c.Length - 1, tMax, overlapTolerance);
    }

    /// <summary>
    /// <see cref="FirstEntry(ReadOnlySpan{double}, double, double)"/> of the polynomial of degree
    /// <paramref name="n"/> (at most 4) held in <paramref name="p"/> (unchanged), with no span
    /// or stack buffer: the event engine's hot path.
    /// </summary>
    internal static double FirstEntry(ref Coefficients p, int n, double tMax, double overlapTolerance)
    {
        if (!(tMax > 0))
        {
            tMax = 0;
        }
        int degree = EffectiveDegree(ref p, n, tMax);
        if (degree == 0)
        {
            return double.PositiveInfinity;
        }

        Coefficients derivative = default;
        for (int k = 1; k <= degree; k++)
        {
            derivative[k - 1] = k * p[k];
        }
        Coefficients critical = default;
        int nc = RealRoots(ref derivative, degree - 1, 0, tMax, ref critical);

        double a = 0;
        double fa = Evaluate(ref p, degree, 0);
        for (int piece = 0; piece <= nc; piece++)
        {
            double b = piece < nc ? critical[piece] : tMax;
            if (b <= a && piece < nc)
            {
                continue;
            }
            double fb = Evaluate(ref p, degree, b);
            // Monotone piece: decreasing when its end is lower; at the very start of a piece the
            // derivative decides (a piece of zero length has fb == fa).
            bool decreasing = fb < fa || (fb == fa && Evaluate(ref derivative, degree - 1, a) < 0);
            if (decreasing)
            {
                if (fa <= 0)
                {
                    if (fa >= -overlapTolerance)
                    {
                        return a;
                    }
                }
                else if (fb < 0)
                {
                    return Bracketed(ref p, degree, a, b, fa);
                }
                else if (fb == 0 && piece == nc)
                {
                    // Zero exactly at the end of the interval; at an interior critical point a
                    // zero would be a tangent graze, which is no contact.
                    return b;
                }
            }
            a = b;
            fa = fb;
        }
        return double.PositiveInfinity;
    }

    private static Coefficients Load(ReadOnlySpan<double> c)
    {
        if (c.Length is 0 or > MaxDegree + 1)
        {
            throw new ArgumentException($"expected 1 to {MaxDegree + 1} coefficients, got {c.Length}", nameof(c));
        }
        Coefficients p = default;
        c.CopyTo(p);
        return p;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int EffectiveDegree(ref Coefficients c, int n, double tMax)
    {
        double scale = 0;
        double power = 1;
        Coefficients magnitude = default;
        for (int k = 0; k <= n; k++)
        {
            magnitude[k] = Math.Abs(c[k]) * power;
            scale = Math.Max(scale, magnitude[k]);
            power *= tMax;
        }
        int degree = n;
        while (degree > 0 && magnitude[degree] <= NegligibleTerm * scale)
        {
            degree--;
        }
        return degree;
    }

    // Horner over c[0..degree]; the first step (0 t + c[degree]) is kept so that every caller
    // rounds exactly as the span version does.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Evaluate(ref Coefficients c, int degree, double t)
    {
        double r = 0;
        for (int k = degree; k >= 0; k--)
        {
            r = r * t + c[k];
        }
        return r;
    }

    private static int RealRoots(ref Coefficients c, int n, double lo, double hi, ref Coefficients roots)
    {
        int degree = n;
        while (degree > 0 && c[degree] == 0)
        {
            degree--;
        }
        if (degree <= 0)
        {
            return 0;
        }
        if (degree == 1)
        {
            double t = -c[0] / c[1];
            if (t >= lo && t <= hi)
            {
                roots[0] = t;
                return 1;
            }
            return 0;
        }
        if (degree == 2)
        {
            return QuadraticRoots(c[0], c[1], c[2], lo, hi, ref roots);
        }

        Coefficients derivative = default;
        for (int k = 1; k <= degree; k++)
        {
            derivative[k - 1] = k * c[k];
        }
        Coefficients critical = default;
        int nc = RealRoots(ref derivative, degree - 1, lo, hi, ref critical);

        int count = 0;
        double a = lo;
        double fa = Evaluate(ref c, degree, a);
        for (int piece = 0; piece <= nc; piece++)
        {
            double b = piece < nc ? critical[piece] : hi;
            double fb = Evaluate(ref c, degree, b);
            if (fa == 0 && (count == 0 || roots[count - 1] != a))
            {
                roots[count++] = a;
            }
            else if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0))
            {
                roots[count++] = Bracketed(ref c, degree, a, b, fa);
            }
            a = b;
            fa = fb;
        }
        if (fa == 0 && (count == 0 || roots[count - 1] != a))
        {
            roots[count++] = a;
        }
        return count;
    }

    private static int QuadraticRoots(double c0, double c1, double c2, double lo, double hi, ref Coefficients roots)
    {
        double disc = c1 * c1 - 4 * c2 * c0;
        if (disc < 0)
        {
            return 0;
        }
        // Stable form: no cancellation between -c1 and the square root.
        double q = -0.5 * (c1 + Math.CopySign(Math.Sqrt(disc), c1));
        double r1 = q / c2;
        double r2 = q != 0 ? c0 / q : r1;
        if (r1 > r2)
        {
            (r1, r2) = (r2, r1);
        }
        int count = 0;
        if (r1 >= lo && r1 <= hi)
        {
            roots[count++] = r1;
        }
        if (r2 >= lo && r2 <= hi && (count == 0 || r2 != r1))
        {
            roots[count++] = r2;
        }
        return count;
    }

    // The root in [a, b] of a polynomial of the given degree (1 to 4) monotone there with a sign
    // change; fa = p(a). Newton, safeguarded by bisection; Horner unrolled per degree in the same
    // order of operations as a loop would take.
    private static double Bracketed(ref Coefficients p, int degree, double a, double b, double fa)
    {
        double p0 = p[0], p1 = p[1], p2 = p[2], p3 = p[3], p4 = p[4];
        double x = 0.5 * (a + b);
        for (int iteration = 0; iteration < 100; iteration++)
        {
            double f, df = 0;
            switch (degree)
            {
                case 4:
                    f = p4;
                    df = df * x + f; f = f * x + p3;
                    df = df * x + f; f = f * x + p2;
                    df = df * x + f; f = f * x + p1;
                    df = df * x + f; f = f * x + p0;
                    break;
                case 3:
                    f = p3;
                    df = df * x + f; f = f * x + p2;
                    df = df * x + f; f = f * x + p1;
                    df = df * x + f; f = f * x + p0;
                    break;
                case 2:
                    f = p2;
                    df = df * x + f; f = f * x + p1;
                    df = df * x + f; f = f * x + p0;
                    break;
                default:
                    f = p1;
                    df = df * x + f; f = f * x + p0;
                    break;
            }
            if (f == 0)
            {
                return x;
            }
            if ((f < 0) == (fa < 0))
            {
                a = x;
                fa = f;
            }
            else
            {
                b = x;
            }
            double next = df != 0 ? x - f / df : double.NaN;
            if (!(next > a && next < b))
            {
                next = 0.5 * (a + b);
            }
            double tolerance = 1e-15 * Math.Max(1.0, Math.Abs(next));
            if (Math.Abs(next - x) <= tolerance || b - a <= tolerance)
            {
                return next;
            }
            x = next;
        }
        return x;
    }
}

/// <summary>The ascending coefficients of a polynomial of degree at most <see cref="Polynomial.MaxDegree"/>, held inline.</summary>
[InlineArray(Polynomial.MaxDegree + 1)]
internal struct Coefficients
{
    private double _element;
}
