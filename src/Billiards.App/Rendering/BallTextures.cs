using System.Numerics;
using Billiards.Core.Balls;
using Billiards.Core.Scenes;
using SkiaSharp;

namespace Billiards.App.Rendering;

/// <summary>
/// Procedural ball textures: equirectangular RGBA images (u = longitude, v = latitude from the
/// south pole) of a ball set's balls, as each ball's look says (pool's here). Solids are coloured with a white number disc at +x and
/// -x of the ball's own frame, stripes are white with a coloured band round the equator, the 8
/// is black, a cue ball white with small red spots so that its spin shows. Numbers are drawn
/// with a TrueType font through SkiaSharp.
/// </summary>
public static class BallTextures
{
    /// <summary>Texture width (longitude).</summary>
    public const int Width = 1024;

    /// <summary>Texture height (latitude).</summary>
    public const int Height = 512;

    private static readonly float[] s_sides = [1f, -1f];

    private const float DiscAngle = 0.50f;     // rad: angular radius of the number disc
    private const float StripeHalfHeight = 0.55f; // |z| of the band's edges on the unit sphere
    private const float DigitHeight = 0.52f;   // gnomonic units (tan of the angle)

    /// <summary>The ball's base colour (sRGB, 0..1), as its ball set's look has it.</summary>
    public static Vector3 BaseColor(BallSet set, BallId id)
    {
        ArgumentNullException.ThrowIfNull(set);
        var look = set.Kind(id).Look;
        return new(look.Red, look.Green, look.Blue);
    }

    /// <summary>Direction on the unit sphere (ball frame) of texel centre (i, j).</summary>
    public static Vector3 Direction(float u, float v)
    {
        float lon = u * 2 * MathF.PI;
        float lat = (v - 0.5f) * MathF.PI;
        return new Vector3(MathF.Cos(lat) * MathF.Cos(lon), MathF.Cos(lat) * MathF.Sin(lon), MathF.Sin(lat));
    }

    /// <summary>The TrueType font of the numbers (DejaVu Sans Bold, assets/fonts, its licence beside it).</summary>
    public static string NumberFontPath => Path.Combine(AssetFolder.Assets, "fonts", "DejaVuSans-Bold.ttf");

    /// <summary>Side of the tangent-plane image a number is drawn into (px).</summary>
    private const int NumberImage = 256;

    /// <summary>
    /// The ball's texture, <see cref="Width"/> x <see cref="Height"/> sRGB RGBA, rows from v = 0.
    /// One sample a texel: the edges of the disc, the band and the spots are blended over the
    /// texel's angular size, the number's ink comes antialiased from the font.
    /// </summary>
    public static byte[] Generate(BallSet set, BallId id)
    {
        ArgumentNullException.ThrowIfNull(set);
        var kind = set.Kind(id);
        var pixels = new byte[Width * Height * 4];
        var white = new Vector3(0.97f, 0.96f, 0.92f);
        var ink = new Vector3(0.03f, 0.03f, 0.03f);
        var baseColor = BaseColor(set, id);
        float[] number = !kind.Look.Numbered ? [] : NumberCoverage(kind.Name);
        bool cueBall = set.IsCueBall(id);
        var cosLon = new float[Width];
        var sinLon = new float[Width];
        for (int i = 0; i < Width; i++)
        {
            float lon = (i + 0.5f) / Width * 2 * MathF.PI;
            cosLon[i] = MathF.Cos(lon);
            sinLon[i] = MathF.Sin(lon);
        }
        // A texel's angular size (rad): the width over which an edge is blended.
        const float Texel = MathF.PI / Height;
        for (int j = 0; j < Height; j++)
        {
            float lat = (((j + 0.5f) / Height) - 0.5f) * MathF.PI;
            float cosLat = MathF.Cos(lat), z = MathF.Sin(lat);
            for (int i = 0; i < Width; i++)
            {
                var d = new Vector3(cosLat * cosLon[i], cosLat * sinLon[i], z);
                var c = Shade(cueBall, kind.Look.Striped, d, baseColor, white, ink, number, Texel);
                int o = ((j * Width) + i) * 4;
                pixels[o] = (byte)Math.Clamp((c.X * 255) + 0.5f, 0, 255);
                pixels[o + 1] = (byte)Math.Clamp((c.Y * 255) + 0.5f, 0, 255);
                pixels[o + 2] = (byte)Math.Clamp((c.Z * 255) + 0.5f, 0, 255);
                pixels[o + 3] = 255;
            }
        }
        return pixels;
    }

