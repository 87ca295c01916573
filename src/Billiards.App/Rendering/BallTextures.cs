using System.Numerics;
using Billiards.Core.Balls;

namespace Billiards.App.Rendering;

/// <summary>
/// Procedural ball textures: equirectangular RGBA images (u = longitude, v = latitude from the
/// south pole) of the standard pool set. Solids are coloured with a white number disc at +x and
/// -x of the ball's own frame, stripes are white with a coloured band round the equator, the 8
/// is black, the cue ball white with small red spots so that its spin shows.
/// </summary>
public static class BallTextures
{
    /// <summary>Texture width (longitude).</summary>
    public const int Width = 512;

    /// <summary>Texture height (latitude).</summary>
    public const int Height = 256;

    private static readonly float[] s_sides = [1f, -1f];

    private const float DiscAngle = 0.50f;     // rad: angular radius of the number disc
    private const float StripeHalfHeight = 0.55f; // |z| of the band's edges on the unit sphere
    private const float DigitHeight = 0.52f;   // gnomonic units (tan of the angle)

    /// <summary>The ball's base colour (sRGB, 0..1): the solid or stripe colour, white for the cue ball.</summary>
    public static Vector3 BaseColor(BallId id) => (id.Value == 0 ? 0 : ((id.Value - 1) % 8) + 1) switch
    {
        0 => new(0.96f, 0.95f, 0.90f),
        1 => new(0.98f, 0.80f, 0.06f), // yellow
        2 => new(0.06f, 0.22f, 0.72f), // blue
        3 => new(0.86f, 0.09f, 0.07f), // red
        4 => new(0.36f, 0.13f, 0.58f), // purple
        5 => new(0.98f, 0.45f, 0.06f), // orange
        6 => new(0.04f, 0.48f, 0.23f), // green
        7 => new(0.50f, 0.10f, 0.08f), // maroon
        _ => new(0.04f, 0.04f, 0.045f), // black (8)
    };

    /// <summary>Direction on the unit sphere (ball frame) of texel centre (i, j).</summary>
    public static Vector3 Direction(float u, float v)
    {
        float lon = u * 2 * MathF.PI;
        float lat = (v - 0.5f) * MathF.PI;
        return new Vector3(MathF.Cos(lat) * MathF.Cos(lon), MathF.Cos(lat) * MathF.Sin(lon), MathF.Sin(lat));
    }

    /// <summary>The ball's texture, <see cref="Width"/> x <see cref="Height"/> sRGB RGBA, rows from v = 0.</summary>
    public static byte[] Generate(BallId id)
    {
        var pixels = new byte[Width * Height * 4];
        var white = new Vector3(0.97f, 0.96f, 0.92f);
        var ink = new Vector3(0.03f, 0.03f, 0.03f);
        var baseColor = BaseColor(id);
        string label = id.Value.ToString(System.Globalization.CultureInfo.InvariantCulture);
        const int Supersample = 3;
        for (int j = 0; j < Height; j++)
        {
            for (int i = 0; i < Width; i++)
            {
                var sum = Vector3.Zero;
                for (int sj = 0; sj < Supersample; sj++)
                {
                    for (int si = 0; si < Supersample; si++)
                    {
                        float u = (i + ((si + 0.5f) / Supersample)) / Width;
                        float v = (j + ((sj + 0.5f) / Supersample)) / Height;
                        sum += Shade(id, Direction(u, v), baseColor, white, ink, label);
                    }
                }
                var c = sum / (Supersample * Supersample);
                int o = ((j * Width) + i) * 4;
                pixels[o] = (byte)Math.Clamp(c.X * 255 + 0.5f, 0, 255);
                pixels[o + 1] = (byte)Math.Clamp(c.Y * 255 + 0.5f, 0, 255);
                pixels[o + 2] = (byte)Math.Clamp(c.Z * 255 + 0.5f, 0, 255);
                pixels[o + 3] = 255;
            }
        }
        return pixels;
    }

    private static Vector3 Shade(BallId id, Vector3 d, Vector3 baseColor, Vector3 white, Vector3 ink, string label)
    {
        if (id.IsCue)
        {
            // Six small red spots on the axes show the cue ball's rotation.
            float spot = MathF.Max(MathF.Max(MathF.Abs(d.X), MathF.Abs(d.Y)), MathF.Abs(d.Z));
            return spot > MathF.Cos(0.11f) ? new Vector3(0.80f, 0.08f, 0.08f) : baseColor;
        }
        var surface = id.IsStripe && MathF.Abs(d.Z) > StripeHalfHeight ? white : baseColor;
        // Number discs at +x and -x; read upright with z up.
        foreach (float side in s_sides)
        {
            float cos = d.X * side;
            if (cos < MathF.Cos(DiscAngle))
            {
                continue;
            }
            // Gnomonic coordinates on the disc's tangent plane: right and up as seen from outside.
            float right = d.Y * side / cos;
            float up = d.Z / cos;
            float glyph = DigitCoverage(label, right, up);
            return glyph > 0.36f ? ink : white;
        }
        return surface;
    }

    private static float DigitCoverage(string label, float right, float up)
    {
        float scale = BitmapFont.GlyphHeight / DigitHeight;
        float width = ((label.Length * BitmapFont.Advance) - 1) / scale;
        float x = (right + (width / 2)) * scale;
        float y = ((DigitHeight / 2) - up) * scale;
        int index = (int)MathF.Floor(x / BitmapFont.Advance);
        if (index < 0 || index >= label.Length)
        {
            return 0;
        }
        return BitmapFont.Sample(label[index], x - (index * BitmapFont.Advance), y);
    }
}
