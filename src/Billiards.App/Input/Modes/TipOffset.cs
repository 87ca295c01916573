using System.Numerics;

namespace Billiards.App.Input.Modes;

/// <summary>
/// Where the cue's tip meets the cue ball (seed 4.4.4): the seed's e_x (to the right) and e_y (up)
/// in centimetres from the ball's centre as seen along the cue.
/// </summary>
public sealed class TipOffset
{
    /// <summary>Largest distance of the tip from the centre (cm).</summary>
    public const double MaxOffsetCentimetres = SeedControls.MaxTipFraction * SeedControls.BallRadiusCentimetres;

    /// <summary>e_x: offset to the right (cm).</summary>
    public double X { get; private set; }

    /// <summary>e_y: offset upwards (cm).</summary>
    public double Y { get; private set; }

    /// <summary>
    /// Formel 32-33: e_x += dx * 0.01, e_y -= dy * 0.01 (pixels, y down, so moving the mouse up
    /// raises the tip); then pulled back radially onto the allowed disc so the tip stays on the ball.
    /// </summary>
    public void Move(double dx, double dy)
    {
        Set(X + dx * SeedControls.SpinCentimetresPerPixel, Y - dy * SeedControls.SpinCentimetresPerPixel);
    }

    /// <summary>Sets the offset (cm), clamped onto the allowed disc.</summary>
    public void Set(double x, double y)
    {
        double length = Math.Sqrt(x * x + y * y);
        if (length > MaxOffsetCentimetres)
        {
            x *= MaxOffsetCentimetres / length;
            y *= MaxOffsetCentimetres / length;
        }
        X = x;
        Y = y;
    }

    /// <summary>Back to the centre (the seed resets the cue when the balls come to rest).</summary>
    public void Reset() => Set(0, 0);

    /// <summary>
    /// The offset as fractions of R [side, height], as <see cref="Billiards.Core.Cue.ShotSpec"/> and
    /// the HUD's spin diagram take it: side positive to the right seen from behind the cue, height up.
    /// </summary>
    public Vector2 Fractions => new((float)(X / SeedControls.BallRadiusCentimetres), (float)(Y / SeedControls.BallRadiusCentimetres));

    /// <summary>Side offset as a fraction of R, in double precision for the strike.</summary>
    public double SideFraction => X / SeedControls.BallRadiusCentimetres;

    /// <summary>Height offset as a fraction of R, in double precision for the strike.</summary>
    public double HeightFraction => Y / SeedControls.BallRadiusCentimetres;
}
