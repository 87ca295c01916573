using SkiaSharp;

namespace Billiards.App.Rendering;

/// <summary>The TrueType fonts in assets/fonts, each read once for the process.</summary>
internal static class FontFile
{
    private static readonly Dictionary<string, SKTypeface> s_open = [];

    /// <summary>The typeface in <paramref name="path"/>, read on first use.</summary>
    public static SKTypeface Open(string path)
    {
        lock (s_open)
        {
            if (!s_open.TryGetValue(path, out var typeface))
            {
                typeface = SKTypeface.FromFile(path) ?? throw new InvalidOperationException($"{path}: not a font file that can be read");
                s_open[path] = typeface;
            }
            return typeface;
        }
    }
}
