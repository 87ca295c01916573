using System.Numerics;
using Billiards.App.Camera;
using Billiards.Core.Mathematics;

namespace Billiards.App.Tests.Camera;

public class OrbitCameraTests
{
    private const int Digits = 12;

    [Fact]
    public void EyeIsCentrePlusDistanceTimesTheZUpPolarDirection()
    {
        // θ = π/4, φ = 0, distance 2: eye = c + 2 (sin 45°, 0, cos 45°) = c + (√2, 0, √2).
        var camera = new OrbitCamera(new Vec3(1, 2, 0.03), Math.PI / 4, 0, 2);
        Assert.Equal(1 + Math.Sqrt(2), camera.Eye.X, Digits);
        Assert.Equal(2, camera.Eye.Y, Digits);
        Assert.Equal(0.03 + Math.Sqrt(2), camera.Eye.Z, Digits);
    }

    [Fact]
    public void OrbitFollowsListing5()
    {
        // θ -= 0.01 * 20 = 1.0 - 0.2 = 0.8; φ += 0.01 * 10 = 0.5 + 0.1 = 0.6.
        var camera = new OrbitCamera(Vec3.Zero, 1.0, 0.5, 1.0);
        camera.Orbit(10, 20);
        Assert.Equal(0.8, camera.Theta, Digits);
        Assert.Equal(0.6, camera.Phi, Digits);
        // (sin 0.8 cos 0.6, sin 0.8 sin 0.6, cos 0.8)
        Assert.Equal(0.5920595303917607, camera.Eye.X, Digits);
        Assert.Equal(0.4050497174705004, camera.Eye.Y, Digits);
        Assert.Equal(0.6967067093471654, camera.Eye.Z, Digits);
        Assert.Equal(1.0, camera.Distance, Digits);
    }

    [Fact]
    public void OrbitScalesWithTheSensitivity()
    {
        var camera = new OrbitCamera(Vec3.Zero, 1.0, 0.5, 1.0) { Sensitivity = 2 };
        camera.Orbit(10, 20);
        Assert.Equal(1.0 - 0.4, camera.Theta, Digits);
        Assert.Equal(0.5 + 0.2, camera.Phi, Digits);
    }

    [Theory]
    [InlineData(-1000, Math.PI / 2 - 0.01)] // mouse far up: θ grows to the clamp, camera near the bed
    [InlineData(1000, 0.01)]                // mouse far down: θ shrinks to the clamp, camera near the top
    public void ThetaIsClampedToListing5sLimits(double dy, double expected)
    {
        var camera = new OrbitCamera(Vec3.Zero, 1.0, 0, 1.0);
        camera.Orbit(0, dy);
        Assert.Equal(expected, camera.Theta, Digits);
        Assert.True(camera.Eye.Z > 0, "the camera stays above the bed plane through the centre");
    }

    [Fact]
    public void PhiWrapsBelowZeroByAddingTwoPi()
    {
        var camera = new OrbitCamera(Vec3.Zero, 1.0, 0.05, 1.0);
        camera.Orbit(-10, 0); // 0.05 - 0.1 = -0.05 -> -0.05 + 2π
        Assert.Equal(6.233185307179586, camera.Phi, Digits);
    }

    [Fact]
    public void PhiWrapsAboveTwoPiBySubtractingIt()
    {
        var camera = new OrbitCamera(Vec3.Zero, 1.0, 6.2, 1.0);
        camera.Orbit(10, 0); // 6.2 + 0.1 = 6.3 -> 6.3 - 2π
        Assert.Equal(0.01681469282041359, camera.Phi, Digits);
    }

    [Fact]
    public void PhiOfExactlyTwoPiWrapsToZero()
    {
        Assert.Equal(0, OrbitCamera.WrapPhi(2 * Math.PI));
        Assert.Equal(0, new OrbitCamera(Vec3.Zero, 1, 2 * Math.PI, 1).Phi);
    }

