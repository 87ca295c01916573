using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Physics.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Cue;

/// <summary>The tip in the cue's frame (scene-format.md), the tip's restitution and the miscue.</summary>
public class CueFrameTests
{
    private static readonly PhysicsParams P = PhysicsParams.Pool;

    [Theory]
    [InlineData(0)]
    [InlineData(30)]
    [InlineData(55)]
    [InlineData(80)]
    public void TheCentreOfTheTipStrikesThroughTheCentreAtAnyElevation(double elevation)
    {
        var o = CueStrike.Strike(new ShotSpec(3, 20, 0, 0, elevation), P);
        Assert.Equal(0, o.Spin.Length, 12);
        double v = (1 + P.ETip) * 3 / (1 + P.M / P.CueMass);
        double t = elevation * Math.PI / 180;
        Assert.Equal(v * Math.Cos(t), o.Velocity.Length, 12);
        Assert.Equal(v * Math.Sin(t), o.IntoSlate, 12);
        Assert.False(o.Miscue);
    }

    [Fact]
    public void ALeatherTipGivesTheBallLessThanAnElasticOne()
    {
        // TP A-30: v = (1 + e) V0 / (1 + m/M + ...); e_tip 0.73 against 1.
        double elastic = CueStrike.BallSpeed(3, 0, 0, P with { ETip = 1 });
        Assert.Equal(1.73 / 2, CueStrike.BallSpeed(3, 0, 0, P) / elastic, 12);
        Assert.True(P.ETip < 1);
    }

    [Fact]
    public void TopSpinAboutTheCuesAxisIsPerpendicularToIt()
    {
        // b above the cue's axis: w = v / (I/m) (-b i + a sin t j + a cos t k); for a = 0 the spin is
        // about the horizontal axis to the right of the aim, whatever the elevation.
        double b = 0.4, t = 40 * Math.PI / 180;
        var o = CueStrike.Strike(new ShotSpec(2, 0, 0, b, 40), P);
        double v = CueStrike.BallSpeed(2, 0, b * P.R, P);
        var expected = new Vec3(0, 1, 0) * (v / (0.4 * P.R * P.R) * b * P.R); // i = (0, -1, 0) for aim +x: -b i = +b y
        Assert.True((o.Spin - expected).Length < 1e-9 * expected.Length, $"{o.Spin} against {expected}");
        Assert.Equal(v * Math.Cos(t), o.Velocity.X, 12);
    }

    [Fact]
    public void ATipPastTheMiscueLimitIsAMiscueInSimulate()
    {
        var scene = SceneLoader.Parse("""
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
              "balls": [ { "id": "cue", "position": [-0.6, 0] } ],
              "shot": { "speed": 3, "aim_deg": 0, "tip": [0, 0.8], "elevation_deg": 0 } }
            """, "miscue.json");
        var outcome = SimulationRunner.Run(scene, new RunOptions());
        var events = outcome.Simulation.Events.AsSpan().ToArray();
        Assert.Equal([EventKind.CueStrike, EventKind.Miscue], events.Take(2).Select(e => e.Kind));
        string json = System.Text.Encoding.UTF8.GetString(ResultWriter.ToUtf8(outcome, indented: false));
        Assert.Contains("\"type\":\"miscue\"", json.Replace(" ", "", StringComparison.Ordinal), StringComparison.Ordinal);

        var strike = CueStrike.Strike(scene.Shot!, scene.Physics.Params);
        Assert.True(strike.Miscue);
        Assert.Equal(Vec3.Zero, strike.Spin);
        double centre = CueStrike.Strike(scene.Shot! with { TipHeight = 0 }, scene.Physics.Params).Velocity.Length;
        Assert.Equal(CueStrike.MiscueSpeedFraction * centre, strike.Velocity.Length, 12);
    }

    [Fact]
    public void TheLimitIsAParameter()
    {
        Assert.False(CueStrike.IsMiscue(new ShotSpec(3, 0, 0.42, 0.42), P));
        Assert.True(CueStrike.IsMiscue(new ShotSpec(3, 0, 0.43, 0.43), P));
        Assert.False(CueStrike.IsMiscue(new ShotSpec(3, 0, 0, 0.8), P with { MiscueLimit = 0.85 }));
    }
}
