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
public sealed record RunOutcome(Simulation Simulation, IReadOnlyList<Sample> Samples, double WallMilliseconds, bool AtRest)
{
    /// <summary>The referee's ruling on the shot, for a scene with a game block; otherwise null.</summary>
    public Rules.Ruling? Ruling { get; init; }
}

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
        var ruling = Judge(scene, sim);
        return new RunOutcome(sim, samples, clock.Elapsed.TotalMilliseconds, sim.IsAtRest) { Ruling = ruling };
    }

    /// <summary>
    /// The referee's ruling on the scene's shot once <paramref name="sim"/> has run it, or null for
    /// a scene without a game block. With ball in hand (and on the break) the scene's cue ball is
    /// where the shooter placed it.
    /// </summary>
    public static Rules.Ruling? Judge(Scene scene, Simulation sim)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(sim);
        if (scene.Game is not { } game)
        {
            return null;
        }
        if (game.Shot == 0 || game.BallInHand != Rules.BallInHand.None)
        {
            var cue = scene.Balls.FirstOrDefault(b => b.Id.IsCue);
            game = game with { Placement = cue?.Position };
        }
        var referee = Rules.Referee.For(game.Rules, scene.Table, scene.BallRadius);
        return referee.Judge(game, ShotRecord.LastShot(sim, scene.Shot));
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
