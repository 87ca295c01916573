using Billiards.App.Game;

namespace Billiards.App.Tests.Game;

public class FixedStepLoopTests
{
    private const double Dt = 1.0 / 250; // the seed's rate, not exact in binary on purpose

    [Fact]
    public void A_frame_runs_the_whole_steps_it_owes_and_keeps_the_rest()
    {
        var loop = new FixedStepLoop(Dt);
        int steps = 0;
        Assert.Equal(2, loop.Advance(0.010, () => steps++)); // 10 ms = 2.5 steps
        Assert.Equal(2, steps);
        Assert.Equal(0.002, loop.Accumulator, 12);
        Assert.Equal(0.5, loop.Alpha, 9);
        Assert.Equal(3, loop.Advance(0.010, () => steps++)); // 2 ms + 10 ms = 3 steps exactly
        Assert.Equal(0, loop.Alpha, 6);
    }

    [Fact]
    public void Rounding_does_not_lose_a_step()
    {
        var loop = new FixedStepLoop(Dt);
        Assert.Equal(5, loop.Advance(0.020, () => { })); // 0.02 - 4 * 0.004 is a hair under 0.004 in binary
        Assert.True(loop.Alpha is >= 0 and < 1e-6);
    }

    [Fact]
    public void Frame_time_is_clamped_at_500_ms()
    {
        var loop = new FixedStepLoop(Dt);
        Assert.Equal(125, loop.Advance(3.0, () => { })); // a 3 s stall counts as 0.5 s = 125 steps
        Assert.Equal(0, loop.Accumulator, 9);
        Assert.Equal(125, loop.Steps);
    }

    [Fact]
    public void Negative_frame_time_runs_nothing()
    {
        var loop = new FixedStepLoop(Dt);
        Assert.Equal(0, loop.Advance(-1, () => { }));
        Assert.Equal(0, loop.Accumulator);
    }

    [Fact]
    public void Pause_freezes_the_accumulator_and_single_step_runs_exactly_one()
    {
        var loop = new FixedStepLoop(Dt);
        loop.Advance(0.006, () => { });            // 1 step, 2 ms left: alpha 0.5
        loop.TogglePause();
        Assert.Equal(0, loop.Advance(1.0, () => { }));
        Assert.Equal(0.5, loop.Alpha, 9);
        loop.RequestSingleStep();
        Assert.Equal(1, loop.Advance(0.5, () => { }));
        Assert.Equal(0, loop.Advance(0.5, () => { })); // one request, one step
        Assert.Equal(0.5, loop.Alpha, 9);
        loop.TogglePause();
        loop.RequestSingleStep();                  // ignored while running
        Assert.Equal(0, loop.Advance(0.001, () => { }));
        Assert.Equal(1, loop.Advance(0.001, () => { })); // 2 + 1 + 1 ms = one step
    }

    [Fact]
    public void The_step_must_be_positive() =>
        Assert.Throws<ArgumentOutOfRangeException>(() => new FixedStepLoop(0));
}

public class FrameInterpolationTests
{
    [Fact]
    public void Balls_are_drawn_between_the_previous_and_the_current_step_by_alpha()
    {
        // The scene's opening shot sends the cue ball along +x at 2 m/s; the fake keeps that speed.
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        game.Simulation.Deceleration = 0;
        double x0 = -0.635, dt = TestScenes.Dt;
        var frame = game.Frame(0.010);             // 0.010 / (1/256) = 2.56: 2 steps, alpha 0.56
        Assert.Equal(2, game.Simulation.StepCount);
        Assert.Equal(0.56, game.Host.Loop.Alpha, 9);
        var cue = frame.Balls.Single(b => PoolBalls.IsCue(b.Id));
        // previous = x0 + 2 dt * 1, current = x0 + 2 dt * 2, drawn = x0 + 2 dt * 1.56
        Assert.Equal(x0 + 2 * dt * 1.56, cue.Position.X, 5);
        Assert.Equal((float)(x0 + 2 * 2 * dt), (float)game.Simulation.State[0].Position.X, 6);
    }

    [Fact]
    public void At_rest_the_drawn_position_is_the_simulated_one()
    {
        using var game = new TestGame(TestScenes.TwoBalls(withShot: true));
        game.RunUntilRest();
        var frame = game.Frame(0.001);
        var cue = frame.Balls.Single(b => PoolBalls.IsCue(b.Id));
        Assert.Equal((float)game.Simulation.State[0].Position.X, cue.Position.X, 6);
    }
}
