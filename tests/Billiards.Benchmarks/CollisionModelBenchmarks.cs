using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Collisions;

namespace Billiards.Benchmarks;

/// <summary>
/// One collision with each interaction model of the registry: a ball at 2 m/s into the foot cushion
/// 30 deg off its normal with natural follow and some side; a cue ball at 2 m/s with follow into a
/// resting object ball, a 37 deg cut.
/// </summary>
public class CollisionModelBenchmarks
{
    private static readonly PhysicsParams P = PhysicsParams.Default;
    private static readonly Vec3 Normal = new(-1, 0, 0);
    private static readonly double Height = 0.64 * 2 * P.R;
    private IBallCushionModel? _cushion;
    private IBallBallModel? _ballBall;
    private BallState _ball, _cue, _object;

    /// <summary>The model: a cushion model or a ball-ball model of the registry.</summary>
    [ParamsSource(nameof(ModelNames))]
    public string Model { get; set; } = "han-2005";

    public static IEnumerable<string> ModelNames() => ModelRegistry.BallCushionNames.Concat(ModelRegistry.BallBallNames);

    [GlobalSetup]
    public void Setup()
    {
        _cushion = ModelRegistry.FindBallCushion(Model);
        _ballBall = ModelRegistry.FindBallBall(Model);
        var v = new Vec3(2 * Math.Cos(Math.PI / 6), 2 * Math.Sin(Math.PI / 6), 0);
        _ball = new BallState { Position = new Vec3(0, 0, P.R), Velocity = v, Spin = Vec3.Cross(Vec3.UnitZ, v) / P.R + new Vec3(0, 0, 20) };
        _cue = new BallState { Position = new Vec3(0, 0, P.R), Velocity = new Vec3(2, 0, 0), Spin = new Vec3(0, 2 / P.R, 0) };
        _object = new BallState { Position = new Vec3(2 * P.R * 0.8, 2 * P.R * 0.6, P.R) };
    }

    /// <summary>One collision: the ball-cushion impact or the ball-ball collision the model resolves.</summary>
    [Benchmark]
    public double Collision()
    {
        if (_cushion is { } cushion)
        {
            var b = _ball;
            cushion.Resolve(ref b, Normal, Height, P);
            return b.Velocity.X;
        }
        var a = _cue;
        var o = _object;
        _ballBall!.Resolve(ref a, ref o, P);
        return o.Velocity.X;
    }
}

/// <summary>The seeded 8-ball break (assets/scenes/models) from the strike to rest with each cushion model, exact integrator at 1/250 s.</summary>
public class CushionModelBreakBenchmarks
{
    private SceneShot _break = null!;

    /// <summary>The cushion model.</summary>
    [ParamsSource(nameof(CushionNames))]
    public string Cushion { get; set; } = "han-2005";

    public static IEnumerable<string> CushionNames() => ModelRegistry.BallCushionNames;

    [GlobalSetup]
    public void Setup() => _break = SceneShot.Of(SceneLoader.Load(AssetFolder.Scene($"models/eight-ball-break-{Cushion}.json")));

    /// <summary>8-ball break to rest.</summary>
    [Benchmark]
    public double EightBallBreak() => _break.RunToRest();
}
