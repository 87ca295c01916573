using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Thesis;

/// <summary>The thesis model behind the Simulation API: frames, strikes, events, whole breaks.</summary>
public class ThesisSimulationTests
{
    private static Scene LoadScene(string name) =>
        SceneLoader.Load(AssetFolder.Scene(name));

    [Fact]
    public void Balls_read_back_in_SI_where_the_scene_put_them()
    {
        var scene = LoadScene("thesis-eight-ball-break.json");
        var sim = new ThesisSimulation(scene);
        Assert.Equal(16, sim.Balls.Length);
        for (int i = 0; i < scene.Balls.Count; i++)
        {
            var expected = scene.Balls[i].Position;
            var actual = sim.Balls[i].Position;
            // Through single-precision centimetres and back: a few micrometres at most.
            // (Vec3.ToString recurses through its XY property, so the message names components.)
            Assert.True((expected - actual).Length < 1e-6, $"ball {scene.Balls[i].Id}: ({actual.X}, {actual.Y}, {actual.Z})");
            Assert.Equal(MotionState.Stationary, sim.Balls[i].State);
        }
        Assert.True(sim.IsAtRest);
    }

    [Fact]
    public void A_strike_along_90_degrees_moves_the_cue_ball_towards_plus_y_at_the_capped_speed()
    {
        var sim = new ThesisSimulation(LoadScene("thesis-eight-ball-break.json"));
        sim.Strike(new ShotSpec(10, 90, TipSide: 0.5, TipHeight: -0.3, ElevationDeg: 12));
        // A cue at 10 m/s = 1000 cm/s is capped at Formel 31's 800 cm/s; a centre-ball impact of a
        // 0.567 kg cue on the 0.17 kg ball gives the ball 2 / (1 + 0.17 / 0.567) of it, 1230.9 cm/s;
        // aim 90 deg = SI +y = seed -z.
        double ball = 8 * 2 / (1 + 0.17 / 0.567);
        Assert.Equal((float)(-100 * ball), sim.Engine.Balls[0].Velocity.Z, 1e-3f);
        Assert.Equal(0.5f * 2.86f, sim.Queue.EX, 1e-6f);
        Assert.Equal(-0.3f * 2.86f, sim.Queue.EY, 1e-6f);
        Assert.Equal(12f, sim.Queue.Grade);
        sim.Step();
        // One step damps it once: times 0.9965, along +y, rolling.
        var cue = sim.Balls[0];
        Assert.Equal(0, cue.Velocity.X, 1e-6);
        Assert.Equal(ball * 0.9965, cue.Velocity.Y, 1e-4);
        Assert.Equal(MotionState.Rolling, cue.State);
        // Rolling without slip: w = z x v / R = (-v / 0.0286, 0, 0).
        Assert.Equal(-ball * 0.9965 / 0.0286, cue.Spin.X, 0.01);
        Assert.Equal(0.004, sim.Time, 1e-12);
    }

