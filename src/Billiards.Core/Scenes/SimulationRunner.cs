using System.Diagnostics;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;

namespace Billiards.Core.Scenes;

/// <summary>What ended a headless run; results write it as <c>stats.stop</c>.</summary>
public enum StopReason
{
    /// <summary>Every ball came to rest ("rest").</summary>
    Rest,
    /// <summary>The requested time was reached ("until").</summary>
    Until,
    /// <summary>The bound on simulated time was reached without rest ("max-time").</summary>
    MaxTime,
    /// <summary>The bound on the number of events was reached ("max-events").</summary>
    MaxEvents,
    /// <summary>The bound on wall-clock time was reached ("wall-clock").</summary>
    WallClock,
}

/// <summary>Options of a headless run, with the bounds every run has.</summary>
/// <param name="Until">Stop at this time (s) even if balls still move; null runs until everything rests. At most <see cref="RunOptions.MaxUntil"/>.</param>
/// <param name="SampleDt">Record every ball's position every this many seconds; null records none.</param>
/// <param name="MaxTime">Bound on simulated time (s) when <paramref name="Until"/> is null.</param>
/// <param name="MaxEvents">Bound on the number of events of the run.</param>
/// <param name="MaxWallSeconds">Bound on the wall-clock time of the run (s).</param>
public sealed record RunOptions(double? Until = null, double? SampleDt = null, double MaxTime = 600, int MaxEvents = RunOptions.DefaultMaxEvents, double MaxWallSeconds = RunOptions.DefaultMaxWallSeconds)
{
    /// <summary>The largest accepted <see cref="Until"/> (s): one hour of simulated time.</summary>
    public const double MaxUntil = 3600;

    /// <summary>Default bound on events: far above any real shot (a break has about 100).</summary>
    public const int DefaultMaxEvents = 200_000;

    /// <summary>Default bound on wall-clock time (s).</summary>
    public const double DefaultMaxWallSeconds = 60;
}

/// <summary>Positions of every ball at one time, for trajectories and replays.</summary>
/// <param name="Time">Simulated time of the sample (s).</param>
/// <param name="Positions">Ball centres (m), index-aligned with <see cref="Simulation.Ids"/>.</param>
public sealed record Sample(double Time, Vec3[] Positions);

/// <summary>What a headless run produced: the final simulation, samples and its wall time.</summary>
/// <param name="Simulation">The simulation in its final state, with its events.</param>
/// <param name="Samples">Position samples (empty without <see cref="RunOptions.SampleDt"/>).</param>
/// <param name="WallMilliseconds">Wall-clock time of the run (ms).</param>
/// <param name="AtRest">True when every ball came to rest.</param>
/// <param name="Stop">Which bound ended the run.</param>
public sealed record RunOutcome(Simulation Simulation, IReadOnlyList<Sample> Samples, double WallMilliseconds, bool AtRest, StopReason Stop = StopReason.Rest)
{
    /// <summary>The referee's ruling on the shot, for a scene with a game block; otherwise null.</summary>
    public Rules.Ruling? Ruling { get; init; }
}

/// <summary>Runs a scene headless: create, strike, advance to rest (or a time), sample; always bounded.</summary>
public static class SimulationRunner
{
    // Simulated time between two checks of the event and wall-clock bounds (s): long enough that
    // a normal shot is advanced in one piece, short enough that a bound is noticed promptly.
    private const double Chunk = 10;

