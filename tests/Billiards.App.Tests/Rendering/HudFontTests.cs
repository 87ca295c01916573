using Billiards.App.Rendering;

namespace Billiards.App.Tests.Rendering;

public class HudFontTests
{
    private static int Ink(byte[] atlas, int scale, char c)
    {
        int cellW = HudFont.CellWidth * scale, cellH = HudFont.LineHeight * scale, width = HudFont.Columns * cellW;
        int cell = c - 32, left = cell % HudFont.Columns * cellW, top = cell / HudFont.Columns * cellH;
        int ink = 0;
        for (int y = top; y < top + cellH; y++)
        {
            for (int x = left; x < left + cellW; x++)
            {
                ink += atlas[(y * width) + x];
            }
        }
        return ink;
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void TheAtlasHasAntialiasedGlyphsInTheirCells(int scale)
    {
        byte[] atlas = HudFont.Atlas(scale);
        Assert.Equal(HudFont.Columns * HudFont.CellWidth * scale * HudFont.Rows * HudFont.LineHeight * scale, atlas.Length);
        Assert.Equal(0, Ink(atlas, scale, ' '));
        // Every printable character has ink, and a capital M more than a full stop.
        for (char c = '!'; c <= '~'; c++)
        {
            Assert.True(Ink(atlas, scale, c) > 0, $"'{c}' has no ink at scale {scale}");
        }
        Assert.True(Ink(atlas, scale, 'M') > 3 * Ink(atlas, scale, '.'));
        // Antialiased: edges take values between no ink and full ink.
        int partial = atlas.Count(b => b is > 20 and < 235);
        Assert.True(partial > atlas.Count(b => b >= 235) / 4, $"only {partial} partly covered pixels: not antialiased");
    }
}
