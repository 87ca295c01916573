using System.Numerics;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Thesis;

/// <summary>
/// The thesis model (thesis-model.md) behind the common <see cref="Simulation"/> API: the
/// scene's SI state is turned into the seed's units and frame (<see cref="SeedFrame"/>), stepped by
/// the <see cref="PhysicsEngine"/>, and read back in SI.
/// </summary>
/// <remarks>
/// The model has no spin and no sliding: a moving ball reports <see cref="MotionState.Rolling"/>
/// with the spin of rolling without slip, w = z x v / R; a scene's initial spins are ignored.
/// A ball reports <see cref="MotionState.Pocketed"/> from the step the pocket test catches it, while it
/// still falls. The shot's end-of-shot rules (respot, reset) are applied when it comes to rest,
/// see <see cref="PhysicsEngine.CheckForRest"/>; <see cref="Engine"/>'s
/// <see cref="PhysicsEngine.LastShotEnd"/> tells which applied.
/// </remarks>
public sealed partial class ThesisSimulation : Simulation
{
    /// <summary>Ball radius of the model (cm).</summary>
    private const float Radius = PhysicsEngine.BallRadius;

    private readonly ThesisTableModel _model;
    private readonly BallState[] _states;
    private readonly Vector3[] _startVelocities;
    private bool _statesStale = true;

    /// <summary>The scene's balls on its table, at rest unless the scene gives them velocities.</summary>
    public ThesisSimulation(Scene scene)
        : this(new ThesisTableModel(scene.Table, scene.Physics), scene)
    {
    }

    /// <summary>The scene's balls on a shared table model (the scene's table and physics are the model's).</summary>
    internal ThesisSimulation(ThesisTableModel model, Scene scene)
        : base(ThesisModel.ModelName, scene.Physics.Integrator, scene.Physics.Dt, scene.Table, scene.Balls.Select(b => b.Id).ToList(), scene.BallSet)
    {
        _model = model;
        var balls = new Ball[scene.Balls.Count];
        // Orientations are drawing state only; seed them from the rack so that runs repeat.
        var random = new SeededRandom(scene.Rack?.Seed ?? 0);
        for (int i = 0; i < balls.Length; i++)
        {
            var setup = scene.Balls[i];
            balls[i] = new Ball(setup.Id.Value, SeedFrame.FromSi(setup.Position)) { Velocity = SeedFrame.FromSi(setup.Velocity), IsCueBall = scene.BallSet.IsCueBall(setup.Id) };
            balls[i].RandomizeOrientation(random);
        }
        Queue = new ThesisCue();
        Engine = new PhysicsEngine(balls, model.RailArray, model.Cull, model.SeedTable, Queue, scene.Physics.Dt, random)
        {
            Events = Events,
        };
        _states = new BallState[balls.Length];
        _startVelocities = balls.Select(b => b.Velocity).ToArray();
    }

    /// <inheritdoc />
    public override bool RefereeRules
    {
        get => !Engine.SeedEndOfShotRules;
        set => Engine.SeedEndOfShotRules = !value;
    }

    /// <inheritdoc />
    public override TableModel TableModel => _model;

    /// <inheritdoc />
    public override bool KeepsSnapshots => true;

    /// <summary>The engine, in the seed's units, for the game and for tests.</summary>
    public PhysicsEngine Engine { get; }

    /// <summary>The cue: its tip offset is the cue ball's effet.</summary>
    public ThesisCue Queue { get; }

    /// <inheritdoc />
    public override ReadOnlySpan<BallState> Balls
    {
        get
        {
            if (_statesStale)
            {
                RefreshStates();
            }
            return _states;
        }
    }

    /// <inheritdoc />
    public override bool IsAtRest => Engine.IsAtRest;

    /// <inheritdoc />
    public override void Step()
    {
        Engine.TrackOrientation = TrackOrientation;
        Engine.CalculatePhysics();
        Time = Engine.Time;
        StepCount = Engine.Steps;
        _statesStale = true;
        StateChecker.Check(this, ThesisConstants.RadiusMetres, checkOverlap: false);
    }

    /// <inheritdoc />
    public override void Reset()
    {
        Engine.Restart(_startVelocities);
        Events.Clear();
        Time = 0;
        StepCount = 0;
        _statesStale = true;
    }

