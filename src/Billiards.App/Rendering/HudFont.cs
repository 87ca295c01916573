using Billiards.Core.Scenes;
using SkiaSharp;

namespace Billiards.App.Rendering;

/// <summary>
/// The HUD's text: a monospaced TrueType font (DejaVu Sans Mono, assets/fonts, its licence beside
/// it) drawn antialiased by SkiaSharp into an atlas of 16 x 6 cells for the characters 32..127,
/// each <see cref="Advance"/> x <see cref="LineHeight"/> HUD units of <c>scale</c> pixels, so
/// that at the HUD's scale one atlas texel is one screen pixel.
/// </summary>
public static class HudFont
{
    /// <summary>Horizontal advance of a character (HUD units).</summary>
    public const int Advance = 6;

    /// <summary>Line height (HUD units).</summary>
    public const int LineHeight = 9;

    /// <summary>Cells of the atlas across and down.</summary>
    public const int Columns = 16, Rows = 6;

    /// <summary>The font file.</summary>
    public static string FontPath => Path.Combine(AssetFolder.Assets, "fonts", "DejaVuSansMono.ttf");

    /// <summary>
    /// The atlas at <paramref name="scale"/> pixels a HUD unit: <see cref="Columns"/> x
    /// <see cref="Rows"/> cells, one byte of ink coverage a pixel, rows from the top.
    /// </summary>
    public static byte[] Atlas(int scale)
    {
        int cellW = Advance * scale, cellH = LineHeight * scale;
        int width = Columns * cellW, height = Rows * cellH;
        using var font = new SKFont(FontFile.Open(FontPath), 100) { Edging = SKFontEdging.Antialias, Hinting = SKFontHinting.None };
        float advance = font.MeasureText("M");
        // The span of the tallest and deepest characters drawn: ascenders, descenders, brackets.
        const string Span = "Mbdfhkl|gjpqy()[]{}_";
        font.MeasureText(Span, out var span);
        // As large as the cell allows: the advance fills most of its width, that span its height.
        float size = 100 * MathF.Min(0.92f * cellW / advance, cellH / span.Height);
        font.Size = size;
        font.MeasureText(Span, out span);
        using var bitmap = new SKBitmap(new SKImageInfo(width, height, SKColorType.Alpha8, SKAlphaType.Premul));
        using (var canvas = new SKCanvas(bitmap))
        {
            canvas.Clear(SKColors.Transparent);
            using var paint = new SKPaint { Color = SKColors.Black, IsAntialias = true };
            float ink = font.MeasureText("M");
            for (int c = 33; c < 127; c++)
            {
                int cell = c - 32;
                float left = cell % Columns * cellW, top = cell / Columns * cellH;
                // The span centred in the cell; each glyph clipped to its cell, so no ink of one
                // character reaches a neighbour's in the atlas.
                float baseline = top + ((cellH - span.Height) / 2) - span.Top;
                canvas.Save();
                canvas.ClipRect(new SKRect(left, top, left + cellW, top + cellH));
                canvas.DrawText(((char)c).ToString(), left + ((cellW - ink) / 2), baseline, SKTextAlign.Left, font, paint);
                canvas.Restore();
            }
        }
        return bitmap.GetPixelSpan().ToArray();
    }
}
