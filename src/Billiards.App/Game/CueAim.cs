using Billiards.App.Camera;
using Billiards.Core.Mathematics;

namespace Billiards.App.Game;

/// <summary>
/// Turning the cue from the keyboard, for a match and for practice alike: the cue aims from the
/// camera's azimuth through the cue ball (<see cref="CueNode.AimDirection"/>), so aiming centres the
/// camera on the cue ball and turns it.
/// </summary>
public static class CueAim
{
    /// <summary>Turns the aim by <paramref name="degrees"/> (counter-clockwise seen from above) about the cue ball at <paramref name="cueBall"/>.</summary>
    public static void Turn(OrbitCamera camera, Vec3 cueBall, double degrees)
    {
        ArgumentNullException.ThrowIfNull(camera);
        camera.Translate(cueBall - camera.Centre);
        camera.Orbit(degrees * Math.PI / 180 / OrbitCamera.OrbitRadiansPerPixel / camera.Sensitivity, 0);
    }

    /// <summary>Sets the aim to <paramref name="degrees"/> (from +x counter-clockwise): the camera behind the cue ball at <paramref name="cueBall"/>.</summary>
    public static void AimAt(OrbitCamera camera, Vec3 cueBall, double degrees)
    {
        ArgumentNullException.ThrowIfNull(camera);
        camera.Translate(cueBall - camera.Centre);
        camera.SetPhi((degrees * Math.PI / 180) + Math.PI);
    }
}
