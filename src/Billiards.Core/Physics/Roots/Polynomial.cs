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
        double scale = 0;
        double power = 1;
        Span<double> magnitude = stackalloc double[MaxDegree + 1];
        for (int k = 0; k < c.Length; k++)
        {
            magnitude[k] = Math.Abs(c[k]) * power;
            scale = Math.Max(scale, magnitude[k]);
            power *= tMax;
        }
        int degree = c.Length - 1;
        while (degree > 0 && magnitude[degree] <= NegligibleTerm * scale)
        {
            degree--;
        }
        return degree;
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
        int degree = c.Length - 1;
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
            return QuadraticRoots(c[0], c[1], c[2], lo, hi, roots);
        }

        Span<double> derivative = stackalloc double[degree];
        for (int k = 1; k <= degree; k++)
        {
            derivative[k - 1] = k * c[k];
        }
        Span<double> critical = stackalloc double[MaxDegree];
        int nc = RealRoots(derivative, lo, hi, critical);

        int count = 0;
        double a = lo;
        double fa = Evaluate(c[..(degree + 1)], a);
        for (int piece = 0; piece <= nc; piece++)
        {
            double b = piece < nc ? critical[piece] : hi;
            double fb = Evaluate(c[..(degree + 1)], b);
            if (fa == 0 && (count == 0 || roots[count - 1] != a))
            {
                roots[count++] = a;
            }
            else if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0))
            {
                roots[count++] = Bracketed(c[..(degree + 1)], a, b, fa);
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
        if (!(tMax > 0))
        {
            tMax = 0;
        }
        int degree = EffectiveDegree(c, tMax);
        if (degree == 0)
        {
            return double.PositiveInfinity;
        }
        var p = c[..(degree + 1)];

        Span<double> derivative = stackalloc double[MaxDegree];
        for (int k = 1; k <= degree; k++)
        {
            derivative[k - 1] = k * p[k];
        }
        Span<double> critical = stackalloc double[MaxDegree];
        int nc = RealRoots(derivative[..degree], 0, tMax, critical);

        double a = 0;
        double fa = Evaluate(p, 0);
        for (int piece = 0; piece <= nc; piece++)
        {
            double b = piece < nc ? critical[piece] : tMax;
            if (b <= a && piece < nc)
            {
                continue;
            }
            double fb = Evaluate(p, b);
            // Monotone piece: decreasing when its end is lower; at the very start of a piece the
            // derivative decides (a piece of zero length has fb == fa).
            bool decreasing = fb < fa || (fb == fa && Evaluate(derivative[..degree], a) < 0);
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
                    return Bracketed(p, a, b, fa);
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

    private static int QuadraticRoots(double c0, double c1, double c2, double lo, double hi, Span<double> roots)
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

    // The root in [a, b] of a polynomial monotone there with a sign change; fa = p(a).
    private static double Bracketed(ReadOnlySpan<double> p, double a, double b, double fa)
    {
        double x = 0.5 * (a + b);
        for (int iteration = 0; iteration < 100; iteration++)
        {
            double f = p[^1];
            double df = 0;
            for (int k = p.Length - 2; k >= 0; k--)
            {
                df = df * x + f;
                f = f * x + p[k];
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
