using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Where a ball in the air comes down decides what it lands on (docs/flight.md): inside the
/// cushion noses the bed, over a cushion or a rail its top (a bounce, or off the table), over a
/// hole the pocket, beyond the rails the floor (off the table). Issue 40's two strokes, which
/// used to end at rest metres off the table and inside a cushion, and their kin.
/// </summary>
public class LandingTests
{
    // Issue 40: the cue ball bounces three times and used to roll on to [3.409, 8.658] m.
    private const string IntoTheCorner = """{"format":"billiards-scene/1","table":{"preset":"pool-9ft"},"physics":{"model":"standard","integrator":"exact"},"rack":{"game":"nine-ball","seed":680834572},"balls":[{"id":"cue","position":[0.5400217506239174,0.258553726067873]}],"shot":{"speed":6.249385358881851,"aim_deg":23.71305259117534,"tip":[-0.4413358430180669,0.028494107569491733],"elevation_deg":41.55720854250585}}""";

    // Issue 40: the cue ball meets a jaw in the air and used to come to rest at y = 0.653, inside the cushion.
    private const string OntoTheJaw = """{"format":"billiards-scene/1","table":{"preset":"pool-9ft"},"physics":{"model":"standard","integrator":"exact"},"rack":{"game":"eight-ball","seed":743559151},"balls":[{"id":"cue","position":[0.7881793286354533,0.3704239463773784]}],"shot":{"speed":4.10012175114831,"aim_deg":41.196625205314064,"tip":[0.05678980290264576,0.46144913607861715],"elevation_deg":58.17901416596911}}""";

    private static Simulation RunScene(string json, string integrator)
    {
        var scene = SceneLoader.Parse(json.Replace("\"exact\"", $"\"{integrator}\"", StringComparison.Ordinal), "issue-40.json");
        var outcome = SimulationRunner.Run(scene, new RunOptions());
        Assert.True(outcome.Simulation.IsAtRest);
        return outcome.Simulation;
    }

    private static SimEvent[] EventsOf(Simulation sim, int ball) =>
        [.. sim.Events.AsSpan().ToArray().Where(e => e.A.Value == ball || e.B.Value == ball)];

    /// <summary>
    /// Issue 40's two strokes, as the contract reads them now (the tip in the cue's frame, the
    /// measured defaults): each cue ball ends where its flight decides, at rest on the bed, in a
    /// pocket or off the table, never outside the table or inside a cushion; exact and event agree
    /// to 1e-9 in every event and every ball. (Under the tip on the ball's face, with which they
    /// were found, the first dropped into the foot-left corner from the air and the second came to
    /// rest on the foot-left jaw; the tossed balls below hold those landings on every preset.)
    /// </summary>
    [Theory]
    [InlineData(IntoTheCorner, "into the corner")]
    [InlineData(OntoTheJaw, "onto the jaw")]
    public void IssueFortysStrokesEndOnTheBedInAPocketOrOffTheTableWithEitherIntegrator(string scene, string where)
    {
        var exact = RunScene(scene, Integrators.Exact);
        var reference = RunScene(scene, Integrators.Event);
        AssertSameRun(reference, exact);
        Assert.Contains(EventsOf(exact, 0), e => e.Kind == EventKind.BallAirborne);
        Assert.Contains(exact.Balls[0].State, new[] { MotionState.Stationary, MotionState.Pocketed, MotionState.OffTable });
        AssertAtRestOnTheTable(exact, where);
    }

