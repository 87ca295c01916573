using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Soak;

/// <summary>What the soak runs: model, integrator, step, number of shots, seed, the mix of strokes and the first shot.</summary>
public sealed record SoakOptions(string Model, string Integrator, double Dt, long Shots, int Seed, long Progress, long Only = -1, string Mix = SoakOptions.StandardMix, long First = 0)
{
    /// <summary>The mix of <see cref="SoakRunner"/>'s legal shots: racks and scatters, mostly level.</summary>
    public const string StandardMix = "standard";

    /// <summary>The mix of elevated strokes (issue 40): racked 8- and 9-ball tables, the cue ball anywhere on the bed, 0.1-12 m/s, tip within 0.5 R, elevation 0-80 deg.</summary>
    public const string ElevatedMix = "elevated";

    /// <summary>Parses <c>--model --integrator --dt --shots --seed --progress --only --mix --first</c>; null on a bad argument.</summary>
    public static SoakOptions? Parse(string[] args)
    {
        var o = new SoakOptions(ModelRegistry.Default.Name, Integrators.Exact, PhysicsConfig.DefaultDt, 10_000, 1, 0);
        for (int i = 0; i + 1 < args.Length; i += 2)
        {
            string v = args[i + 1];
            o = args[i] switch
            {
                "--model" => ModelRegistry.Find(v) is { } m ? o with { Model = v, Integrator = m.Integrators[0].Name } : null!,
                "--integrator" => o with { Integrator = v },
                "--dt" => o with { Dt = double.Parse(v, CultureInfo.InvariantCulture) },
                "--shots" => o with { Shots = long.Parse(v, CultureInfo.InvariantCulture) },
                "--seed" => o with { Seed = int.Parse(v, CultureInfo.InvariantCulture) },
                "--progress" => o with { Progress = long.Parse(v, CultureInfo.InvariantCulture) },
                "--only" => o with { Only = long.Parse(v, CultureInfo.InvariantCulture) },
                "--mix" => v is StandardMix or ElevatedMix ? o with { Mix = v } : null!,
                "--first" => o with { First = long.Parse(v, CultureInfo.InvariantCulture) },
                _ => null!,
            };
            if (o is null)
            {
                return null;
            }
        }
        if (args.Length % 2 != 0 || ModelRegistry.Find(o.Model) is not { } model || ModelRegistry.FindIntegrator(model, o.Integrator) is null)
        {
            return null;
        }
        return o;
    }
}

/// <summary>The outcome of one shot.</summary>
/// <param name="Shot">The shot's number (with the seed, it reproduces the shot).</param>
/// <param name="Nan">Balls with a non-finite position, velocity or spin at the end.</param>
/// <param name="Escapes">Balls in play at the end that are not at rest on the bed (<see cref="BallPlace.Outside"/>: their centre neither on the bed nor in a pocket's mouth, or in the air).</param>
/// <param name="InsideCushion">Balls in play at the end on the bed's height inside a cushion or jaw (<see cref="BallPlace.InsideCushion"/>).</param>
/// <param name="OffTable">Balls off the table at the end (state off-table): counted apart, never as escapes.</param>
/// <param name="Overlaps">Pairs of balls in play closer than 2R less 1 micrometre at the end.</param>
/// <param name="MaxOverlap">The deepest of those overlaps (m).</param>
/// <param name="AtRest">Whether the run came to rest within <see cref="SoakRunner.MaxTime"/>.</param>
/// <param name="Events">Events of the shot.</param>
/// <param name="TEnd">Simulated time when it came to rest (s).</param>
/// <param name="Description">The shot, for reproducing it.</param>
/// <param name="ElevationDeg">The cue's elevation (deg).</param>
public sealed record ShotOutcome(long Shot, int Nan, int Escapes, int InsideCushion, int OffTable, int Overlaps, double MaxOverlap, bool AtRest, int Events, double TEnd, string Description, double ElevationDeg = 0);

/// <summary>
/// Makes and runs seeded random legal shots: a racked 8-ball or 9-ball table or a random scatter
/// of balls, on a random preset, with a random cue strike inside the contract's limits.
/// </summary>
public sealed class SoakRunner(SoakOptions options)
{
    /// <summary>A shot that has not come to rest after this much simulated time (s) does not terminate.</summary>
    public const double MaxTime = 600;

    /// <summary>Overlap below which two balls count as touching (m): round-off of the contact times.</summary>
    public const double OverlapTolerance = 1e-6;

    private static readonly string[] Presets = ["pool-9ft", "pool-8ft", "pool-7ft", "thesis"];

