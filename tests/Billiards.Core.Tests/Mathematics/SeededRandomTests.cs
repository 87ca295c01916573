using Billiards.Core.Mathematics;

// Not Billiards.Core.Tests.Mathematics: that namespace would hide Billiards.Core.Mathematics from
// tests that write Mathematics.Vec3.
namespace Billiards.Core.Tests.Mathematics;

/// <summary>SeededRandom draws exactly what System.Random with the same seed draws, and its state copies.</summary>
public class SeededRandomTests
{
    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(42)]
    [InlineData(-7)]
    [InlineData(int.MaxValue)]
    [InlineData(int.MinValue)]
    public void ItDrawsTheSequenceOfSystemRandomWithTheSameSeed(int seed)
    {
        var expected = new Random(seed);
        var actual = new SeededRandom(seed);
        for (int k = 0; k < 2000; k++)
        {
            switch (k % 5)
            {
                case 0: Assert.Equal(expected.NextSingle(), actual.NextSingle()); break;
                case 1: Assert.Equal(expected.NextDouble(), actual.NextDouble()); break;
                case 2: Assert.Equal(expected.Next(), actual.Next()); break;
                case 3: Assert.Equal(expected.Next(1000), actual.Next(1000)); break;
                default: Assert.Equal(expected.Next(-5, int.MaxValue), actual.Next(-5, int.MaxValue)); break;
            }
        }
    }

    [Fact]
    public void ACopyContinuesTheSequence()
    {
        var a = new SeededRandom(3);
        for (int k = 0; k < 100; k++)
        {
            a.Next();
        }
        var b = new SeededRandom(99);
        b.CopyFrom(a);
        for (int k = 0; k < 100; k++)
        {
            Assert.Equal(a.NextDouble(), b.NextDouble());
        }
    }
}
