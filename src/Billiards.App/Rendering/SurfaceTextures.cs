namespace Billiards.App.Rendering;

/// <summary>
/// Procedural detail textures that modulate a surface's lit colour: one byte a texel holding half
/// the factor (128 = unchanged), tileable, the same bytes on every run (a fixed integer hash, no
/// random generator). Cloth: a fine weave over a soft mottle. Wood: grain running along u.
/// Planks: boards along u with dark joints and their own grain.
/// </summary>
public static class SurfaceTextures
{
    /// <summary>Side of the textures (texels).</summary>
    public const int Size = 256;

    /// <summary>Metres one texture repeat covers on the cloth.</summary>
    public const float ClothRepeat = 0.5f;

    /// <summary>Metres one texture repeat covers on the wood.</summary>
    public const float WoodRepeat = 0.8f;

    /// <summary>Metres one texture repeat covers on the floor's boards.</summary>
    public const float PlankRepeat = 1.2f;

    /// <summary>The cloth's weave (2-texel twill) over a mottle of a few per cent.</summary>
    public static byte[] Cloth() => Build((x, y) =>
    {
        float mottle = Fbm(x, y, 8, 3) - 0.5f;
        float fine = Fbm(x, y, 64, 2) - 0.5f;
        float twill = ((x + y) / 2 % 2 == 0) ? 0.012f : -0.012f;
        return 1 + (0.10f * mottle) + (0.05f * fine) + twill;
    });

    /// <summary>Wood grain along u: streaks bent by low-frequency noise, with rays of fine noise.</summary>
    public static byte[] Wood() => Build((x, y) => Grain(x, y, 0));

    /// <summary>Floor boards along u, 8 across a repeat, each with its own grain and a dark joint.</summary>
    public static byte[] Planks() => Build((x, y) =>
    {
        const int Boards = 8;
        int board = y * Boards / Size;
        int within = y - (board * Size / Boards);
        if (within == 0)
        {
            return 0.45f;
        }
        // Boards are staggered along u and differ a little in tone.
        int shift = (int)(Hash(board, 7, 101) * Size);
        float tone = 0.9f + (0.2f * Hash(board, 3, 202));
        return tone * Grain((x + shift) % Size, y, board + 1);
    });

    private static float Grain(int x, int y, int salt)
    {
        float bend = Fbm(x + (salt * 37), y, 2, 2);
        float rings = MathF.Sin((((float)y / Size * 24) + (bend * 6)) * MathF.PI * 2);
        float pores = Fbm(x, y + (salt * 53), 64, 1) - 0.5f;
        return 1 + (0.16f * rings * rings) - 0.08f + (0.08f * pores);
    }

    private static byte[] Build(Func<int, int, float> factor)
    {
        var texels = new byte[Size * Size];
        for (int y = 0; y < Size; y++)
        {
            for (int x = 0; x < Size; x++)
            {
                texels[(y * Size) + x] = (byte)Math.Clamp((factor(x, y) * 128) + 0.5f, 0, 255);
            }
        }
        return texels;
    }

    /// <summary>Tileable fractal value noise in [0, 1]: <paramref name="cells"/> lattice cells a repeat, doubling per octave.</summary>
    public static float Fbm(int x, int y, int cells, int octaves)
    {
        float sum = 0, weight = 0, amplitude = 1;
        for (int o = 0; o < octaves; o++)
        {
            sum += amplitude * Value((float)x / Size * cells, (float)y / Size * cells, cells, o);
            weight += amplitude;
            amplitude *= 0.5f;
            cells *= 2;
        }
        return sum / weight;
    }

    private static float Value(float x, float y, int period, int salt)
    {
        int x0 = (int)MathF.Floor(x), y0 = (int)MathF.Floor(y);
        float fx = x - x0, fy = y - y0;
        float sx = fx * fx * (3 - (2 * fx)), sy = fy * fy * (3 - (2 * fy));
        float Corner(int cx, int cy) => Hash(((cx % period) + period) % period, ((cy % period) + period) % period, salt);
        float top = Corner(x0, y0) + (sx * (Corner(x0 + 1, y0) - Corner(x0, y0)));
        float bottom = Corner(x0, y0 + 1) + (sx * (Corner(x0 + 1, y0 + 1) - Corner(x0, y0 + 1)));
        return top + (sy * (bottom - top));
    }

    /// <summary>A hash of three integers to [0, 1).</summary>
    private static float Hash(int x, int y, int salt)
    {
        uint h = (uint)((x * 374761393) + (y * 668265263) + (salt * 1274126177));
        h = (h ^ (h >> 13)) * 1274126177u;
        h ^= h >> 16;
        return (h & 0xFFFFFF) / (float)0x1000000;
    }
}
