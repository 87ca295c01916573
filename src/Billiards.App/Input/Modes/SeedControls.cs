namespace Billiards.App.Input.Modes;

/// <summary>
/// The constants of the seed's cue controls (seed 4.4.3-4.4.5) in one place, with their units;
/// Formel 31's belong to the thesis cue, <see cref="Billiards.Core.Cue.ThesisCue"/>.
/// The seed works in centimetres and milliseconds (GLUT_ELAPSED_TIME); the game converts to
/// Core's metres only where it hands a value to Core. The camera's constants (Listings 5 and 6)
/// live in <see cref="Camera.OrbitCamera"/>.
/// </summary>
public static class SeedControls
{
    /// <summary>Centimetres per metre: the seed's length unit to Core's.</summary>
    public const double CentimetresPerMetre = 100;

    /// <summary>Formel 32-33: the tip offset moves 0.01 cm per pixel of mouse movement.</summary>
    public const double SpinCentimetresPerPixel = 0.01;

    /// <summary>The seed's ball radius (cm); the tip offset e_x, e_y is in the same unit.</summary>
    public const double BallRadiusCentimetres = 2.86;

    /// <summary>
    /// How far from the centre the tip may go, as a fraction of R. The seed only says the tip is
    /// kept on the ball (seed 4.4.4); Core's <see cref="Billiards.Core.Cue.ShotSpec"/> needs it
    /// strictly inside (side² + height² &lt; 1), and a tip at the very silhouette would be a
    /// miscue, so we stop at 0.9 R.
    /// </summary>
    public const double MaxTipFraction = 0.9;

    /// <summary>
    /// Formel 34: the seed adds the raw mouse delta to the ball's position, i.e. one seed unit
    /// (1 cm) per pixel; in metres.
    /// </summary>
    public const double MoveMetresPerPixel = 0.01;

    /// <summary>The share of a drag of the cue ball (ball in hand, move mode) that moves it with Shift held: fine placement, an addition to the seed.</summary>
    public const double FineMoveFactor = 0.1;

    /// <summary>How far an arrow key moves the cue ball in move mode (m), along the screen's up and right on the bed; an addition to the seed.</summary>
    public const double KeyMoveMetres = 0.005;

    /// <summary>As <see cref="KeyMoveMetres"/> with Shift held (m): a half-millimetre nudge.</summary>
    public const double FineKeyMoveMetres = 0.0005;

    /// <summary>The share of the orbit (Listing 5) a mouse drag with Shift held turns: fine aim, an addition to the seed.</summary>
    public const double FineOrbitFactor = 0.1;

    /// <summary>Cue elevation (deg) per key press or wheel notch. The seed's elevation ("grade") was visual only; here it feeds the strike.</summary>
    public const double ElevationStepDegrees = 1;

    /// <summary>Largest cue elevation (deg); Core accepts up to 90, but the cue would stand on the ball.</summary>
    public const double MaxElevationDegrees = Billiards.Core.Cue.CueClearance.MaxElevationDegrees;

    /// <summary>Gap between the tip and the ball's surface at rest (m), the seed's cue offset d when not stroking; visual only.</summary>
    public const double CueRestGap = 0.01;

    /// <summary>How far the drawn cue moves back per pixel of backswing (m); visual only, the seed does not give it.</summary>
    public const double PullBackMetresPerPixel = 0.001;

    /// <summary>Longest drawn backswing (m); visual only.</summary>
    public const double MaxPullBack = 0.4;

    /// <summary>Wheel notches count as this many pixels of right-drag zoom in view mode (Listing 6's dy); an addition to the seed.</summary>
    public const double ZoomPixelsPerNotch = 10;

    /// <summary>Converts the seed's stroke speed (cm/s) to Core's (m/s).</summary>
    public static double ToMetresPerSecond(double seedSpeed) => seedSpeed / CentimetresPerMetre;
}
