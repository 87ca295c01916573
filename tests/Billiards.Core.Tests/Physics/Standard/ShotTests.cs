using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Roots;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Standard;

/// <summary>Whole shots: what a player expects, exact against event, no tunnelling, pockets.</summary>
public class ShotTests
{
    private const string Pocketless = """{ "preset": "pocketless" }""";

    // A firm straight shot (cue at 3 m/s) over 0.6 m: the spin survives the trip.
    private static StandardSimulation StraightShot(double tipHeight, string integrator = "exact") =>
        Create(integrator, 1.0 / 250, Pocketless, $$"""{ "speed": 3.0, "aim_deg": 0, "tip": [0, {{F(tipHeight)}}] }""", "",
            Ball("cue", -0.6, 0), Ball("1", 0, 0));

    [Fact]
    public void DrawComesBack()
    {
        var sim = StraightShot(-0.6);
        sim.AdvanceTo(2.0);
        Assert.Equal(EventKind.CueStrike, sim.Events[0].Kind);
        Assert.Equal(EventKind.BallBall, sim.Events[1].Kind);
        // Contact happens with the cue ball's centre at x = -2R; draw brings it well behind that.
        Assert.True(sim.Balls[0].Position.X < -2 * R - 0.2, $"cue ball at {sim.Balls[0].Position.X}");
    }

    [Fact]
    public void FollowFollows()
    {
        var sim = StraightShot(0.6);
        sim.AdvanceTo(0.8);
        Assert.Equal(EventKind.CueStrike, sim.Events[0].Kind);
        Assert.Equal(EventKind.BallBall, sim.Events[1].Kind);
        Assert.True(sim.Balls[0].Velocity.X > 0.1, $"vx = {sim.Balls[0].Velocity.X}");
        Assert.True(sim.Balls[0].Position.X > -2 * R + 0.05);
    }

    [Fact]
    public void StunStopsNearlyDead()
    {
        // A stun reaches the object ball without spin: it keeps (1 - e_b)/2 of its speed.
        var sim = Create("exact", 1.0 / 250, Pocketless, null, "", Ball("cue", -2 * R - 1e-4, 0, 2, 0, 0, 0), Ball("1", 0, 0));
        sim.AdvanceTo(0.004);
        Assert.Equal(EventKind.BallBall, sim.Events[0].Kind);
        Assert.InRange(sim.Balls[0].Velocity.X, 0.0, 0.06);
        Assert.InRange(sim.Balls[1].Velocity.X, 1.9, 1.96);
    }

    [Theory]
    [InlineData(0.5, -1)]
    [InlineData(-0.5, 1)]
    public void MasseCurvesToTheSideOfTheSpin(double side, int expectedSign)
    {
        // Elevated cue, tip to the right (side > 0): the ball curves to the right, i.e. -y when aimed along +x.
        var sim = Create("exact", 1.0 / 250, Pocketless, $$"""{ "speed": 1.5, "aim_deg": 0, "tip": [{{F(side)}}, 0], "elevation_deg": 70 }""", "",
            Ball("cue", -1.0, 0));
        var v0 = sim.Balls[0].Velocity.Normalized();
        var r0 = sim.Balls[0].Position;
        // The slate returns this stroke with e_t 0.39 m/s: it hops 8 mm for 0.08 s, curving only
        // once it lands; by 1 s its sliding has bent the path.
        sim.AdvanceTo(1.0);
        Assert.Contains(sim.Events.AsSpan().ToArray(), e => e.Kind == EventKind.BallAirborne);
        // Offset from the initial line of motion, positive to its left.
        var d = sim.Balls[0].Position - r0;
        double lateral = v0.X * d.Y - v0.Y * d.X;
        Assert.Equal(expectedSign, Math.Sign(lateral));
        Assert.True(Math.Abs(lateral) > 0.05, $"lateral offset {lateral}");
    }

    [Theory]
    [InlineData("eight-ball-break.json")]
    [InlineData("nine-ball-break.json")]
    [InlineData("half-ball-cut.json")]
    [InlineData("bank.json")]
    [InlineData("masse.json")]
    [InlineData("draw.json")]
    public void ExactAgreesWithEventAtEveryStep(string scene)
    {
        var reference = Load(scene, "event");
        RunToRest(reference);
        foreach (double dt in new[] { 1.0 / 30, 1.0 / 250, 1.0 / 1000 })
        {
            var exact = Load(scene, "exact", dt);
            RunToRest(exact);
            Assert.Equal(reference.Events.Count, exact.Events.Count);
            for (int i = 0; i < exact.Balls.Length; i++)
            {
                double d = (exact.Balls[i].Position - reference.Balls[i].Position).Length;
                Assert.True(d <= 1e-6, $"{scene} dt {dt}: ball {exact.Ids[i]} differs by {d:E2} m");
                Assert.Equal(reference.Balls[i].State, exact.Balls[i].State);
            }
        }
    }

