using Billiards.Core.Physics.Standard;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// The cap on events at one instant (physics-standard-model.md, "Ties and frozen balls"). The
/// engine (EventEngine.MaxEventsPerInstant = 64) counts events at one instant and, past the cap,
/// drops the offending prediction and counts a hit in <see cref="Simulation.EventCapHits"/>.
/// </summary>
/// <remarks>
/// How to force it with a legal scene: a frozen line of n balls, the first moving head-on into
/// the rest. Every pair touches, so every collision happens at t = 0. Resolved one pair at a
/// time, lowest pair first (the engine's tie order), the impulse runs down the line and each
/// new contact sends a ripple back: with e_b = 0.95 the order is (0-1), (1-2), (0-1), (2-3),
/// (1-2), (0-1), (3-4), ... because after (k, k+1) fires, ball k carries 0.025 of what it had,
/// less than the slow ball behind it, which therefore approaches again (worked through with
/// v = 1: 0-1 gives 0.025 / 0.975; 1-2 gives 0.024375 / 0.950625; now ball 0 at 0.025, faster than 0.024375,
/// so 0-1 fires again, and so on). That is 1 + 2 + ... + (n - 1) = n (n - 1) / 2 events at one
/// instant: 10 for the 5-ball cradle (under the cap), 120 for 16 balls (the cue ball and 15),
/// so the 66th event at t = 0 crosses the cap of 64.
/// One catch: with the default R = 0.028575 m, 2R is not a binary fraction, so centres placed
/// 2R apart in doubles have gaps of a few 1e-17 m, and the collisions fall at distinct instants
/// 1e-17 to 1e-11 s apart (checked: never more than a handful at one instant), so no default
/// scene reaches the cap. With R = 1/32 m (a legal override of "R"), 2R = 1/16 and every centre
/// -0.5 + k/16 is exact, so every gap is exactly zero and all contacts fall at t = 0 exactly. This leans on the engine's tie order; an
/// engine that resolved a frozen line in fewer events at one instant would need another scene.
/// </remarks>
public class EventCapTests
{
    private const int LineLength = 16;

    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void AFrozenLineOfSixteenHitsTheCapSaysSoAndStillEndsSanely(string integrator, double dt)
    {
        const double r = 1.0 / 32;
        var parameters = PhysicsParams.Default with { R = r };
        var balls = Enumerable.Range(0, LineLength).Select(k => new BallSetup(new BallId(k), new Vec3(-0.5 + 2 * r * k, 0, r), new Vec3(k == 0 ? 3 : 0, 0, 0), Vec3.Zero));
        var sim = Create(integrator, dt, balls, parameters: parameters);
        sim.AdvanceTo(dt);

        var atOnce = EventsOf(sim, EventKind.BallBall).Where(e => e.Time == 0).ToList();
        Assert.True(sim.EventCapHits > 0,
            $"{atOnce.Count} ball-ball events at t = 0 and no cap hit (cap {64}); expected {LineLength * (LineLength - 1) / 2} events to cross it");
        Assert.True(atOnce.Count >= 64, $"only {atOnce.Count} events at t = 0");

        // Capped or not, the shot must end: finite, on the bed, no overlap, and no energy gained
        // beyond the engine's documented bound: a repeat contact of a pushing pair (the TC model,
        // EventEngine.ContactDuration) leaves at RepeatSeparationSpeed at least, which may add at
        // most m v^2 / 4 (reduced mass m / 2) = 1.06e-6 J; first contacts add nothing.
        double repeatBound = parameters.M * EventEngine.RepeatSeparationSpeed * EventEngine.RepeatSeparationSpeed / 4;
        double startEnergy = KineticEnergy(sim.Balls);
        StepChecked(sim, 60, $"frozen line {integrator} dt {dt:R}", checkOverlap: true, energyTolerance: 1e-12 + repeatBound / startEnergy);
        Assert.True(sim.IsAtRest, "the frozen line did not come to rest by 60 s");
        AssertNoOverlap(sim, "frozen line at rest");
    }

    /// <summary>
    /// Normal shots never hit the cap: a racked (gapped, jittered) 8-ball break at 12 m/s on the
    /// 9 ft pool table, and the 5-ball cradle (10 events at one instant, see the remarks above).
    /// </summary>
    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void NormalShotsNeverHitTheCap(string integrator, double dt)
    {
        var table = Billiards.Core.Table.TableSpec.FromPreset("pool-9ft");
        var rack = Initializer.Rack(new RackSpec(RackGame.EightBall, 7), table, R).Select(b => Ball(b.Id.Value, b.Position.X, b.Position.Y)).ToList();
        var head = Initializer.HeadSpot(table, R);
        rack.Add(Ball(0, head.X, head.Y));
        var brk = Create(integrator, dt, rack, table);
        brk.Strike(new ShotSpec(CueSpeedFor(12), 0));
        brk.AdvanceTo(150);
        Assert.True(brk.IsAtRest);
        Assert.True(EventsOf(brk, EventKind.BallBall).Count > 15, "the break hit almost nothing");
        Assert.Equal(0, brk.EventCapHits);

        var cradle = Create(integrator, dt, Enumerable.Range(0, 5).Select(k => Ball(k, -0.5 + 2 * R * k, 0, vx: k == 0 ? 2 : 0)));
        cradle.AdvanceTo(30);
        Assert.True(cradle.IsAtRest);
        Assert.Equal(0, cradle.EventCapHits);
    }
}