    /// <summary>Part of a texel inside an edge at signed angular distance <paramref name="inside"/> (rad, positive inside).</summary>
    private static float Cover(float inside, float texel) => Math.Clamp((inside / texel) + 0.5f, 0, 1);

    private static Vector3 Shade(bool cueBall, bool striped, Vector3 d, Vector3 baseColor, Vector3 white, Vector3 ink, float[] number, float texel)
    {
        if (cueBall)
        {
            // Six small red spots on the axes show the cue ball's rotation.
            float nearest = MathF.Max(MathF.Max(MathF.Abs(d.X), MathF.Abs(d.Y)), MathF.Abs(d.Z));
            float spot = Cover(0.11f - MathF.Acos(MathF.Min(1, nearest)), texel);
            return Vector3.Lerp(baseColor, new Vector3(0.80f, 0.08f, 0.08f), spot);
        }
        var surface = baseColor;
        if (striped)
        {
            // The band's edge as an angle: latitude asin(StripeHalfHeight).
            float band = Cover(MathF.Asin(StripeHalfHeight) - MathF.Abs(MathF.Asin(d.Z)), texel);
            surface = Vector3.Lerp(white, baseColor, band);
        }
        if (number.Length == 0)
        {
            // A ball without a number (snooker's) is its colour all over.
            return surface;
        }
        // Number discs at +x and -x; read upright with z up.
        foreach (float side in s_sides)
        {
            float cos = d.X * side;
            if (cos < MathF.Cos(DiscAngle + texel))
            {
                continue;
            }
            float disc = Cover(DiscAngle - MathF.Acos(MathF.Min(1, cos)), texel);
            // Gnomonic coordinates on the disc's tangent plane: right and up as seen from outside.
            float right = d.Y * side / cos;
            float up = d.Z / cos;
            var face = Vector3.Lerp(white, ink, Sample(number, right, up));
            return Vector3.Lerp(surface, face, disc);
        }
        return surface;
    }

    /// <summary>
    /// The number drawn with the TrueType font into a square image of the disc's tangent plane
    /// (gnomonic coordinates -tan(disc) .. tan(disc) both ways, up is up), as ink coverage 0..1,
    /// its digits <see cref="DigitHeight"/> tall and centred.
    /// </summary>
    public static float[] NumberCoverage(string label)
    {
        float extent = MathF.Tan(DiscAngle);
        float pixelsPerUnit = NumberImage / (2 * extent);
        using var font = new SKFont(FontFile.Open(NumberFontPath), 100) { Edging = SKFontEdging.Antialias, Subpixel = true };
        font.MeasureText("0", out var zero);
        // Scale the font so that a digit's height is DigitHeight on the tangent plane.
        font.Size = 100 * DigitHeight * pixelsPerUnit / zero.Height;
        font.MeasureText(label, out var bounds);
        using var bitmap = new SKBitmap(new SKImageInfo(NumberImage, NumberImage, SKColorType.Alpha8, SKAlphaType.Premul));
        using (var canvas = new SKCanvas(bitmap))
        {
            canvas.Clear(SKColors.Transparent);
            using var paint = new SKPaint { Color = SKColors.Black, IsAntialias = true };
            float x = (NumberImage / 2f) - bounds.MidX;
            float y = (NumberImage / 2f) - bounds.MidY;
            canvas.DrawText(label, x, y, SKTextAlign.Left, font, paint);
        }
        var coverage = new float[NumberImage * NumberImage];
        var bytes = bitmap.GetPixelSpan();
        for (int k = 0; k < coverage.Length; k++)
        {
            coverage[k] = bytes[k] / 255f;
        }
        return coverage;
    }

    /// <summary>Bilinear ink coverage at gnomonic (right, up) from <see cref="NumberCoverage"/>; 0 outside.</summary>
    private static float Sample(float[] number, float right, float up)
    {
        float extent = MathF.Tan(DiscAngle);
        float x = ((right + extent) / (2 * extent) * NumberImage) - 0.5f;
        float y = ((extent - up) / (2 * extent) * NumberImage) - 0.5f;
        int x0 = (int)MathF.Floor(x), y0 = (int)MathF.Floor(y);
        float fx = x - x0, fy = y - y0;
        float At(int px, int py) => px < 0 || py < 0 || px >= NumberImage || py >= NumberImage ? 0 : number[(py * NumberImage) + px];
        float top = At(x0, y0) + (fx * (At(x0 + 1, y0) - At(x0, y0)));
        float bottom = At(x0, y0 + 1) + (fx * (At(x0 + 1, y0 + 1) - At(x0, y0 + 1)));
        return top + (fy * (bottom - top));
    }
}
