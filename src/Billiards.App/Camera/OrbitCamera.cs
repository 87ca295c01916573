using Billiards.Core.Mathematics;

namespace Billiards.App.Camera;

/// <summary>
/// The seed's camera (seed 4.4.1-4.4.2): it sits on a half sphere around the centre of interest
/// (the cue ball) at polar angle <see cref="Theta"/> from the vertical and azimuth <see cref="Phi"/>,
/// and zooms along the line to the centre.
/// </summary>
/// <remarks>
/// The seed is Y-up in centimetres; Core is z-up in metres. Listing 5's
/// camera = coi + dist * (sin θ cos φ, cos θ, sin θ sin φ) therefore becomes
/// coi + dist * (sin θ cos φ, sin θ sin φ, cos θ), and Listing 6's distance clamp
/// [10, 400] cm becomes [0.1, 4] m. Mouse deltas are in pixels, as in the seed.
/// </remarks>
public sealed class OrbitCamera
{
    /// <summary>Listing 5: radians of rotation per pixel of mouse movement (before the sensitivity).</summary>
    public const double OrbitRadiansPerPixel = 0.01;

    /// <summary>Listing 5: smallest polar angle (rad); keeps the camera off the vertical.</summary>
    public const double ThetaMin = 0.01;

    /// <summary>Listing 5: largest polar angle (rad), π/2 - 0.01; keeps the camera above the bed.</summary>
    public const double ThetaMax = Math.PI / 2 - 0.01;

    /// <summary>Listing 6: the zoom's percentage base, scale = (100 - dy * sensitivity) / 100.</summary>
    public const double ZoomPercentBase = 100;

    /// <summary>Listing 6: nearest distance to the centre of interest, 10 cm in the seed (m).</summary>
    public const double MinDistance = 0.10;

    /// <summary>Listing 6: farthest distance from the centre of interest, 400 cm in the seed (m).</summary>
    public const double MaxDistance = 4.00;

    /// <summary>
    /// Smallest zoom scale of one mouse event. Listing 6 has none: a jump of 100 pixels or more in
    /// one event would make the scale zero or negative and flip the camera through the centre
    /// under the table; we stop at 1 % instead, which the distance clamp then catches.
    /// </summary>
    public const double MinZoomScale = 0.01;

    /// <summary>Creates a camera.</summary>
    /// <param name="centre">Centre of interest (m).</param>
    /// <param name="theta">Polar angle from the vertical (rad), clamped to [<see cref="ThetaMin"/>, <see cref="ThetaMax"/>].</param>
    /// <param name="phi">Azimuth from +x towards +y (rad), wrapped to [0, 2π).</param>
    /// <param name="distance">Distance from the centre (m), clamped to [<see cref="MinDistance"/>, <see cref="MaxDistance"/>].</param>
    public OrbitCamera(Vec3 centre, double theta, double phi, double distance)
    {
        Centre = centre;
        Theta = Math.Clamp(theta, ThetaMin, ThetaMax);
        Phi = WrapPhi(phi);
        Distance = Math.Clamp(distance, MinDistance, MaxDistance);
    }

    /// <summary>Centre of interest (m): the point the camera looks at and orbits.</summary>
    public Vec3 Centre { get; set; }

    /// <summary>Polar angle from the vertical (rad).</summary>
    public double Theta { get; private set; }

    /// <summary>Azimuth from +x towards +y (rad), in [0, 2π).</summary>
    public double Phi { get; private set; }

    /// <summary>Distance of the eye from the centre (m).</summary>
    public double Distance { get; private set; }

    /// <summary>Mouse sensitivity, the seed's <c>mouseSensitivity</c> (the seed does not give its value).</summary>
    public double Sensitivity { get; set; } = 1.0;

    /// <summary>The eye (m): centre + distance * (sin θ cos φ, sin θ sin φ, cos θ).</summary>
    public Vec3 Eye => Centre + Distance * Direction(Theta, Phi);

    /// <summary>Unit vector from the centre towards the eye for a polar angle and azimuth (z up).</summary>
    public static Vec3 Direction(double theta, double phi) =>
        new(Math.Sin(theta) * Math.Cos(phi), Math.Sin(theta) * Math.Sin(phi), Math.Cos(theta));

    /// <summary>Listing 5: rotates the camera by a mouse movement (pixels, y down).</summary>
    public void Orbit(double dx, double dy)
    {
        Theta -= OrbitRadiansPerPixel * dy * Sensitivity;
        Theta = Math.Clamp(Theta, ThetaMin, ThetaMax);
        Phi = WrapPhi(Phi + OrbitRadiansPerPixel * dx * Sensitivity);
    }

    /// <summary>Listing 6: zooms by a mouse movement (pixels, y down; moving down zooms in).</summary>
    public void Zoom(double dy)
    {
        double scale = Math.Max((ZoomPercentBase - dy * Sensitivity) / ZoomPercentBase, MinZoomScale);
        // The seed scales the vector coi -> camera and clamps its length; the direction is unchanged,
        // so scaling the distance is the same thing and keeps θ and φ exact.
        Distance = Math.Clamp(Distance * scale, MinDistance, MaxDistance);
    }

    /// <summary>Turns the camera to the azimuth <paramref name="phi"/> (rad), exactly: a computer player's or a hint's aim.</summary>
    public void SetPhi(double phi) => Phi = WrapPhi(phi);

    /// <summary>Lowers the polar angle to at most <paramref name="theta"/> (rad), i.e. raises the eye; never below <see cref="ThetaMin"/>.</summary>
    public void LimitTheta(double theta) => Theta = Math.Clamp(Math.Min(Theta, theta), ThetaMin, ThetaMax);

    /// <summary>Moves the centre and the eye together (Formel 35: camera = p + c), keeping the view.</summary>
    public void Translate(Vec3 offset) => Centre += offset;

    /// <summary>
    /// Listing 5's wrap, for one step: below 0 add 2π, at or above 2π subtract it. The seed tests
    /// <c>phi &gt; 2π</c>; we use ≥ so that φ stays in [0, 2π) (2π and 0 are the same view). The
    /// loop only matters for a jump of more than a whole turn in one event.
    /// </summary>
    public static double WrapPhi(double phi)
    {
        while (phi < 0)
        {
            phi += 2 * Math.PI;
        }
        while (phi >= 2 * Math.PI)
        {
            phi -= 2 * Math.PI;
        }
        return phi;
    }
}