    // The elevated mix plays on every preset the standard model has.
    private static readonly string[] ElevatedPresets = ["pool-9ft", "pool-8ft", "pool-7ft", "snooker-12ft", "thesis", "pocketless"];

    /// <summary>Builds and runs shot number <paramref name="shot"/>; the same shot and seed give the same outcome.</summary>
    public ShotOutcome RunShot(long shot)
    {
        var random = new Random(ShotSeed(options.Seed, shot));
        var scene = MakeScene(random, shot);
        var sim = SimulationFactory.Create(scene);
        sim.Strike(scene.Shot!);
        // Whole-step loop so that every integrator is bounded by the same simulated time.
        while (!sim.IsAtRest && sim.Time < MaxTime)
        {
            sim.Step();
        }
        if (options.Only >= 0)
        {
            Dump(sim, scene);
        }
        return Check(sim, scene, shot);
    }

    // One shot in detail: its scene and the final state of every ball, for investigating a failure.
    private static void Dump(Simulation sim, Scene scene)
    {
        foreach (var b in scene.Balls)
        {
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"start {b.Id,4} [{b.Position.X:0.######}, {b.Position.Y:0.######}]"));
        }
        for (int i = 0; i < sim.Balls.Length; i++)
        {
            var b = sim.Balls[i];
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"end   {sim.Ids[i],4} [{b.Position.X:0.######}, {b.Position.Y:0.######}] {b.State} pocket {b.Pocket}"));
        }
        var counts = sim.Events.AsSpan().ToArray().GroupBy(e => (e.Kind, e.A, e.B, e.Feature)).OrderByDescending(g => g.Count()).Take(5);
        foreach (var g in counts)
        {
            Console.WriteLine($"events {g.Key}: {g.Count()} from t = {g.First().Time:0.###} to {g.Last().Time:0.###}");
        }
    }

    // SplitMix64 of (seed, shot): the same in every process (HashCode is randomised per process).
    private static int ShotSeed(int seed, long shot)
    {
        ulong z = unchecked(((ulong)(uint)seed << 40) ^ (ulong)shot) + 0x9E3779B97F4A7C15UL;
        z = unchecked((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL);
        z = unchecked((z ^ (z >> 27)) * 0x94D049BB133111EBUL);
        return (int)((z ^ (z >> 31)) & int.MaxValue);
    }

    private Scene MakeScene(Random random, long shot) =>
        options.Mix == SoakOptions.ElevatedMix ? MakeElevatedScene(random, shot) : MakeStandardScene(random, shot);

    // Issue 40's strokes: a racked 8- or 9-ball table, the cue ball anywhere on the bed clear of
    // the rack, 0.1-12 m/s, a tip anywhere within half the radius, the cue elevated 0-80 deg.
    private Scene MakeElevatedScene(Random random, long shot)
    {
        var model = ModelRegistry.Get(options.Model);
        var table = TableSpec.FromPreset(model == ModelRegistry.Default ? ElevatedPresets[random.Next(ElevatedPresets.Length)] : model.DefaultTablePreset);
        var physics = PhysicsConfig.Default with { Model = model, Integrator = ModelRegistry.FindIntegrator(model, options.Integrator)!, Dt = options.Dt };
        double r = model.BallRadius(physics.Params);
        var rack = new RackSpec(random.Next(2) == 0 ? RackGame.EightBall : RackGame.NineBall, random.Next());
        var balls = new List<BallSetup>();
        foreach (var (id, position) in Initializer.Rack(rack, table, r))
        {
            balls.Add(new BallSetup(id, position, Vec3.Zero, Vec3.Zero));
        }
        if (RandomSpot(random, table, r, balls, -table.HalfLength + r, table.HalfLength - r) is not { } cue)
        {
            return MakeElevatedScene(random, shot);
        }
        balls.Insert(0, new BallSetup(Billiards.Core.Balls.BallSet.Pool.CueBalls[0], cue, Vec3.Zero, Vec3.Zero));
        double speed = 0.1 + random.NextDouble() * 11.9;
        double tipR = 0.5 * Math.Sqrt(random.NextDouble());
        double tipA = random.NextDouble() * 2 * Math.PI;
        double elevation = random.NextDouble() * 80;
        var strike = new ShotSpec(speed, random.NextDouble() * 360 - 180, tipR * Math.Cos(tipA), tipR * Math.Sin(tipA), elevation);
        return new Scene($"soak shot {shot}", null, table, physics, rack, balls, strike, null);
    }

    private Scene MakeStandardScene(Random random, long shot)
    {
        // The default model is soaked on every pool table, another model on its own table.
        var model = ModelRegistry.Get(options.Model);
        var table = TableSpec.FromPreset(model == ModelRegistry.Default ? Presets[random.Next(Presets.Length)] : model.DefaultTablePreset);
        var physics = PhysicsConfig.Default with { Model = model, Integrator = ModelRegistry.FindIntegrator(model, options.Integrator)!, Dt = options.Dt };
        double r = model.BallRadius(physics.Params);
        var balls = new List<BallSetup>();
        RackSpec? rack = null;
        if (random.Next(2) == 0)
        {
            rack = new RackSpec(random.Next(2) == 0 ? RackGame.EightBall : RackGame.NineBall, random.Next());
            foreach (var (id, position) in Initializer.Rack(rack, table, r))
            {
                balls.Add(new BallSetup(id, position, Vec3.Zero, Vec3.Zero));
            }
            // The cue ball anywhere behind the head string.
            var cue = RandomSpot(random, table, r, balls, -table.HalfLength + r, -table.HalfLength / 2);
            if (cue is not { } c)
            {
                return MakeStandardScene(random, shot);
            }
            balls.Insert(0, new BallSetup(Billiards.Core.Balls.BallSet.Pool.CueBalls[0], c, Vec3.Zero, Vec3.Zero));
        }
        else
        {
            int count = 1 + random.Next(16);
            for (int id = 0; id < count; id++)
            {
                if (RandomSpot(random, table, r, balls, -table.HalfLength + r, table.HalfLength - r) is { } p)
                {
                    balls.Add(new BallSetup(new BallId(id), p, Vec3.Zero, Vec3.Zero));
                }
            }
            if (balls.Count == 0 || !Billiards.Core.Balls.BallSet.Pool.IsCueBall(balls[0].Id))
            {
                return MakeStandardScene(random, shot);
            }
        }
        // A legal strike: speed up to the contract's cap (mostly up to a hard break), any aim, a tip
        // inside the miscue limit (half the radius), elevation up to 60 deg (masse) but mostly level.
        double speed = random.Next(10) == 0 ? random.NextDouble() * SceneLoader.MaxShotSpeed : 0.05 + random.NextDouble() * 11.95;
        double tipR = 0.5 * Math.Sqrt(random.NextDouble());
        double tipA = random.NextDouble() * 2 * Math.PI;
        double elevation = random.Next(4) == 0 ? random.NextDouble() * 60 : random.NextDouble() * 10;
        var strike = new ShotSpec(speed, random.NextDouble() * 360 - 180, tipR * Math.Cos(tipA), tipR * Math.Sin(tipA), elevation);
        balls.Sort((a, b) => a.Id.Value.CompareTo(b.Id.Value));
        return new Scene($"soak shot {shot}", null, table, physics, rack, balls, strike, null);
    }

    private static Vec3? RandomSpot(Random random, TableSpec table, double r, List<BallSetup> placed, double x0, double x1)
    {
        for (int attempt = 0; attempt < 50; attempt++)
        {
            var p = new Vec3(x0 + random.NextDouble() * (x1 - x0), (random.NextDouble() * 2 - 1) * (table.HalfWidth - r), r);
            if (placed.All(b => (b.Position - p).XY.Length >= 2 * r))
            {
                return p;
            }
        }
        return null;
    }

    private static ShotOutcome Check(Simulation sim, Scene scene, long shot)
    {
        double r = scene.BallRadius;
        var balls = sim.Balls;
        int nan = 0, escapes = 0, insideCushion = 0, offTable = 0, overlaps = 0;
        double maxOverlap = 0;
        for (int i = 0; i < balls.Length; i++)
        {
            ref readonly var b = ref balls[i];
            if (!Finite(b.Position) || !Finite(b.Velocity) || !Finite(b.Spin))
            {
                nan++;
                continue;
            }
            switch (StateChecker.PlaceOf(sim, i))
            {
                case BallPlace.OffTable:
                    offTable++;
                    break;
                case BallPlace.Outside:
                    escapes++;
                    break;
                case BallPlace.InsideCushion:
                    insideCushion++;
                    break;
            }
            for (int j = i + 1; j < balls.Length; j++)
            {
                if (b.IsOutOfPlay || balls[j].IsOutOfPlay)
                {
                    continue;
                }
                double depth = 2 * r - (b.Position - balls[j].Position).XY.Length;
                if (depth > OverlapTolerance)
                {
                    overlaps++;
                    maxOverlap = Math.Max(maxOverlap, depth);
                }
            }
        }
        var s = scene.Shot!;
        string description = string.Create(CultureInfo.InvariantCulture,
            $"shot {shot}: {scene.Table.Preset}, {(scene.Rack is { } rk ? $"{rk.Game} rack seed {rk.Seed}" : $"{scene.Balls.Count} balls scattered")}, speed {s.Speed:0.###} aim {s.AimDeg:0.##} tip [{s.TipSide:0.###}, {s.TipHeight:0.###}] elevation {s.ElevationDeg:0.#}");
        return new ShotOutcome(shot, nan, escapes, insideCushion, offTable, overlaps, maxOverlap, sim.IsAtRest, sim.Events.Count, sim.Time, description, s.ElevationDeg);
    }

    private static bool Finite(Vec3 v) => double.IsFinite(v.X) && double.IsFinite(v.Y) && double.IsFinite(v.Z);
}

