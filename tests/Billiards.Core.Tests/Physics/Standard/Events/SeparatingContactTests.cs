using Billiards.Core.Physics;
using Billiards.Core.Tests.Physics.Standard;
using static Billiards.Core.Tests.Physics.Standard.StabilityKit;

namespace Billiards.Core.Tests.Physics.Standard.Events;

/// <summary>
/// A touching pair that is separating is not a collision: two balls exactly 2R apart, one
/// moving away from the other (straight away, and at 60 deg off the line of centres, still
/// opening the gap). Its slip is along its velocity (no spin), so it keeps going away in a
/// straight line; the gap only grows, and no ball-ball event may be logged.
/// </summary>
public class SeparatingContactTests
{
    [Theory]
    [MemberData(nameof(AllIntegrators), MemberType = typeof(StabilityKit))]
    public void TouchingPairMovingApartLogsNoCollision(string integrator, double dt)
    {
        foreach (double angleDeg in new[] { 180.0, 120.0 })
        {
            double a = angleDeg * Math.PI / 180;
            // Ball 1 sits at +2R on x; the cue ball leaves along (cos a, sin a), whose x part is negative.
            var sim = Create(integrator, dt, [Ball(0, 0, 0, Math.Cos(a), Math.Sin(a)), Ball(1, 2 * R, 0)]);
            StepChecked(sim, 1, $"separating {angleDeg} deg");
            Assert.Empty(EventsOf(sim, EventKind.BallBall));
            AssertVec(new Billiards.Core.Mathematics.Vec3(2 * R, 0, R), sim.Balls[1].Position, 0, "sim.Balls[1].Position");
            Assert.True((sim.Balls[0].Position - sim.Balls[1].Position).Length > 2 * R + 0.1, "the balls did not separate");
        }
    }
}