    // Nothing but the ball's own way through the air: no cushion, no landing after it leaves the bed.
    private static void AssertNoContactAfterTheStrike(Simulation sim, string where)
    {
        var events = sim.Events.AsSpan().ToArray();
        Assert.False(events.Any(e => e.Kind is EventKind.BallCushion or EventKind.BallTable),
            $"{where}: {string.Join("; ", events.Select(e => $"{e.Time:0.####} {e.Kind} {e.Feature}"))}");
    }

    private static void AssertSameRun(Simulation reference, Simulation exact)
    {
        var a = reference.Events.AsSpan().ToArray();
        var b = exact.Events.AsSpan().ToArray();
        Assert.Equal(a.Select(e => (e.Kind, e.A, e.B, e.Feature)), b.Select(e => (e.Kind, e.A, e.B, e.Feature)));
        for (int k = 0; k < a.Length; k++)
        {
            Assert.Equal(a[k].Time, b[k].Time, 1e-9);
        }
        for (int i = 0; i < reference.Balls.Length; i++)
        {
            Assert.Equal(reference.Balls[i].State, exact.Balls[i].State);
            AssertVec(reference.Balls[i].Position, exact.Balls[i].Position, 1e-9, $"ball {reference.Ids[i]}");
        }
    }

    public static TheoryData<string, string> PresetsAndIntegrators()
    {
        var data = new TheoryData<string, string>();
        foreach (string preset in TableSpec.PresetNames)
        {
            foreach (string integrator in new[] { Integrators.Exact, Integrators.Event, Integrators.Euler })
            {
                data.Add(preset, integrator);
            }
        }
        return data;
    }

    // The ball tossed from `start` on the bed at 3 m/s up, aimed to come down to the rails' top over `target`.
    private static (Simulation Sim, double Down) Toss(TableSpec table, string integrator, Vec3 start, Vec3 target)
    {
        const double Up = 3;
        double down = (Up + Math.Sqrt(Up * Up - 2 * G * table.RailHeight)) / G;
        var v = (target - start).XY / down;
        double dt = integrator == Integrators.Euler ? 1e-4 : Dt250;
        var sim = Create(integrator, dt, [new BallSetup(new BallId(0), start with { Z = R }, v with { Z = Up }, Vec3.Zero)], table);
        sim.AdvanceTo(60);
        Assert.True(sim.IsAtRest);
        return (sim, down);
    }

    /// <summary>
    /// On every preset and with every integrator, a ball tossed from the bed to come down over the
    /// middle of each rail's cushion, half a radius inside its nose (the ball overlaps the cushion
    /// there), first meets that cushion's top (a ball-cushion contact of that rail) at the moment it
    /// comes down to the rails' top, never the bed there; it ends on the bed, or off the table.
    /// </summary>
    [Theory]
    [MemberData(nameof(PresetsAndIntegrators))]
    public void ABallComingDownOverACushionLandsOnItsTop(string preset, string integrator)
    {
        var table = TableSpec.FromPreset(preset);
        var geometry = TableGeometry.Build(table, R);
        foreach (int rail in new[] { 0, 1, 3, 4 })
        {
            var face = geometry.Segments[rail];
            var middle = (face.Start + face.End) * 0.5;
            var target = middle + face.Normal * (0.5 * R);
            var (sim, down) = Toss(table, integrator, middle + face.Normal * 0.5, target);
            var first = sim.Events.AsSpan().ToArray().First(e => e.Time > 0 && e.Kind != EventKind.BallAirborne);
            string where = $"{preset}, {integrator}, {geometry.CushionName(rail)}";
            Assert.True(first.Kind == EventKind.BallCushion && first.Feature == face.Feature, $"{where}: first met {first.Kind} {first.Feature}");
            Assert.Equal(down, first.Time, integrator == Integrators.Euler ? 1e-3 : 1e-9);
            AssertAtRestOnTheTable(sim, where);
        }
    }

    /// <summary>
    /// A ball tossed to come down beyond the rails' outer edge is off the table there, at the
    /// moment it comes down to the rails' top; one tossed to come down over a pocket's capture
    /// circle drops into that pocket then; one tossed to come down inside the noses lands on the bed
    /// after 2 vz / g, where the parabola says. Every preset, every integrator.
    /// </summary>
    [Theory]
    [MemberData(nameof(PresetsAndIntegrators))]
    public void ABallComingDownBeyondTheRailsOverAHoleOrOnTheBedMeetsWhatIsThere(string preset, string integrator)
    {
        var table = TableSpec.FromPreset(preset);
        var geometry = TableGeometry.Build(table, R);
        double tolerance = integrator == Integrators.Euler ? 1e-3 : 1e-9;
        string where = $"{preset}, {integrator}";

        var floor = new Vec3(table.HalfLength + table.RailWidth + 0.05, 0.1, 0);
        var (offSim, down) = Toss(table, integrator, new Vec3(table.HalfLength - 0.4, 0.1, 0), floor);
        var off = Assert.Single(offSim.Events.AsSpan().ToArray(), e => e.Kind == EventKind.BallOffTable);
        Assert.Equal(down, off.Time, tolerance);
        Assert.Equal(MotionState.OffTable, offSim.Balls[0].State);
        AssertVec(floor with { Z = table.RailHeight + R }, offSim.Balls[0].Position, integrator == Integrators.Euler ? 2e-3 : 1e-9, $"{where}: off the table");
        AssertNoContactAfterTheStrike(offSim, $"{where}: beyond the rails");

        foreach (var hole in geometry.Pockets)
        {
            var mouth = table.Pockets[hole.Pocket].MouthMiddle(table);
            var (sim, _) = Toss(table, integrator, mouth - table.Pockets[hole.Pocket].Outward * 0.4, hole.Centre);
            Assert.True(sim.Balls[0].IsPocketed && sim.Balls[0].Pocket == hole.Pocket, $"{where}: over pocket {hole.Pocket} ended {sim.Balls[0].State}");
            AssertNoContactAfterTheStrike(sim, $"{where}: over pocket {hole.Pocket}");
        }

        var bed = new Vec3(0.3, -0.2, 0);
        var (bedSim, _) = Toss(table, integrator, new Vec3(-0.3, 0.1, 0), bed);
        var landing = bedSim.Events.AsSpan().ToArray().First(e => e.Time > 0 && e.Kind != EventKind.BallAirborne);
        Assert.Equal(EventKind.BallTable, landing.Kind);
        Assert.Equal(2 * 3 / G, landing.Time, tolerance);
        AssertAtRestOnTheTable(bedSim, $"{where}: on the bed");
    }
}
