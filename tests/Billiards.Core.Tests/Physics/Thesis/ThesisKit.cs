using System.Numerics;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Thesis;

/// <summary>Builds small thesis-model set-ups in the seed's units (cm, Y up, bed height y = 2.86).</summary>
internal static class ThesisKit
{
    public const float Y = 2.86f;

    /// <summary>Pool's ball <paramref name="number"/> (0 the cue ball) at (x, z) cm.</summary>
    public static Ball At(int number, float x, float z, float vx = 0, float vz = 0) =>
        new(number, new Vector3(x, Y, z)) { Velocity = new Vector3(vx, 0, vz), IsCue = PoolBalls.IsCue(new Billiards.Core.Balls.BallId(number)) };

    public static PhysicsEngine Engine(string preset, params Ball[] balls) => Engine(preset, 1.0 / 250, balls);

    public static PhysicsEngine Engine(string preset, double dt, params Ball[] balls)
    {
        var table = TableSpec.FromPreset(preset);
        return new PhysicsEngine(balls, Initializer.InitRails(table), ThesisTable.From(table), new ThesisCue(), dt, new Random(1))
        {
            Events = new EventLog(),
        };
    }

    public static void AssertVector(Vector3 expected, Vector3 actual, float tolerance = 1e-3f)
    {
        Assert.True(Vector3.Distance(expected, actual) <= tolerance, $"expected {expected}, got {actual}");
    }
}
