using System.Diagnostics;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;

namespace Billiards.Core.Scenes;

/// <summary>Options of a headless run.</summary>
/// <param name="Until">Stop at this time (s) even if balls still move; null runs until everything rests.</param>
/// <param name="SampleDt">Record every ball's position every this many seconds; null records none.</param>
/// <param name="MaxTime">Safety limit (s) when <paramref name="Until"/> is null.</param>
public sealed record RunOptions(double? Until = null, double? SampleDt = null, double MaxTime = 600);

/// <summary>Positions of every ball at one time, for trajectories and replays.</summary>
/// <param name="Time">Simulated time of the sample (s).</param>
/// <param name="Positions">Ball centres (m), index-aligned with <see cref="Simulation.Ids"/>.</param>
public sealed record Sample(double Time, Vec3[] Positions);

/// <summary>What a headless run produced: the final simulation, samples and its wall time.</summary>
/// <param name="Simulation">The simulation in its final state, with its events.</param>
/// <param name="Samples">Position samples (empty without <see cref="RunOptions.SampleDt"/>).</param>
/// <param name="WallMilliseconds">Wall-clock time of the run (ms).</param>
/// <param name="AtRest">True when every ball came to rest.</param>
public sealed record RunOutcome(Simulation Simulation, IReadOnlyList<Sample> Samples, double WallMilliseconds, bool AtRest);

/// <summary>Runs a scene headless: create, strike, advance to rest (or a time), sample.</summary>
public static class SimulationRunner
{
    /// <summary>Runs the scene with the options.</summary>
    public static RunOutcome Run(Scene scene, RunOptions options)
    {
        var clock = Stopwatch.StartNew();
        var sim = SimulationFactory.Create(scene);
        if (scene.Shot is { } shot)
        {
            sim.Strike(shot);
        }
        double limit = options.Until ?? options.MaxTime;
        var samples = new List<Sample>();
        if (options.SampleDt is { } sampleDt)
        {
            for (long k = 0; k * sampleDt <= limit + 1e-12; k++)
            {
                sim.AdvanceTo(k * sampleDt);
                samples.Add(new Sample(sim.Time, Positions(sim)));
                if (sim.IsAtRest)
                {
                    break;
                }
            }
        }
        sim.AdvanceTo(limit);
        return new RunOutcome(sim, samples, clock.Elapsed.TotalMilliseconds, sim.IsAtRest);
    }

    private static Vec3[] Positions(Simulation sim)
    {
        var balls = sim.Balls;
        var result = new Vec3[balls.Length];
        for (int i = 0; i < balls.Length; i++)
        {
            result[i] = balls[i].Position;
        }
        return result;
    }
}
