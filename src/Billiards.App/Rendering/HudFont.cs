using Billiards.Core.Scenes;
using SkiaSharp;

namespace Billiards.App.Rendering;

/// <summary>
/// The HUD's text: a proportional TrueType font (DejaVu Sans, assets/fonts, its licence beside
/// it) drawn antialiased by SkiaSharp into an atlas of 16 x 6 cells for the characters 32..127,
/// each <see cref="CellWidth"/> x <see cref="LineHeight"/> HUD units of <c>scale</c> pixels, so
/// that at the HUD's scale one atlas texel is one screen pixel. Each character advances by its own
/// width (<see cref="Width(string)"/>); the font's digits share one width, so columns of numbers
/// (scores, degrees, speeds) stay aligned as a monospace would keep them.
/// </summary>
public static class HudFont
{
    /// <summary>Width of an atlas cell (HUD units): the widest glyph with its bearings.</summary>
    public const int CellWidth = 10;

    /// <summary>Line height (HUD units).</summary>
    public const int LineHeight = 9;

    /// <summary>Where a glyph's origin lies in its cell (HUD units from the cell's left): room for a negative left bearing ('j').</summary>
    public const float Origin = 1;

    /// <summary>Cells of the atlas across and down.</summary>
    public const int Columns = 16, Rows = 6;

    /// <summary>The font file.</summary>
    public static string FontPath => Path.Combine(AssetFolder.Assets, "fonts", "DejaVuSans.ttf");

    // The span of the tallest and deepest characters drawn: ascenders, descenders, brackets.
    private const string Span = "Mbdfhkl|gjpqy()[]{}_";

    private static readonly Lazy<float[]> Advances = new(() =>
    {
        using var font = SizedFont(1);
        var widths = new float[128];
        for (int c = 32; c < 127; c++)
        {
            widths[c] = font.MeasureText(((char)c).ToString());
        }
        return widths;
    });

    /// <summary>The advance of a character (HUD units); characters outside 32..126 draw as '?'.</summary>
    public static float AdvanceOf(char c) => Advances.Value[c is >= ' ' and <= '~' ? c : '?'];

    /// <summary>The width of a line of text (HUD units).</summary>
    public static float Width(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        float w = 0;
        foreach (char c in text)
        {
            w += AdvanceOf(c);
        }
        return w;
    }

    // The font at the size whose span fills a line of LineHeight * scale pixels.
    private static SKFont SizedFont(int scale)
    {
        var font = new SKFont(FontFile.Open(FontPath), 100) { Edging = SKFontEdging.Antialias, Hinting = SKFontHinting.None, Subpixel = true };
        font.MeasureText(Span, out var span);
        font.Size = 100 * LineHeight * scale / span.Height;
        return font;
    }

    /// <summary>
    /// The atlas at <paramref name="scale"/> pixels a HUD unit: <see cref="Columns"/> x
    /// <see cref="Rows"/> cells, one byte of ink coverage a pixel, rows from the top.
    /// </summary>
    public static byte[] Atlas(int scale)
    {
        int cellW = CellWidth * scale, cellH = LineHeight * scale;
        int width = Columns * cellW, height = Rows * cellH;
        using var font = SizedFont(scale);
        font.MeasureText(Span, out var span);
        using var bitmap = new SKBitmap(new SKImageInfo(width, height, SKColorType.Alpha8, SKAlphaType.Premul));
        using (var canvas = new SKCanvas(bitmap))
        {
            canvas.Clear(SKColors.Transparent);
            using var paint = new SKPaint { Color = SKColors.Black, IsAntialias = true };
            for (int c = 33; c < 127; c++)
            {
                int cell = c - 32;
                float left = cell % Columns * cellW, top = cell / Columns * cellH;
                // The span centred in the cell; each glyph clipped to its cell, so no ink of one
                // character reaches a neighbour's in the atlas.
                float baseline = top + ((cellH - span.Height) / 2) - span.Top;
                canvas.Save();
                canvas.ClipRect(new SKRect(left, top, left + cellW, top + cellH));
                canvas.DrawText(((char)c).ToString(), left + (Origin * scale), baseline, SKTextAlign.Left, font, paint);
                canvas.Restore();
            }
        }
        return bitmap.GetPixelSpan().ToArray();
    }
}