    [Theory]
    [InlineData(1.0, 20, 0.8)]   // scale (100 - 20) / 100 = 0.8: moving down zooms in
    [InlineData(1.0, -50, 1.5)]  // scale 1.5: moving up zooms out
    [InlineData(3.0, -50, 4.0)]  // 4.5 m clamped to Listing 6's 400 cm = 4 m
    [InlineData(0.12, 50, 0.1)]  // 0.06 m clamped to Listing 6's 10 cm = 0.1 m
    [InlineData(1.0, 500, 0.1)]  // a 500 px jump: Listing 6's scale would be -4; the camera does not flip
    public void ZoomFollowsListing6WithItsClamps(double distance, double dy, double expected)
    {
        var camera = new OrbitCamera(new Vec3(0.5, 0.2, 0.03), 1.1, 2.0, distance);
        var before = (camera.Eye - camera.Centre) / camera.Distance;
        camera.Zoom(dy);
        Assert.Equal(expected, camera.Distance, Digits);
        Assert.Equal(expected, (camera.Eye - camera.Centre).Length, Digits);
        // The direction from the centre is unchanged: the camera moves on the line through the ball.
        var after = (camera.Eye - camera.Centre) / camera.Distance;
        Assert.Equal(before.X, after.X, Digits);
        Assert.Equal(before.Y, after.Y, Digits);
        Assert.Equal(before.Z, after.Z, Digits);
    }

    [Fact]
    public void ZoomScalesWithTheSensitivity()
    {
        var camera = new OrbitCamera(Vec3.Zero, 1, 0, 1.0) { Sensitivity = 0.5 };
        camera.Zoom(20); // (100 - 10) / 100
        Assert.Equal(0.9, camera.Distance, Digits);
    }

    [Fact]
    public void TranslateMovesCentreAndEyeTogether()
    {
        var camera = new OrbitCamera(new Vec3(0, 0, 0.03), 1.0, 1.0, 1.0);
        var eye = camera.Eye;
        camera.Translate(new Vec3(0.25, -0.5, 0));
        Assert.Equal(eye.X + 0.25, camera.Eye.X, Digits);
        Assert.Equal(eye.Y - 0.5, camera.Eye.Y, Digits);
        Assert.Equal(eye.Z, camera.Eye.Z, Digits);
        Assert.Equal(1.0, camera.Theta);
        Assert.Equal(1.0, camera.Phi);
    }
}

public class ViewMathTests
{
    [Fact]
    public void BedForwardIgnoresHeightAndRightIsClockwiseFromAbove()
    {
        var f = ViewMath.BedForward(new Vec3(-1, 0, 0.7), new Vec3(0, 0, 0.03));
        Assert.Equal(new Vec3(1, 0, 0), f);
        Assert.Equal(new Vec3(0, -1, 0), ViewMath.BedRight(f)); // looking along +x with z up, right is -y
    }

    [Theory]
    [InlineData(1, 0, 0)]
    [InlineData(0, 1, 90)]
    [InlineData(-1, 0, 180)]
    [InlineData(0, -1, -90)]
    public void AimDegreesAreFromPlusXCounterClockwise(double x, double y, double degrees) =>
        Assert.Equal(degrees, ViewMath.AimDegrees(new Vec3(x, y, 0)), 12);

    [Fact]
    public void ViewMatrixPutsTheTargetStraightAhead()
    {
        var eye = new Vector3(-2, 0, 1);
        var target = new Vector3(0, 0, 0);
        var v = Vector3.Transform(target, ViewMath.View(eye, target));
        Assert.Equal(0, v.X, 5);
        Assert.Equal(0, v.Y, 5);
        Assert.Equal(-MathF.Sqrt(5), v.Z, 5); // right-handed: forward is -z in view space
        var up = Vector3.Transform(new Vector3(0, 0, 1), ViewMath.View(eye, target)) - Vector3.Transform(Vector3.Zero, ViewMath.View(eye, target));
        Assert.True(up.Y > 0, "world z is up on screen");
    }
}
