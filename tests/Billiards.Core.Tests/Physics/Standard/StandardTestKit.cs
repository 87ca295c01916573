using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>Builds standard-model simulations from small inline scenes.</summary>
internal static class StandardTestKit
{
    public const double R = 0.028575;
    public const double G = 9.81;

    public static readonly double[] Dts = [1.0 / 30, 1.0 / 250, 1.0 / 4000];

    public static string F(double x) => x.ToString("R", CultureInfo.InvariantCulture);

    public static string Ball(string id, double x, double y, double vx = 0, double vy = 0, double wx = 0, double wy = 0, double wz = 0) =>
        $$"""{ "id": "{{id}}", "position": [{{F(x)}}, {{F(y)}}], "velocity": [{{F(vx)}}, {{F(vy)}}], "spin": [{{F(wx)}}, {{F(wy)}}, {{F(wz)}}] }""";

    public static StandardSimulation Create(string integrator, double dt, string table, string? shot, string extraParams, params string[] balls)
    {
        string json = $$"""
        {
          "format": "billiards-scene/1",
          "table": {{table}},
          "physics": { "model": "standard", "integrator": "{{integrator}}", "dt": {{F(dt)}}, "params": { {{extraParams}} } },
          "balls": [ {{string.Join(", ", balls)}} ]{{(shot is null ? "" : $", \"shot\": {shot}")}}
        }
        """;
        var scene = SceneLoader.Parse(json, "inline.json");
        var sim = new StandardSimulation(scene);
        if (scene.Shot is { } s)
        {
            sim.Strike(s);
        }
        return sim;
    }

    /// <summary>A pocketless 10 x 5 m table: room for the longest analytic runs.</summary>
    public const string BigTable = """{ "preset": "pocketless", "length": 10, "width": 5 }""";

    public static StandardSimulation Load(string sceneFile, string? integrator = null, double? dt = null)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(sceneFile), new SceneOverrides(null, integrator, dt));
        var sim = new StandardSimulation(scene);
        if (scene.Shot is { } s)
        {
            sim.Strike(s);
        }
        return sim;
    }

    public static void RunToRest(StandardSimulation sim, double limit = 600)
    {
        sim.AdvanceTo(limit);
        Assert.True(sim.IsAtRest, "the shot did not come to rest");
    }

    public static void AssertRelative(double expected, double actual, double tolerance, string what)
    {
        double error = Math.Abs(actual - expected) / Math.Abs(expected);
        Assert.True(error <= tolerance, $"{what}: expected {expected:R}, got {actual:R} (relative error {error:E2})");
    }

    public static double Energy(in BallState b, double m = 0.170097, double r = R) =>
        0.5 * m * b.Velocity.LengthSquared + 0.5 * 0.4 * m * r * r * b.Spin.LengthSquared;

    public static Vec3 V(double x, double y, double z = 0) => new(x, y, z);
}
