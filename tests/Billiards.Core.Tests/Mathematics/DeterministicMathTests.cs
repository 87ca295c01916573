using Billiards.Core.Mathematics;

namespace Billiards.Core.Tests.Mathematics;

/// <summary>
/// <see cref="DeterministicMath"/> against the platform's functions (glibc on Linux, whose results
/// are within half an ulp of the true value in practice): seeded arguments over the ranges Core
/// uses and beyond, with the ulp bounds DeterministicMath's remarks state, and C's special values.
/// </summary>
public class DeterministicMathTests
{
    private const int Samples = 20000;

    private static long Ulps(double a, double b)
    {
        if (a == b || (double.IsNaN(a) && double.IsNaN(b)))
        {
            return 0;
        }
        static long Ordered(double x)
        {
            long bits = BitConverter.DoubleToInt64Bits(x);
            return bits < 0 ? long.MinValue - bits : bits;
        }
        return Math.Abs(Ordered(a) - Ordered(b));
    }

    private static void Within(Func<double, double> ours, Func<double, double> platform, double from, double to, long ulps, int seed)
    {
        var random = new Random(seed);
        long worst = 0;
        double worstAt = 0;
        for (int i = 0; i < Samples; i++)
        {
            double x = from + (to - from) * random.NextDouble();
            long d = Ulps(ours(x), platform(x));
            if (d > worst)
            {
                worst = d;
                worstAt = x;
            }
        }
        Assert.True(worst <= ulps, $"{worst} ulp at x = {worstAt:R} (ours {ours(worstAt):R}, platform {platform(worstAt):R})");
    }

    [Theory]
    [InlineData(-0.8, 0.8)]
    [InlineData(-10, 10)]
    [InlineData(-1000, 1000)]
    [InlineData(1e5, 8e5)]
    public void SineAndCosineAreWithinOneUlp(double from, double to)
    {
        Within(DeterministicMath.Sin, Math.Sin, from, to, 1, 1);
        Within(DeterministicMath.Cos, Math.Cos, from, to, 1, 2);
    }

    [Theory]
    [InlineData(-1.5, 1.5)]
    [InlineData(-100, 100)]
    public void TangentIsWithinTwoUlp(double from, double to) => Within(DeterministicMath.Tan, Math.Tan, from, to, 2, 3);

    [Theory]
    [InlineData(-1, 1)]
    [InlineData(-50, 50)]
    [InlineData(1e3, 1e9)]
    public void ArcTangentIsWithinOneUlp(double from, double to) => Within(DeterministicMath.Atan, Math.Atan, from, to, 1, 4);

    [Fact]
    public void ArcTangentOfTwoArgumentsIsWithinTwoUlpInEveryQuadrant()
    {
        var random = new Random(5);
        for (int i = 0; i < Samples; i++)
        {
            double y = (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-3, 4));
            double x = (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-3, 4));
            Assert.True(Ulps(DeterministicMath.Atan2(y, x), Math.Atan2(y, x)) <= 2, $"atan2({y:R}, {x:R})");
        }
    }

    [Fact]
    public void ArcSineAndArcCosineAreWithinTwoUlp()
    {
        Within(DeterministicMath.Asin, Math.Asin, -1, 1, 2, 6);
        Within(DeterministicMath.Acos, Math.Acos, -1, 1, 2, 7);
    }

    [Theory]
    [InlineData(-1, 1)]
    [InlineData(-700, 700)]
    [InlineData(-745, -708)]
    public void ExponentialIsWithinOneUlp(double from, double to) => Within(DeterministicMath.Exp, Math.Exp, from, to, 1, 8);

    [Theory]
    [InlineData(0.5, 2)]
    [InlineData(1e-300, 1e300)]
    [InlineData(0, 1e-310)]
    public void LogarithmIsWithinOneUlp(double from, double to)
    {
        Within(DeterministicMath.Log, Math.Log, from, to, 1, 9);
        Within(DeterministicMath.Log10, Math.Log10, from, to, 3, 10);
    }

    [Fact]
    public void PowerIsWithinFourUlpForCoresExponents()
    {
        var random = new Random(11);
        for (int i = 0; i < Samples; i++)
        {
            // |y·log x| <= 1, as Core's exponents (Pow's remarks: the error grows with it).
            double x = 0.01 + random.NextDouble() * 10;
            double y = (random.NextDouble() - 0.5) * 2 / Math.Max(1, Math.Abs(Math.Log(x)));
            Assert.True(Ulps(DeterministicMath.Pow(x, y), Math.Pow(x, y)) <= 4, $"pow({x:R}, {y:R})");
        }
    }

    [Fact]
    public void SpecialValuesFollowC()
    {
        double nan = double.NaN, inf = double.PositiveInfinity;
        foreach (var f in new Func<double, double>[] { DeterministicMath.Sin, DeterministicMath.Cos, DeterministicMath.Tan })
        {
            Assert.True(double.IsNaN(f(nan)) && double.IsNaN(f(inf)) && double.IsNaN(f(-inf)));
        }
        Assert.True(double.IsNegative(DeterministicMath.Sin(-0.0)) && DeterministicMath.Sin(-0.0) == 0);
        Assert.Equal(1, DeterministicMath.Cos(0));
        Assert.Equal(Math.PI / 2, DeterministicMath.Atan(inf));
        Assert.Equal(-Math.PI / 2, DeterministicMath.Atan(-inf));
        Assert.Equal(Math.PI, DeterministicMath.Atan2(0.0, -0.0));
        Assert.Equal(-Math.PI, DeterministicMath.Atan2(-0.0, -1));
        Assert.True(double.IsNegative(DeterministicMath.Atan2(-0.0, 1)));
        Assert.Equal(Math.PI / 2, DeterministicMath.Atan2(1, 0));
        Assert.Equal(Math.Atan2(inf, -inf), DeterministicMath.Atan2(inf, -inf));
        Assert.Equal(Math.Atan2(-inf, inf), DeterministicMath.Atan2(-inf, inf));
        Assert.True(double.IsNaN(DeterministicMath.Asin(1.5)) && double.IsNaN(DeterministicMath.Acos(-1.5)));
        Assert.Equal(Math.PI, DeterministicMath.Acos(-1));
        Assert.Equal(0, DeterministicMath.Acos(1));
        Assert.Equal(1, DeterministicMath.Exp(0));
        Assert.Equal(inf, DeterministicMath.Exp(710));
        Assert.Equal(0, DeterministicMath.Exp(-746));
        Assert.Equal(0, DeterministicMath.Exp(-inf));
        Assert.Equal(0, DeterministicMath.Log(1));
        Assert.Equal(-inf, DeterministicMath.Log(0));
        Assert.True(double.IsNaN(DeterministicMath.Log(-1)));
        Assert.Equal(inf, DeterministicMath.Log(inf));
        Assert.Equal(1, DeterministicMath.Pow(nan, 0));
        Assert.Equal(1, DeterministicMath.Pow(1, nan));
        Assert.Equal(-8, DeterministicMath.Pow(-2, 3), 12);
        Assert.True(double.IsNaN(DeterministicMath.Pow(-2, 0.5)));
        Assert.Equal(-inf, DeterministicMath.Pow(-0.0, -3));
        Assert.Equal(0, DeterministicMath.Pow(0.5, inf));
    }
}
