using Billiards.Core.Physics;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard;

/// <summary>
/// Newton's cradle on the bed: five balls in a line along x, each exactly 2R from the next
/// (frozen), the first (the cue ball) sent head-on into the others at v0 = 2 m/s with no spin.
/// </summary>
public class NewtonsCradleTests
{
    private const double V0 = 2;
    private const int Count = 5;

    private static Simulation Cradle(string integrator, double dt)
    {
        var balls = Enumerable.Range(0, Count).Select(k => Ball(k, -0.5 + 2 * R * k, 0, vx: k == 0 ? V0 : 0));
        return Create(integrator, dt, balls);
    }

    /// <summary>
    /// By hand: a head-on impact of a moving ball on a resting one with e_b = 0.95 leaves the
    /// striker (1 - e)/2 = 0.025 of its speed and gives the struck ball (1 + e)/2 = 0.975 of it.
    /// Head-on without spin the contact does not slip, so ball-ball friction does nothing. The
    /// last ball is struck once, by ball 4 carrying 0.975^3 v0, so it leaves with
    /// 0.975^4 v0 = 0.903687890625 * 2 = 1.80737578125 m/s. (The balls left behind touch and may
    /// re-collide among themselves at the same instant, slowly, but none of that reaches ball 5:
    /// they all end slower than 0.025 v0.) The impact is at t = 0 (the balls already touch), so
    /// no cloth friction acts before it; after it ball 5 slides without spin, so over the first
    /// step its speed drops by exactly mu_s g t (sliding lasts 2 * 1.807 / (7 * 0.2 * 9.81) = 0.263 s,
    /// longer than any step here). Tolerance 1e-9 m/s: round-off of a few products.
    /// </summary>
    [Theory]
    [MemberData(nameof(ExactAndEvent), MemberType = typeof(StabilityKit))]
    public void EventsRunDownTheLineInOrderAndTheLastBallTakesNearlyAllTheSpeed(string integrator, double dt)
    {
        var sim = Cradle(integrator, dt);
        sim.AdvanceTo(dt);
        AssertFinite(sim, "cradle");

        var events = EventsOf(sim, EventKind.BallBall);
        // The first collision of each neighbouring pair (k-1, k), in log order.
        var firsts = Enumerable.Range(1, Count - 1)
            .Select(k => events.FindIndex(e => Math.Min(e.A.Value, e.B.Value) == k - 1 && Math.Max(e.A.Value, e.B.Value) == k))
            .ToList();
        Assert.All(firsts, i => Assert.True(i >= 0, "a neighbouring pair never collided: " + string.Join(", ", events)));
        Assert.Equal(firsts.Order(), firsts);
        // Only neighbours touch, and everything happens at the instant of the first impact, t = 0.
        Assert.All(events, e => Assert.Equal(1, Math.Abs(e.A.Value - e.B.Value)));
        Assert.All(events, e => Assert.Equal(0, e.Time, 1e-12));
        Assert.Equal(V0, events[0].Speed, 1e-12);
        Assert.Equal(0, sim.EventCapHits);

        double t = sim.Time;
        double expected = Math.Pow((1 + 0.95) / 2, Count - 1) * V0 - MuS * G * t; // 1.80737578125 - 1.962 t
        var last = sim.Balls[Index(sim, Count - 1)];
        Assert.True(Math.Abs(last.Velocity.X - expected) <= 1e-9 && Math.Abs(last.Velocity.Y) <= 1e-12,
            $"last ball at t = {t:R}: {Fmt(last.Velocity)}, expected ({expected:R}, 0)");
    }
}
