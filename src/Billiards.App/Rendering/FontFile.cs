using Billiards.Core.Scenes;
using SkiaSharp;

namespace Billiards.App.Rendering;

/// <summary>The TrueType fonts in assets/fonts, each read once for the process.</summary>
/// <remarks>A font that is missing or unreadable is an <see cref="AssetException"/> naming it.</remarks>
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
                if (!File.Exists(path))
                {
                    throw AssetException.Missing(path);
                }
                typeface = SKTypeface.FromFile(path) ?? throw AssetException.Unreadable(path, "not a TrueType font that SkiaSharp can read");
                s_open[path] = typeface;
            }
            return typeface;
        }
    }
}
