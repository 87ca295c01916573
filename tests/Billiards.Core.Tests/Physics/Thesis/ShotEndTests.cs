using System.Numerics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using static Billiards.Core.Tests.Thesis.ThesisKit;

namespace Billiards.Core.Tests.Thesis;

/// <summary>Seed 4.3.1: the stop rule and the end-of-shot rules (cue ball respot, game reset).</summary>
public class ShotEndTests
{
    private static int RunToRest(PhysicsEngine engine, int limit = 100_000)
    {
        int steps = 0;
        while (!engine.IsAtRest && steps < limit)
        {
            engine.CalculatePhysics();
            steps++;
        }
        Assert.True(engine.IsAtRest);
        return steps;
    }

    [Fact]
    public void The_shot_ends_when_the_summed_speed_drops_below_half_a_centimetre_per_second()
    {
        var ball = At(1, 0, 0, vx: 10);
        var engine = Engine("thesis", ball);
        int steps = RunToRest(engine);
        // After n steps v = 10 * 0.9965^n; first below 0.5 at n > ln(0.05) / ln(0.9965) = 854.4.
        Assert.Equal(855, steps);
        Assert.Equal(Vector3.Zero, ball.Velocity);
        // x = sum over k < 855 of 10 * 0.9965^k / 250 = 0.04 (1 - 0.9965^855) / 0.0035.
        double x = 0.04 * (1 - Math.Pow(0.9965, 855)) / 0.0035;
        Assert.Equal(x, ball.Position.X, 1e-3);
        Assert.Equal(ShotEnd.Rested, engine.LastShotEnd);
    }

    [Fact]
    public void A_pocketed_cue_ball_goes_back_to_its_start()
    {
        // Straight at the foot-right pocket centre (124.5, 65.5) along 45 deg: it meets the test
        // circle 3.5 cm inside both jaws' triangles, so nothing deflects it.
        var start = new Vector3(110, Y, 51);
        var cue = new Ball(0, start) { IsCue = true, Velocity = 200 * Vector3.Normalize(new Vector3(1, 0, 1)) };
        var other = At(1, -50, 0);
        var engine = Engine("thesis", cue, other);
        RunToRest(engine);
        Assert.Equal(ShotEnd.CueBallRespotted, engine.LastShotEnd);
        Assert.Equal(start, cue.Position);
        Assert.Equal(-1, cue.Pocket);
        Assert.False(cue.IsPocketed);
        Assert.Equal(new Vector3(-50, Y, 0), other.Position);
        // The drop is still in the log.
        var drop = engine.Events!.AsSpan().ToArray().Single(e => e.Kind == EventKind.BallPocket);
        Assert.Equal(0, drop.A.Value);
        Assert.Equal(5, drop.Feature);
    }

    [Fact]
    public void Without_the_seed_s_end_of_shot_rules_a_pocketed_cue_ball_stays_in_its_pocket()
    {
        // The shot above, for a game whose referee decides: the engine leaves the ball where it dropped.
        var start = new Vector3(110, Y, 51);
        var cue = new Ball(0, start) { IsCue = true, Velocity = 200 * Vector3.Normalize(new Vector3(1, 0, 1)) };
        var other = At(1, -50, 0);
        var engine = Engine("thesis", cue, other);
        engine.SeedEndOfShotRules = false;
        RunToRest(engine);
        Assert.Equal(ShotEnd.Rested, engine.LastShotEnd);
        Assert.True(cue.IsPocketed);
        Assert.Equal(5, cue.Pocket);
        Assert.NotEqual(start, cue.Position);
    }

    [Fact]
    public void A_pocketed_cue_ball_goes_to_the_nearest_free_point_when_a_ball_lies_on_its_start()
    {
        // As above, but once the cue ball is on its way another ball is put on its start: the
        // seed put the cue ball back onto it anyway, leaving them overlapping at rest.
        var start = new Vector3(110, Y, 51);
        var cue = new Ball(0, start) { IsCue = true, Velocity = 200 * Vector3.Normalize(new Vector3(1, 0, 1)) };
        var other = At(1, -50, 0);
        var engine = Engine("thesis", cue, other);
        for (int k = 0; k < 10; k++)
        {
            engine.CalculatePhysics();
        }
        other.Position = start;
        RunToRest(engine);
        Assert.Equal(ShotEnd.CueBallRespotted, engine.LastShotEnd);
        Assert.Equal(start, other.Position);
        Assert.False(cue.IsPocketed);
        // Clear of the other ball, and the nearest such point to within the search's 0.1 cm rings
        // (plus its 0.01 cm margin): one diameter from the start.
        float distance = Vector3.Distance(cue.Position, start);
        Assert.InRange(distance, PhysicsEngine.BallDiameter, PhysicsEngine.BallDiameter + 0.12f);
        Assert.Equal(Y, cue.Position.Y);
        // On the bed, a radius inside the noses.
        Assert.InRange(Math.Abs(cue.Position.X), 0, engine.Table.HalfLength - PhysicsEngine.BallRadius);
        Assert.InRange(Math.Abs(cue.Position.Z), 0, engine.Table.HalfWidth - PhysicsEngine.BallRadius);
    }

    [Fact]
    public void A_pocketed_8_ball_resets_the_game()
    {
        var cue = At(0, -60, 0);
        var one = At(1, 0, 20, vx: 40);
        var eightStart = new Vector3(110, Y, 51);
        var eight = new Ball(8, eightStart) { Velocity = 200 * Vector3.Normalize(new Vector3(1, 0, 1)) };
        var engine = Engine("thesis", cue, one, eight);
        engine.Queue.EX = 1;
        RunToRest(engine);
        Assert.Equal(ShotEnd.GameReset, engine.LastShotEnd);
        Assert.Equal(new Vector3(-60, Y, 0), cue.Position);
        Assert.Equal(new Vector3(0, Y, 20), one.Position); // it had rolled on; it is back
        Assert.Equal(eightStart, eight.Position);
        Assert.Equal(-1, eight.Pocket);
        Assert.All([cue, one, eight], b => Assert.Equal(Vector3.Zero, b.Velocity));
        Assert.Equal(0, engine.Queue.EX);
        Assert.Contains(engine.Events!.AsSpan().ToArray(), e => e.Kind == EventKind.BallPocket && e.A.Value == 8);
    }
}