/// <summary>Totals over the shots: what the README quotes.</summary>
public sealed class SoakReport
{
    private long _shots, _nan, _escapes, _escapeShots, _insideCushion, _offTable, _offTableShots, _overlaps, _nonTerminating;
    private double _maxOverlap;

    // Shots and shots with a ball off the table, by the cue's elevation in bands of 10 deg (0-10, ..., 80-90).
    private readonly long[] _bandShots = new long[9];
    private readonly long[] _bandOffTable = new long[9];
    private ShotOutcome? _maxEvents, _maxTEnd, _firstFailure, _firstEscape;

    /// <summary>Shots with a NaN, an escape (outside the table or inside a cushion), an overlap or no rest.</summary>
    public long Failures { get; private set; }

    /// <summary>Adds one shot.</summary>
    public void Add(ShotOutcome o)
    {
        _shots++;
        _nan += o.Nan;
        _escapes += o.Escapes;
        _escapeShots += o.Escapes > 0 ? 1 : 0;
        _insideCushion += o.InsideCushion;
        _offTable += o.OffTable;
        _offTableShots += o.OffTable > 0 ? 1 : 0;
        int band = Math.Clamp((int)(o.ElevationDeg / 10), 0, _bandShots.Length - 1);
        _bandShots[band]++;
        _bandOffTable[band] += o.OffTable > 0 ? 1 : 0;
        _overlaps += o.Overlaps;
        _maxOverlap = Math.Max(_maxOverlap, o.MaxOverlap);
        _nonTerminating += o.AtRest ? 0 : 1;
        if (o.Nan + o.Escapes + o.InsideCushion + o.Overlaps > 0 || !o.AtRest)
        {
            Failures++;
            _firstFailure ??= o;
        }
        if (o.Escapes + o.InsideCushion > 0)
        {
            _firstEscape ??= o;
        }
        if (_maxEvents is null || o.Events > _maxEvents.Events)
        {
            _maxEvents = o;
        }
        if (_maxTEnd is null || o.TEnd > _maxTEnd.TEnd)
        {
            _maxTEnd = o;
        }
    }

