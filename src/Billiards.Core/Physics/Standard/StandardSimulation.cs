using System.Numerics;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// The standard (physically based) model, physics-standard-model.md, with one of three
/// integrators: "exact" (fixed steps of <see cref="Simulation.Dt"/>, each advanced by the event
/// engine, so motion and contact times are exact inside the step), "event" (the reference solver:
/// each step jumps to the next event) and "euler" (naive explicit stepping with overlap detection).
/// "exact" and "event" share one <see cref="EventEngine"/>; "euler" shares the collision models
/// and the table geometry.
/// </summary>
public sealed class StandardSimulation : Simulation
{
    private readonly BallState[] _balls;
    private readonly BallState[] _initial;
    private readonly EventEngine? _engine;
    private readonly EulerStepper? _euler;
    private readonly bool _eventIntegrator;

    /// <summary>Creates the simulation of a scene at t = 0, before its shot.</summary>
    public StandardSimulation(Scene scene)
        : this(scene, FrictionalInelastic.Instance, Han2005.Instance)
    {
    }

    /// <summary>Creates the simulation of a scene with the given collision models.</summary>
    public StandardSimulation(Scene scene, IBallBallModel ballBall, IBallCushionModel ballCushion)
        : base(StandardModel.ModelName, scene.Physics.Integrator, scene.Physics.Dt, scene.Table, [.. scene.Balls.Select(b => b.Id)])
    {
        Parameters = scene.Physics.Params;
        Geometry = TableGeometry.Build(scene.Table, Parameters.R);
        _balls = new BallState[scene.Balls.Count];
        for (int i = 0; i < _balls.Length; i++)
        {
            var setup = scene.Balls[i];
            _balls[i] = new BallState
            {
                Position = setup.Position with { Z = Parameters.R },
                Velocity = setup.Velocity.XY,
                Spin = setup.Spin,
                Orientation = Quaternion.Identity,
                Pocket = -1,
            };
        }
        _initial = (BallState[])_balls.Clone();
        _eventIntegrator = Integrator == Integrators.Event;
        if (Integrator == Integrators.Euler)
        {
            _euler = new EulerStepper(_balls, Ids, Parameters, Geometry, ballBall, ballCushion, Events);
        }
        else
        {
            _engine = new EventEngine(_balls, Ids, Parameters, Geometry, ballBall, ballCushion, Events);
        }
    }

    /// <summary>The model parameters.</summary>
    public PhysicsParams Parameters { get; }

    /// <summary>The table's collision geometry.</summary>
    public TableGeometry Geometry { get; }

    /// <inheritdoc />
    public override ReadOnlySpan<BallState> Balls => _balls;

    /// <inheritdoc />
    public override bool IsAtRest => _engine?.IsAtRest ?? _euler!.IsAtRest;

    /// <summary>
    /// One step. "exact": advance by <see cref="Simulation.Dt"/>, resolving every contact inside
    /// the step at its exact time. "event": advance to the next event. "euler": one Euler step.
    /// </summary>
    public override void Step()
    {
        if (_engine is { } engine)
        {
            if (engine.IsAtRest)
            {
                // A table waiting for the player: only the clock moves ("event" has nothing to
                // step to, "exact" stays on its fixed grid).
                if (!_eventIntegrator)
                {
                    Time += Dt;
                    engine.IdleTo(Time);
                }
                StepCount++;
                return;
            }
            engine.TrackOrientation = TrackOrientation;
            if (_eventIntegrator)
            {
                engine.StepToNextEvent();
                Time = engine.Time;
            }
            else
            {
                // Steps stay on the fixed grid even when everything rests inside one.
                double end = Time + Dt;
                engine.AdvanceTo(end, stopAtRest: false);
                Time = end;
            }
            EventCapHits = engine.EventCapHits;
        }
        else
        {
            Time += Dt;
            if (!_euler!.IsAtRest)
            {
                _euler.TrackOrientation = TrackOrientation;
                _euler.Step(Dt, Time);
            }
        }
        StepCount++;
    }

    /// <summary>
    /// Advances to <paramref name="time"/>, or until everything rests. The event integrator goes
    /// there exactly (and stops at the instant the last ball stops); the stepping integrators stop
    /// at the first step boundary at or after it.
    /// </summary>
    public override void AdvanceTo(double time)
    {
        if (_engine is { } engine && _eventIntegrator)
        {
            engine.TrackOrientation = TrackOrientation;
            long before = engine.EventCount;
            engine.AdvanceTo(Math.Max(time, Time), stopAtRest: true);
            Time = engine.Time;
            StepCount += engine.EventCount - before;
            EventCapHits = engine.EventCapHits;
            return;
        }
        base.AdvanceTo(time);
    }

    /// <inheritdoc />
    public override void Reset()
    {
        _initial.CopyTo(_balls, 0);
        _engine?.Restart();
        _euler?.Restart();
        Events.Clear();
        Time = 0;
        StepCount = 0;
        EventCapHits = 0;
    }

    /// <summary>Strikes the cue ball (TP, <see cref="CueStrike"/>).</summary>
    protected override void ApplyStrike(int cue, ShotSpec shot)
    {
        var outcome = CueStrike.Strike(shot, Parameters);
        _balls[cue].Velocity = outcome.Velocity;
        _balls[cue].Spin = outcome.Spin;
        _engine?.BallChanged(cue);
        _euler?.BallChanged(cue);
    }

    /// <summary>
    /// Sets a ball's velocity (m/s) and spin (rad/s) from outside, as a strike would, and
    /// re-predicts what involves it. For tests and tools.
    /// </summary>
    public void SetMotion(int index, Mathematics.Vec3 velocity, Mathematics.Vec3 spin)
    {
        _balls[index].Velocity = velocity.XY;
        _balls[index].Spin = spin;
        _engine?.BallChanged(index);
        _euler?.BallChanged(index);
    }

    /// <inheritdoc />
    public override double BallRadius => Parameters.R;

    /// <inheritdoc />
    protected override void PutBall(int index, Mathematics.Vec3 position)
    {
        ref var ball = ref _balls[index];
        ball.Position = position;
        ball.Velocity = Mathematics.Vec3.Zero;
        ball.Spin = Mathematics.Vec3.Zero;
        ball.State = MotionState.Stationary;
        ball.Pocket = -1;
        _engine?.BallChanged(index);
        _euler?.BallChanged(index);
    }

    /// <inheritdoc />
    protected override void TakeOut(int index)
    {
        ref var ball = ref _balls[index];
        ball.Velocity = Mathematics.Vec3.Zero;
        ball.Spin = Mathematics.Vec3.Zero;
        ball.State = MotionState.Pocketed;
        ball.Pocket = -1;
        _engine?.BallChanged(index);
        _euler?.BallChanged(index);
    }

    /// <inheritdoc />
    public override CushionId CushionOf(int feature) => Geometry.CushionOf(feature);

    /// <inheritdoc />
    public override string FeatureName(EventKind kind, int feature) =>
        kind == EventKind.BallPocket ? TableGeometry.PocketName(feature) : Geometry.CushionName(feature);
}
