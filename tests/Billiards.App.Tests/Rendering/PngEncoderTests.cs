using Billiards.App.Rendering;

namespace Billiards.App.Tests.Rendering;

public class PngEncoderTests
{
    [Fact]
    public void Crc32MatchesTheKnownCheckValue()
    {
        // The standard check value of CRC-32 for "123456789".
        Assert.Equal(0xCBF43926u, PngEncoder.Crc32("123456789"u8));
    }

    [Theory]
    [InlineData(1, 1)]
    [InlineData(7, 3)]
    [InlineData(64, 48)]
    public void EncodeRoundTripsEveryPixel(int width, int height)
    {
        var random = new Random(width * 1000 + height);
        var pixels = new byte[width * height * 4];
        random.NextBytes(pixels);
        var (w, h, decoded) = PngDecoder.Decode(PngEncoder.Encode(pixels, width, height));
        Assert.Equal(width, w);
        Assert.Equal(height, h);
        Assert.Equal(pixels, decoded);
    }

    [Fact]
    public void EncodeRejectsAWrongPixelCount()
    {
        Assert.Throws<ArgumentException>(() => PngEncoder.Encode(new byte[15], 2, 2));
    }
}
