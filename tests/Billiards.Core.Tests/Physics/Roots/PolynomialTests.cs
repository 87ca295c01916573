using Billiards.Core.Physics.Roots;

namespace Billiards.Core.Tests.Physics.Roots;

/// <summary>The first entry into contact of a polynomial gap, in its degenerate and touching cases.</summary>
public class PolynomialTests
{
    [Fact]
    public void RootsHandleDegenerateAndTouchingCases()
    {
        // Quartic with a negligible leading term behaves as the quadratic (t - 1)(t - 2) = t^2 - 3t + 2.
        Assert.Equal(1.0, Polynomial.FirstEntry([2, -3, 1, 0, 1e-30], 10, 0), 12);
        // Linear gap 1 - t enters at 1.
        Assert.Equal(1.0, Polynomial.FirstEntry([1, -1, 0], 10, 0), 12);
        // Constant: never.
        Assert.Equal(double.PositiveInfinity, Polynomial.FirstEntry([1, 0, 0, 0, 0], 10, 0));
        // Touching and separating (gap 0, increasing): no contact.
        Assert.Equal(double.PositiveInfinity, Polynomial.FirstEntry([0, 1, 0.5], 10, 1e-9));
        // Touching and approaching: contact now.
        Assert.Equal(0.0, Polynomial.FirstEntry([0, -1, 0.5], 10, 1e-9));
        // Separates then comes back (gap t(t - 1)(t - 3) ... as t^3 - 4 t^2 + 3 t): re-enters at 3? It is
        // negative on (1, 3), so it enters at 1.
        Assert.Equal(1.0, Polynomial.FirstEntry([0, 3, -4, 1], 10, 1e-9), 12);
        // A quartic with four roots 0.5, 1.5, 2.5, 3.5: (t-.5)(t-1.5)(t-2.5)(t-3.5) enters at 0.5.
        double[] c = [0.5 * 1.5 * 2.5 * 3.5, -(1.5 * 2.5 * 3.5 + 0.5 * 2.5 * 3.5 + 0.5 * 1.5 * 3.5 + 0.5 * 1.5 * 2.5),
            0.5 * 1.5 + 0.5 * 2.5 + 0.5 * 3.5 + 1.5 * 2.5 + 1.5 * 3.5 + 2.5 * 3.5, -(0.5 + 1.5 + 2.5 + 3.5), 1];
        Assert.Equal(0.5, Polynomial.FirstEntry(c, 10, 0), 12);
        Span<double> roots = stackalloc double[4];
        Assert.Equal(4, Polynomial.RealRoots(c, 0, 10, roots));
        Assert.Equal(3.5, roots[3], 12);
        // Tangent graze (gap (t - 1)^2 >= 0) is no entry.
        Assert.Equal(double.PositiveInfinity, Polynomial.FirstEntry([1, -2, 1], 10, 0));
    }
}