    [Fact]
    public void NoTunnellingAtTwelveMetresPerSecondWithBigSteps()
    {
        // At 12 m/s a step of 1/30 s is 0.4 m, seven ball diameters.
        var sim = Create("exact", 1.0 / 30, Pocketless, null, "",
            Ball("cue", -1.0, 0, 12, 0), Ball("1", -0.5, 0.01), Ball("2", 0.3, -0.4));
        for (int k = 0; k < 300 && !sim.IsAtRest; k++)
        {
            sim.Step();
            AssertNoOverlapAndOnTable(sim);
        }
        Assert.Equal(EventKind.BallBall, sim.Events[0].Kind);
        Assert.True(sim.Events.Count > 3);
    }

    [Fact]
    public void BreakKeepsEveryBallOnTheTableWithoutOverlap()
    {
        var sim = Load("eight-ball-break.json", "exact", 1.0 / 30);
        while (!sim.IsAtRest && sim.Time < 60)
        {
            sim.Step();
            AssertNoOverlapAndOnTable(sim);
        }
        Assert.True(sim.IsAtRest);
        Assert.Equal(0, sim.EventCapHits);
    }

    private static void AssertNoOverlapAndOnTable(StandardSimulation sim)
    {
        var balls = sim.Balls;
        double hx = sim.Table.HalfLength, hy = sim.Table.HalfWidth;
        for (int i = 0; i < balls.Length; i++)
        {
            if (balls[i].IsPocketed)
            {
                continue;
            }
            // With pockets a ball may be in a pocket's throat, behind the rail's line.
            double slack = sim.Table.HasPockets ? 0.1 : 1e-9;
            Assert.True(Math.Abs(balls[i].Position.X) <= hx - R + slack, $"ball {sim.Ids[i]} off the table at t={sim.Time}");
            Assert.True(Math.Abs(balls[i].Position.Y) <= hy - R + slack, $"ball {sim.Ids[i]} off the table at t={sim.Time}");
            for (int j = i + 1; j < balls.Length; j++)
            {
                if (balls[j].IsPocketed)
                {
                    continue;
                }
                double d = (balls[i].Position - balls[j].Position).Length;
                Assert.True(d >= 2 * R - 1e-9, $"balls {sim.Ids[i]} and {sim.Ids[j]} overlap by {2 * R - d:E2} m at t={sim.Time}");
            }
        }
    }

    [Fact]
    public void BallRolledIntoACornerIsPocketedThere()
    {
        string table = """{ "preset": "pool-9ft" }""";
        var sim = Create("exact", 1.0 / 250, table, null, "", Ball("cue", 0.9, 0.3, 2, 2 * 0.335 / 0.37));
        RunToRest(sim);
        Assert.Equal(MotionState.Pocketed, sim.Balls[0].State);
        Assert.Equal("foot-left", sim.FeatureName(EventKind.BallPocket, sim.Balls[0].Pocket));
        Assert.Equal(EventKind.BallPocket, sim.Events[sim.Events.Count - 1].Kind);
    }

    [Fact]
    public void ShotParallelToARailNeverTouchesIt()
    {
        var sim = Create("exact", 1.0 / 30, Pocketless, null, "", Ball("cue", -1.0, 0.635 - R, 0.5, 0));
        RunToRest(sim);
        Assert.Equal(0, sim.Events.Count);
    }

    [Fact]
    public void FrozenBallsNeitherStickNorOverlap()
    {
        // Three balls touching in a line: the hit passes through the frozen pair at one instant.
        var sim = Create("exact", 1.0 / 250, Pocketless, null, "",
            Ball("cue", -0.3, 0, 2, 0), Ball("1", 0, 0), Ball("2", 2 * R, 0), Ball("3", 4 * R, 0));
        sim.AdvanceTo(1.0);
        AssertNoOverlapAndOnTable(sim);
        Assert.True(sim.Balls[3].Velocity.X > 1.0, "the last ball of the line takes the hit");
        Assert.Equal(0, sim.EventCapHits);
    }

    [Fact]
    public void GeometryNamesFollowTheConvention()
    {
        var g = TableGeometry.Build(TableSpec.FromPreset("pool-9ft"), R);
        string[] rails = ["head", "foot", "left-head", "left-foot", "right-head", "right-foot"];
        for (int i = 0; i < rails.Length; i++)
        {
            Assert.Equal(rails[i], g.CushionName(g.Segments[i].Feature));
        }
        Assert.Contains("side-left-jaw-head", g.CushionNames);
        Assert.Contains("foot-left-jaw-foot", g.CushionNames);
        Assert.Contains("foot-left-jaw-left", g.CushionNames);
        Assert.Equal(6, g.Pockets.Length);
        Assert.Equal(12, g.Noses.Length);
        // The foot rail faces -x and runs at x = L/2; the left rails are at +y.
        Assert.Equal(-1, g.Segments[1].Normal.X);
        Assert.Equal(1.27, g.Segments[1].Start.X, 12);
        Assert.True(g.Segments[2].Start.Y > 0);
        // Corner mouth: the jaw tips are mouth/sqrt(2) from the corner along each rail.
        var spec = TableSpec.FromPreset("pool-9ft");
        double tipDistance = spec.Pockets[0].Mouth / Math.Sqrt(2);
        Assert.True(g.Segments[0].End.Y < spec.HalfWidth - tipDistance);
        Assert.Empty(TableGeometry.Build(TableSpec.FromPreset("pocketless"), R).Pockets.ToArray());
    }