    /// <summary>One paragraph of figures.</summary>
    public string Summary(SoakOptions options) => string.Create(CultureInfo.InvariantCulture,
        $"""
        model {options.Model}, integrator {options.Integrator}, dt {options.Dt:0.######}, seed {options.Seed}, mix {options.Mix}, shots from {options.First}
        shots {_shots}, NaN {_nan}, escapes {_escapes} (in {_escapeShots} shots), inside a cushion {_insideCushion}, overlaps {_overlaps} (max {_maxOverlap * 1000:0.###} mm), non-terminating {_nonTerminating}
        off the table {_offTable} balls in {_offTableShots} shots ({(_shots > 0 ? 100.0 * _offTableShots / _shots : 0):0.###} % of shots; counted apart, not escapes)
        shots with a ball off the table by elevation: {Bands()}
        max events per shot {_maxEvents?.Events} ({_maxEvents?.Description})
        max t_end {_maxTEnd?.TEnd:0.###} s ({_maxTEnd?.Description})
        first failure: {_firstFailure?.Description ?? "none"}
        first escape: {_firstEscape?.Description ?? "none"}
        """);

    private string Bands() => string.Join(", ", Enumerable.Range(0, _bandShots.Length).Where(k => _bandShots[k] > 0).Select(k =>
        string.Create(CultureInfo.InvariantCulture, $"{10 * k}-{10 * k + 10} deg {100.0 * _bandOffTable[k] / _bandShots[k]:0.#} % of {_bandShots[k]}")));
}
