using Billiards.App.Rendering;
using Billiards.Core.Table;

namespace Billiards.App.Nodes;

/// <summary>
/// What <see cref="Node"/>s draw into: the <see cref="RenderFrame"/> being built plus what drawing
/// needs to know about this frame (the interpolation factor between the last two physics steps).
/// </summary>
public sealed class FrameBuilder
{
    /// <summary>Starts a frame for a table and a framebuffer size.</summary>
    /// <param name="table">The table drawn.</param>
    /// <param name="width">Framebuffer width (pixels).</param>
    /// <param name="height">Framebuffer height (pixels).</param>
    /// <param name="alpha">Interpolation factor in [0, 1]: 0 draws the previous physics step, 1 the current one.</param>
    public FrameBuilder(TableSpec table, int width, int height, double alpha)
    {
        Frame = new RenderFrame { Table = table, Width = width, Height = height };
        Alpha = Math.Clamp(alpha, 0, 1);
    }

    /// <summary>The frame being built.</summary>
    public RenderFrame Frame { get; }

    /// <summary>Interpolation factor between the previous and the current physics step.</summary>
    public double Alpha { get; }
}
