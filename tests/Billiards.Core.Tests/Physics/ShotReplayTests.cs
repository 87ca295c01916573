using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

namespace Billiards.Core.Tests.Physics;

/// <summary>
/// A shot played again from its snapshot at the strike (the instant replay): it passes through the
/// states the game's fixed steps gave, bit for bit, at any time asked, forwards or backwards, and
/// ends where the shot ended; its events and paths are the shot's.
/// </summary>
public class ShotReplayTests
{
    public static TheoryData<string, string, string> Breaks => SimulationKit.Breaks;

    // The game's way: one AdvanceTo of one step per tick, from the strike until every ball rests.
    private static (Simulation Sim, SimulationSnapshot AtStrike, List<BallState[]> Steps, List<double> Times) PlayAsTheWindow(Scene scene)
    {
        var sim = SimulationFactory.Create(scene);
        sim.TrackOrientation = true;
        sim.Strike(scene.Shot!);
        var atStrike = sim.CreateSnapshot();
        var steps = new List<BallState[]> { sim.Balls.ToArray() };
        var times = new List<double> { 0 };
        double start = sim.Time;
        while (!sim.IsAtRest)
        {
            sim.AdvanceTo(sim.Time + sim.Dt);
            steps.Add(sim.Balls.ToArray());
            times.Add(sim.Time - start);
        }
        return (sim, atStrike, steps, times);
    }

    private static void AssertSame(IReadOnlyList<BallState> expected, ReadOnlySpan<BallState> actual, string because)
    {
        Assert.Equal(expected.Count, actual.Length);
        for (int i = 0; i < actual.Length; i++)
        {
            // Bit for bit: position, velocity, spin, orientation, state.
            Assert.True(expected[i].Equals(actual[i]), $"{because}: ball {i} differs");
        }
    }

    [Theory]
    [MemberData(nameof(Breaks))]
    public void TheReplayPassesThroughTheShotsStepsBitForBitInAnyOrderAndEndsWhereItEnded(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var (sim, atStrike, steps, times) = PlayAsTheWindow(scene);
        var replay = new ShotReplay(sim, atStrike);

        Assert.Equal(times[^1], replay.Duration, 12);
        AssertSame(steps[^1], [.. replay.Final], "the end");
        // Forwards, then back and forth (restoring checkpoints), then the end again.
        int n = steps.Count;
        int[] order = [0, 1, n / 7, n / 3, n / 2, n / 5, 2, n - 1, n / 4, n / 4 + 1, 0, n - 2];
        foreach (int k in order)
        {
            replay.Seek(times[k]);
            Assert.Equal(1, replay.Alpha);
            AssertSame(steps[k], replay.Current, $"step {k} of {n}");
        }
        // Between two steps: the two steps' states with the share of the way.
        int m = n / 3;
        replay.Seek((times[m] + (3 * times[m + 1])) / 4);
        AssertSame(steps[m], replay.Previous, "the step before");
        AssertSame(steps[m + 1], replay.Current, "the step after");
        Assert.InRange(replay.Alpha, 0.74, 0.76);
        // The simulation the replay was made from is not touched.
        AssertSame(steps[^1], sim.Balls, "the shot's own simulation");
    }