    /// <summary>
    /// The cue ball's speed per unit of cue speed for a centre hit: 2 / (1 + m / M), the
    /// elastic impact of a cue of mass M on a free ball of mass m (TP A-30 with no tip offset),
    /// with the seed's ball of m = 0.17 kg (<see cref="Ball.Mass"/>) and the standard model's
    /// default cue of M = 0.567 kg (the seed has no cue mass): 1.5386.
    /// </summary>
    /// <remarks>
    /// <see cref="ShotSpec.Speed"/> is the cue's speed at impact for every model; the seed's
    /// strike gives the ball a speed directly. This one factor turns the first into the second, so
    /// that a centre-ball shot leaves the cue ball at the standard model's speed (which also
    /// takes m and M from its defaults) to within their masses' rounding, 0.01 %.
    /// </remarks>
    public static readonly double CueToBallSpeed = 2 / (1 + Ball.Mass / PhysicsParams.Default.CueMass);

    /// <summary>
    /// Strikes the cue ball: the cue speed (m/s) in cm/s, capped at Formel 31's 800 cm/s (the
    /// fastest stroke), times <see cref="CueToBallSpeed"/>, along the aim; the tip offset becomes
    /// the effet, e_x = side * 2.86 and e_y = height * 2.86 (cm); the elevation only tilts the
    /// drawn cue, as in the seed.
    /// </summary>
    protected override void ApplyStrike(int cue, ShotSpec shot)
    {
        double aim = shot.AimDeg * Math.PI / 180;
        double cueSpeed = Math.Min(shot.Speed * SeedFrame.CentimetresPerMetre, ThesisCue.MaxStrokeSpeed);
        float speed = (float)(cueSpeed * CueToBallSpeed);
        var direction = SeedFrame.FromSi(new Vec3(DeterministicMath.Cos(aim), DeterministicMath.Sin(aim), 0));
        Queue.EX = (float)shot.TipSide * Radius;
        Queue.EY = (float)shot.TipHeight * Radius;
        Queue.Grade = (float)shot.ElevationDeg;
        Engine.Shoot(Vector3.Normalize(direction) * speed);
        _statesStale = true;
    }

    /// <inheritdoc />
    public override double BallRadius => ThesisConstants.RadiusMetres;

    /// <summary>
    /// Puts the seed's ball at the SI position in its frame (cm, y = 2.86 on the bed), at rest
    /// and in play. The engine's start positions (where the seed's end-of-shot rules put a
    /// pocketed cue ball back, or the whole game) stay those of the scene.
    /// </summary>
    protected override void PutBall(int index, Vec3 position)
    {
        var ball = Engine.Balls[index];
        ball.Position = SeedFrame.FromSi(position);
        ball.Velocity = Vector3.Zero;
        ball.Pocket = -1;
        ball.IsPocketed = false;
        _statesStale = true;
    }

    /// <summary>Takes the seed's ball out of play: its pocketed flag without a pocket, at rest where it was.</summary>
    protected override void TakeOut(int index)
    {
        var ball = Engine.Balls[index];
        ball.Velocity = Vector3.Zero;
        ball.Pocket = -1;
        ball.IsPocketed = true;
        _statesStale = true;
    }

    /// <summary>The seed's features: rails 0-5, jaws 6 + pocket, backs 12 + pocket (<see cref="Initializer.CushionNames"/>).</summary>
    public override CushionId CushionOf(int feature) => feature switch
    {
        >= 0 and < Initializer.FirstJaw => CushionId.OfRail(feature),
        >= Initializer.FirstJaw and < Initializer.FirstBack => CushionId.Jaw(Table.Pockets.Id(feature - Initializer.FirstJaw)),
        >= Initializer.FirstBack and < Initializer.FirstBack + Initializer.FirstBack - Initializer.FirstJaw => CushionId.Back(Table.Pockets.Id(feature - Initializer.FirstBack)),
        _ => CushionId.None,
    };

    /// <inheritdoc />
    public override string FeatureName(EventKind kind, int feature) => kind switch
    {
        EventKind.BallCushion => Initializer.CushionNames[feature],
        EventKind.BallPocket => Table.Pockets.NameOf(feature),
        _ => "",
    };

    private void RefreshStates()
    {
        var balls = Engine.Balls;
        for (int i = 0; i < _states.Length; i++)
        {
            var ball = balls[i];
            var velocity = SeedFrame.ToSi(ball.Velocity);
            ref var s = ref _states[i];
            s.Position = SeedFrame.ToSi(ball.Position);
            s.Velocity = velocity;
            s.Orientation = SeedFrame.ToSi(ball.Orientation);
            s.Pocket = ball.Pocket;
            if (ball.Pocket >= 0 || ball.IsPocketed)
            {
                s.State = MotionState.Pocketed;
                s.Spin = Vec3.Zero;
            }
            else
            {
                bool moving = velocity != Vec3.Zero;
                s.State = moving ? MotionState.Rolling : MotionState.Stationary;
                s.Spin = moving ? Vec3.Cross(Vec3.UnitZ, velocity) / ThesisConstants.RadiusMetres : Vec3.Zero;
            }
        }
        _statesStale = false;
    }
}