    /// <summary>Runs the scene with the options.</summary>
    /// <example>
    /// Run a scene's shot to rest, or to a time, with samples of the balls' positions:
    /// <code language="csharp">
    /// Scene scene = SceneLoader.Load("assets/scenes/eight-ball-break.json");
    /// RunOutcome rest = SimulationRunner.Run(scene, new RunOptions());
    /// RunOutcome firstSecond = SimulationRunner.Run(scene, new RunOptions(Until: 1.0, SampleDt: 0.1));
    /// Console.WriteLine($"{rest.Stop} at {rest.Simulation.Time:0.000} s; {firstSecond.Samples.Count} samples");
    /// </code>
    /// </example>
    /// <exception cref="ArgumentOutOfRangeException">When <see cref="RunOptions.Until"/> is not in [0, <see cref="RunOptions.MaxUntil"/>].</exception>
    /// <exception cref="SceneException">When the scene has a game block but no shot for it to judge (a position for <c>suggest</c>).</exception>
    public static RunOutcome Run(Scene scene, RunOptions options)
    {
        if (scene.Game is not null && scene.Shot is null)
        {
            throw new SceneException(scene.Path, "$.game", "a game block judges the scene's shot, and the scene has none (suggest plays such a position)");
        }
        if (options.Until is { } u && !(u >= 0 && u <= RunOptions.MaxUntil))
        {
            throw new ArgumentOutOfRangeException(nameof(options), u, $"until must lie in [0, {RunOptions.MaxUntil}] s");
        }
        var clock = Stopwatch.StartNew();
        var sim = SimulationFactory.Create(scene);
        if (scene.Shot is { } shot)
        {
            sim.Strike(shot, scene.CueBall);
        }
        double limit = options.Until ?? options.MaxTime;
        var samples = new List<Sample>();
        StopReason? stop = null;
        if (options.SampleDt is { } sampleDt)
        {
            // Samples at t = k DT exactly: the simulation goes to its last step at or before it
            // (a stepping integrator stops at a step boundary at or after the time it is sent to),
            // and the positions come from a split step there (Simulation.PositionsAt).
            double step = sim.Integrator.IsReference ? 0 : sim.Dt;
            for (long k = 0; k * sampleDt <= limit + 1e-12; k++)
            {
                double t = k * sampleDt;
                stop = Advance(sim, step > 0 ? t - step + 1e-9 : t, options, clock);
                var positions = new Vec3[sim.Balls.Length];
                if (sim.Time > t + 1e-12)
                {
                    // Only a step past the time (a coarse step, or one started just before it) is left: the grid passed it.
                    positions = Positions(sim);
                }
                else
                {
                    sim.PositionsAt(t, positions);
                }
                samples.Add(new Sample(t, positions));
                if (stop is StopReason.Rest or StopReason.MaxEvents or StopReason.WallClock)
                {
                    break;
                }
                stop = null;
            }
        }
        stop ??= Advance(sim, limit, options, clock);
        if (stop == StopReason.Until && options.Until is null)
        {
            stop = StopReason.MaxTime;
        }
        return new RunOutcome(sim, samples, clock.Elapsed.TotalMilliseconds, sim.IsAtRest, stop.Value) { Ruling = Judge(scene, sim) };
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
            var cue = scene.Balls.FirstOrDefault(b => b.Id == scene.CueBall);
            game = game with { Placement = cue?.Position };
        }
        var referee = Rules.Referee.For(game.Rules, scene.Table, scene.BallRadius);
        return referee.Judge(game, ShotRecord.LastShot(sim, scene.Shot));
    }

    /// <summary>
    /// Advances <paramref name="sim"/> towards <paramref name="time"/> as <see cref="Simulation.AdvanceTo"/>
    /// does, but stops early at rest, after <see cref="RunOptions.MaxEvents"/> events or
    /// <see cref="RunOptions.MaxWallSeconds"/> of <paramref name="clock"/>; returns why it stopped
    /// (<see cref="StopReason.Until"/> when the time was reached).
    /// </summary>
    public static StopReason Advance(Simulation sim, double time, RunOptions options, Stopwatch clock)
    {
        while (true)
        {
            if (sim.IsAtRest)
            {
                return StopReason.Rest;
            }
            if (sim.Time >= time - 1e-12)
            {
                return StopReason.Until;
            }
            if (sim.Events.Count >= options.MaxEvents)
            {
                return StopReason.MaxEvents;
            }
            if (clock.Elapsed.TotalSeconds >= options.MaxWallSeconds)
            {
                return StopReason.WallClock;
            }
            sim.AdvanceTo(Math.Min(time, sim.Time + Chunk));
        }
    }

    /// <summary>The name results write for a stop reason.</summary>
    public static string Name(StopReason reason) => reason switch
    {
        StopReason.Rest => "rest",
        StopReason.Until => "until",
        StopReason.MaxTime => "max-time",
        StopReason.MaxEvents => "max-events",
        _ => "wall-clock",
    };

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