    [Fact]
    public void TheEventsMarksAndPathsAreTheShots()
    {
        var scene = SimulationKit.Load("eight-ball-break.json", "standard", "exact");
        var (sim, atStrike, steps, _) = PlayAsTheWindow(scene);
        var replay = new ShotReplay(sim, atStrike);

        var shotEvents = sim.Events.AsSpan().ToArray().Where(e => e.Kind != EventKind.CueStrike).ToList();
        Assert.Equal(shotEvents, replay.Events);
        var collisions = shotEvents.Where(e => e.Kind is EventKind.BallBall or EventKind.BallCushion or EventKind.BallPocket).ToList();
        Assert.Equal(collisions.Count, replay.Marks.Count);
        double start = shotEvents[0].Time - replay.EventTime(shotEvents[0]);
        for (int k = 0; k < collisions.Count; k++)
        {
            Assert.Equal(collisions[k].Time - start, replay.Marks[k].Time, 12);
        }
        // Stepping by event visits every collision's time in order, and back again.
        var visited = new List<double>();
        for (double? t = replay.NextEvent(-1); t is double at; t = replay.NextEvent(at))
        {
            visited.Add(at);
        }
        Assert.Equal(replay.Marks.Select(m => m.Time).Distinct(), visited);
        Assert.Equal(visited[^2], replay.PreviousEvent(visited[^1]));
        Assert.Null(replay.PreviousEvent(visited[0]));

        // The first contact is the cue ball on the rack: its mark lies between the two balls, a ball apart from each.
        var first = replay.Marks[0];
        Assert.Equal(EventKind.BallBall, first.Kind);
        replay.Seek(first.Time);
        var cue = replay.Current[replay.Ids.ToList().IndexOf(PoolBalls.Cue)].Position;
        Assert.InRange((first.Position - cue).LengthXY, replay.BallRadius * 0.9, replay.BallRadius * 1.2);

        // Each path starts where the ball was at the strike, ends where it rests, and its times increase.
        for (int i = 0; i < replay.Ids.Count; i++)
        {
            var path = replay.Paths[i];
            Assert.Equal(steps[0][i].Position, path[0].Position);
            if (!steps[^1][i].IsOutOfPlay)
            {
                Assert.Equal(steps[^1][i].Position, path[^1].Position);
            }
            for (int p = 1; p < path.Count; p++)
            {
                Assert.True(path[p].Time >= path[p - 1].Time, $"ball {replay.Ids[i]}: point {p} goes back in time");
            }
        }
        // The cue ball moved, and its path is a few straight runs, not a point per step.
        var cuePath = replay.Paths[replay.Ids.ToList().IndexOf(PoolBalls.Cue)];
        Assert.InRange(cuePath.Count, 3, steps.Count / 4);
    }

    [Theory]
    [MemberData(nameof(Breaks))]
    public void RunToRestTheReplayEndsBitForBitWhereTheOneCallEndedAndShowsAnyTimeTheSameWhateverCameBefore(string file, string model, string integrator)
    {
        var scene = SimulationKit.Load(file, model, integrator);
        var sim = SimulationFactory.Create(scene);
        sim.Strike(scene.Shot!);
        var atStrike = sim.CreateSnapshot();
        double start = sim.Time;
        Billiards.Core.Rules.Match.RunToRest(sim);
        var end = sim.Balls.ToArray();
        var replay = new ShotReplay(sim, atStrike, Billiards.Core.Rules.Match.MaxShotTime, ShotStepping.ToRest);

        // Only the event integrator's run depends on where it stops: the others step to rest as by ticks.
        Assert.Equal(integrator == Integrators.Event ? ShotStepping.ToRest : ShotStepping.Ticks, replay.Stepping);
        Assert.Equal(sim.Time - start, replay.Duration, 12);
        for (int i = 0; i < end.Length; i++)
        {
            Assert.Equal(end[i].Position, replay.Final[i].Position);
            Assert.Equal(end[i].Velocity, replay.Final[i].Velocity);
            Assert.Equal(end[i].State, replay.Final[i].State);
        }
        replay.Seek(replay.Duration);
        for (int i = 0; i < end.Length; i++)
        {
            Assert.Equal(end[i].Position, replay.Current[i].Position);
        }
        // A time looks the same reached from before it or from after it.
        double t = replay.Duration / 3;
        replay.Seek(t);
        var forwards = replay.Current.ToArray();
        replay.Seek(replay.Duration * 0.9);
        replay.Seek(0.01);
        replay.Seek(t);
        for (int i = 0; i < end.Length; i++)
        {
            Assert.Equal(forwards[i].Position, replay.Current[i].Position);
        }
        // Run by its events, a collision's mark lies exactly where its ball is shown at that time.
        if (replay.Stepping != ShotStepping.ToRest)
        {
            return;
        }
        var mark = replay.Marks.First(m => m.Kind == EventKind.BallCushion);
        replay.Seek(mark.Time);
        var ball = replay.Current[replay.Ids.ToList().IndexOf(mark.Ball)].Position;
        Assert.True((ball - mark.Position).Length < 1e-6, $"{ball} against {mark.Position}");
    }
}