    [Fact]
    public void RootsHandleDegenerateAndTouchingCases()
    {
        // Quartic with a negligible leading term behaves as the quadratic (t - 1)(t - 2) = t^2 - 3t + 2.
        Assert.Equal(1.0, Polynomial.FirstEntry([2, -3, 1, 0, 1e-30], 10, 0), 12);
        // Linear gap 1 - t enters at 1.
        Assert.Equal(1.0, Polynomial.FirstEntry([1, -1, 0], 10, 0), 12);
        // Constant: never.
        Assert.Equal(double.PositiveInfinity, Polynomial.FirstEntry([1, 0, 0, 0, 0], 10, 0));
        // Touching and separating (gap 0, increasing): no contact.
        Assert.Equal(double.PositiveInfinity, Polynomial.FirstEntry([0, 1, 0.5], 10, 1e-9));
        // Touching and approaching: contact now.
        Assert.Equal(0.0, Polynomial.FirstEntry([0, -1, 0.5], 10, 1e-9));
        // Separates then comes back (gap t(t - 1)(t - 3) ... as t^3 - 4 t^2 + 3 t): re-enters at 3? It is
        // negative on (1, 3), so it enters at 1.
        Assert.Equal(1.0, Polynomial.FirstEntry([0, 3, -4, 1], 10, 1e-9), 12);
        // A quartic with four roots 0.5, 1.5, 2.5, 3.5: (t-.5)(t-1.5)(t-2.5)(t-3.5) enters at 0.5.
        double[] c = [0.5 * 1.5 * 2.5 * 3.5, -(1.5 * 2.5 * 3.5 + 0.5 * 2.5 * 3.5 + 0.5 * 1.5 * 3.5 + 0.5 * 1.5 * 2.5),
            0.5 * 1.5 + 0.5 * 2.5 + 0.5 * 3.5 + 1.5 * 2.5 + 1.5 * 3.5 + 2.5 * 3.5, -(0.5 + 1.5 + 2.5 + 3.5), 1];
        Assert.Equal(0.5, Polynomial.FirstEntry(c, 10, 0), 12);
        Span<double> roots = stackalloc double[4];
        Assert.Equal(4, Polynomial.RealRoots(c, 0, 10, roots));
        Assert.Equal(3.5, roots[3], 12);
        // Tangent graze (gap (t - 1)^2 >= 0) is no entry.
        Assert.Equal(double.PositiveInfinity, Polynomial.FirstEntry([1, -2, 1], 10, 0));
    }

    [Fact]
    public void EulerConvergesToTheExactSolution()
    {
        // First order: while sliding, explicit Euler's position lags by mu_s g dt t / 2, so halving
        // dt halves the error.
        double Error(double dt)
        {
            var euler = Create("euler", dt, BigTable, null, "", Ball("cue", -4.5, 0, 2, 0));
            euler.AdvanceTo(0.2);
            var exact = Create("exact", dt, BigTable, null, "", Ball("cue", -4.5, 0, 2, 0));
            exact.AdvanceTo(0.2);
            return Math.Abs(euler.Balls[0].Position.X - exact.Balls[0].Position.X);
        }
        double e1 = Error(1.0 / 250), e2 = Error(1.0 / 500), e3 = Error(1.0 / 1000);
        Assert.Equal(0.5 * 0.2 * G * 0.2 / 250, e1, 6);
        Assert.InRange(e1 / e2, 1.9, 2.1);
        Assert.InRange(e2 / e3, 1.9, 2.1);
    }

    [Fact]
    public void OrientationIsTrackedOnlyWhenAsked()
    {
        var off = Create("exact", 1.0 / 250, Pocketless, null, "", Ball("cue", 0, 0, 1, 0));
        off.AdvanceTo(0.5);
        Assert.Equal(System.Numerics.Quaternion.Identity, off.Balls[0].Orientation);
        var on = Create("exact", 1.0 / 250, Pocketless, null, "", Ball("cue", 0, 0, 1, 0));
        on.TrackOrientation = true;
        on.AdvanceTo(0.5);
        Assert.NotEqual(System.Numerics.Quaternion.Identity, on.Balls[0].Orientation);
    }

    [Fact]
    public void IdleStepsDoNotAllocate()
    {
        var sim = Load("eight-ball.json");
        sim.Step();
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int k = 0; k < 1000; k++)
        {
            sim.Step();
        }
        Assert.Equal(before, GC.GetAllocatedBytesForCurrentThread());
    }

    [Fact]
    public void MovingStepsDoNotAllocate()
    {
        var sim = Load("eight-ball-break.json");
        for (int k = 0; k < 50; k++)
        {
            sim.Step(); // warm up: the event log's buffer may grow during the break
        }
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int k = 0; k < 200; k++)
        {
            sim.Step();
        }
        Assert.True(GC.GetAllocatedBytesForCurrentThread() - before == 0 || sim.Events.Count > 256,
            $"{GC.GetAllocatedBytesForCurrentThread() - before} bytes allocated");
    }
}