    [Fact]
    public void The_8_ball_break_comes_to_rest_on_the_bed_or_in_pockets()
    {
        var outcome = SimulationRunner.Run(LoadScene("thesis-eight-ball-break.json"), new RunOptions());
        var sim = outcome.Simulation;
        Assert.True(outcome.AtRest);
        Assert.Equal(16, sim.Balls.Length);
        foreach (var b in sim.Balls)
        {
            Assert.True(b.Position.IsFinite && b.Velocity.IsFinite);
            Assert.Equal(0, b.Velocity.Length);
            if (b.State == MotionState.Pocketed)
            {
                Assert.True(b.Pocket >= 0);
                Assert.True(b.Position.Z < -0.2); // fell below the seed's -20 cm
            }
            else
            {
                Assert.Equal(MotionState.Stationary, b.State);
                Assert.Equal(0.0286, b.Position.Z, 1e-6);
                Assert.True(Math.Abs(b.Position.X) < 1.225 - 0.0286 + 1e-6 && Math.Abs(b.Position.Y) < 0.635 - 0.0286 + 1e-6);
            }
        }
        var events = sim.Events.AsSpan().ToArray();
        // The log tells the break as it happened: the cue strike at t = 0 first, then time order;
        // the cue ball meets the rack before anything else is hit; each ball at rest in a pocket
        // dropped into that pocket exactly once, and no other ball dropped.
        Assert.Equal((0.0, EventKind.CueStrike), (events[0].Time, events[0].Kind));
        Assert.Single(events, e => e.Kind == EventKind.CueStrike);
        Assert.All(events.Zip(events.Skip(1)), p => Assert.True(p.First.Time <= p.Second.Time, $"{p.Second.Kind} at {p.Second.Time} s after {p.First.Time} s"));
        var first = events.First(e => e.Kind is EventKind.BallBall or EventKind.BallCushion);
        Assert.True(first.Kind == EventKind.BallBall && PoolBalls.IsCue(first.A), $"the first contact is {first.Kind} of {first.A}");
        Assert.Contains(events, e => e.Kind == EventKind.BallCushion);
        Assert.All(events, e => Assert.True(e.Speed >= 0 && double.IsFinite(e.Speed)));
        foreach (var e in events.Where(e => e.Kind == EventKind.BallCushion))
        {
            Assert.NotEmpty(sim.FeatureName(e.Kind, e.Feature));
        }
        var drops = events.Where(e => e.Kind == EventKind.BallPocket).Select(e => (e.A.Value, e.Feature)).Order().ToArray();
        var pocketed = Enumerable.Range(0, sim.Balls.Length).Where(i => sim.Balls[i].IsPocketed).Select(i => (sim.Ids[i].Value, sim.Balls[i].Pocket)).Order().ToArray();
        Assert.NotEmpty(drops); // this break pockets a ball
        Assert.Equal(pocketed, drops);
    }

    [Theory]
    [InlineData("thesis-eight-ball-break.json")]
    [InlineData("thesis-nine-ball-break.json")]
    public void A_break_repeats_bit_for_bit(string scene)
    {
        var a = SimulationRunner.Run(LoadScene(scene), new RunOptions()).Simulation;
        var b = SimulationRunner.Run(LoadScene(scene), new RunOptions()).Simulation;
        Assert.True(a.IsAtRest);
        Assert.Equal(a.StepCount, b.StepCount);
        Assert.Equal(a.Balls.ToArray(), b.Balls.ToArray());
        Assert.Equal(a.Events.AsSpan().ToArray(), b.Events.AsSpan().ToArray());
    }

    [Fact]
    public void Feature_names_follow_the_result_format()
    {
        var sim = new ThesisSimulation(LoadScene("thesis-eight-ball-break.json"));
        Assert.Equal("foot-left", sim.FeatureName(EventKind.BallPocket, 4));
        Assert.Equal("left-head", sim.FeatureName(EventKind.BallCushion, 2));
        Assert.Equal("side-right-jaw", sim.FeatureName(EventKind.BallCushion, 9));
        Assert.Equal("head-left-back", sim.FeatureName(EventKind.BallCushion, 12));
    }

    [Fact]
    public void Steps_allocate_nothing()
    {
        var scene = LoadScene("thesis-eight-ball-break.json");
        // A whole break first, so that one-time costs (type initialisation, tiered JIT) are paid.
        SimulationRunner.Run(scene, new RunOptions());
        var sim = new ThesisSimulation(scene);
        sim.Strike(new ShotSpec(8, 0));
        long before = GC.GetAllocatedBytesForCurrentThread();
        while (!sim.IsAtRest)
        {
            sim.Step();
            _ = sim.Balls;
        }
        // With tiered JIT off this is exactly 0; with it on, the runtime's switch to optimised code
        // may charge a few dozen bytes once to this thread. One allocation per step would be
        // 2263 steps * at least 24 bytes = 54 kB.
        Assert.InRange(GC.GetAllocatedBytesForCurrentThread() - before, 0, 256);
    }
}
