using System.Numerics;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// The standard (physically based) model, physics-standard-model.md, with one of its integrators
/// (<see cref="StandardModel.Integrators"/>): each is a type that starts its own stepper over the
/// balls, so the simulation never asks which integrator it runs. The collision models are the
/// scene's <see cref="PhysicsConfig.Models"/>.
/// </summary>
public sealed partial class StandardSimulation : Simulation
{
    private readonly StandardTableModel _model;
    private readonly BallState[] _balls;
    private readonly BallState[] _initial;
    private readonly IStepper _stepper;

    /// <summary>Creates the simulation of a scene at t = 0, before its shot.</summary>
    public StandardSimulation(Scene scene)
        : this(new StandardTableModel(scene.Table, scene.Physics), scene)
    {
    }

    /// <summary>Creates the simulation of a scene's balls on a shared table model (the scene's table and physics are the model's).</summary>
    internal StandardSimulation(StandardTableModel model, Scene scene)
        : base(StandardModel.ModelName, scene.Physics.Integrator, scene.Physics.Dt, scene.Table, [.. scene.Balls.Select(b => b.Id)], scene.BallSet)
    {
        _model = model;
        _balls = new BallState[scene.Balls.Count];
        for (int i = 0; i < _balls.Length; i++)
        {
            var setup = scene.Balls[i];
            _balls[i] = new BallState
            {
                Position = setup.Position,
                Velocity = setup.Velocity,
                Spin = setup.Spin,
                Orientation = Quaternion.Identity,
                Pocket = -1,
            };
        }
        _initial = (BallState[])_balls.Clone();
        var integrator = scene.Physics.Integrator as StandardIntegrator
            ?? throw new ArgumentException($"integrator \"{scene.Physics.Integrator.Name}\" is not one of the standard model's", nameof(scene));
        _stepper = integrator.Start(_balls, Ids, model, Events);
    }

    /// <inheritdoc />
    public override TableModel TableModel => _model;

    /// <inheritdoc />
    public override bool KeepsSnapshots => true;

    /// <inheritdoc />
    public override InteractionModels Models => _model.Physics.Models;

    /// <summary>The model parameters.</summary>
    public PhysicsParams Parameters => _model.Parameters;

    /// <summary>The table's collision geometry.</summary>
    public TableGeometry Geometry => _model.Geometry;

    /// <inheritdoc />
    public override ReadOnlySpan<BallState> Balls => _balls;

    /// <inheritdoc />
    public override bool IsAtRest => _stepper.IsAtRest;

    /// <summary>
    /// One step. "exact": advance by <see cref="Simulation.Dt"/>, resolving every contact inside
    /// the step at its exact time. "event": advance to the next event. "euler": one Euler step.
    /// A table at rest only moves the clock (of the fixed-step integrators).
    /// </summary>
    public override void Step()
    {
        bool resting = _stepper.IsAtRest;
        long truncated = Collisions.ImpulseIntegration.Truncated;
        Time = _stepper.Step(Time, Dt, TrackOrientation);
        TruncatedImpacts += (int)(Collisions.ImpulseIntegration.Truncated - truncated);
        EventCapHits = _stepper.EventCapHits;
        StepCount++;
        if (!resting)
        {
            StateChecker.Check(this, Parameters.R, checkOverlap: _stepper.KeepsBallsApart);
        }
    }

    /// <inheritdoc />
    protected override bool StepBy(double dt)
    {
        // A probe (Simulation.PositionsAt) whose state is restored after it: nothing to count.
        double now = Time;
        long steps = StepCount;
        if (_stepper.TryAdvanceTo(Time + dt, TrackOrientation, ref now, ref steps))
        {
            Time = now;
        }
        else
        {
            Time = _stepper.Step(Time, dt, TrackOrientation);
        }
        return true;
    }

    /// <summary>
    /// Advances to <paramref name="time"/>, or until everything rests. The event integrator goes
    /// there exactly (and stops at the instant the last ball stops); the stepping integrators stop
    /// at the first step boundary at or after it.
    /// </summary>
    public override void AdvanceTo(double time)
    {
        double now = Time;
        long steps = StepCount;
        long truncated = Collisions.ImpulseIntegration.Truncated;
        bool reached = _stepper.TryAdvanceTo(time, TrackOrientation, ref now, ref steps);
        TruncatedImpacts += (int)(Collisions.ImpulseIntegration.Truncated - truncated);
        if (reached)
        {
            Time = now;
            StepCount = steps;
            EventCapHits = _stepper.EventCapHits;
            StateChecker.Check(this, Parameters.R, checkOverlap: _stepper.KeepsBallsApart);
            return;
        }
        base.AdvanceTo(time);
    }

    /// <inheritdoc />
    public override bool? AdvanceOneEvent(double time)
    {
        double now = Time;
        long steps = StepCount;
        long truncated = Collisions.ImpulseIntegration.Truncated;
        bool? resolved = _stepper.AdvanceOneEvent(time, TrackOrientation, ref now, ref steps);
        TruncatedImpacts += (int)(Collisions.ImpulseIntegration.Truncated - truncated);
        if (resolved is not null)
        {
            Time = now;
            StepCount = steps;
            EventCapHits = _stepper.EventCapHits;
        }
        return resolved;
    }

    /// <inheritdoc />
    public override void Reset()
    {
        _initial.CopyTo(_balls, 0);
        _stepper.Restart();
        Events.Clear();
        Time = 0;
        StepCount = 0;
        EventCapHits = 0;
        TruncatedImpacts = 0;
    }

    /// <summary>Strikes the cue ball (TP, <see cref="CueStrike"/>).</summary>
    protected override void ApplyStrike(int cue, ShotSpec shot)
    {
        var outcome = CueStrike.Strike(shot, Parameters);
        if (outcome.Miscue)
        {
            Events.Add(new SimEvent(Time, EventKind.Miscue, Ids[cue], Ids[cue], -1, shot.Speed));
        }
        _balls[cue].Velocity = outcome.Velocity;
        _balls[cue].Spin = outcome.Spin;
        // An elevated cue drives the ball into the slate. When the slate's return (e_t v sin theta)
        // would lift it 5 mm, the engine lands it at once (t = 0, a ball-table event): e_t and the
        // bed's friction send it up, a jump. A smaller return ends on the bed, where the strike's
        // model (TP A-30) has always let the bed take the downward part without friction, so every
        // stroke that does not jump plays exactly as before.
        if (Parameters.ET * outcome.IntoSlate >= _model.Constants.BounceThreshold)
        {
            _balls[cue].Velocity = outcome.Velocity with { Z = -outcome.IntoSlate };
        }
        _stepper.BallChanged(cue);
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
        _stepper.BallChanged(index);
    }

    /// <inheritdoc />
    protected override void TakeOut(int index)
    {
        ref var ball = ref _balls[index];
        ball.Velocity = Mathematics.Vec3.Zero;
        ball.Spin = Mathematics.Vec3.Zero;
        ball.State = MotionState.Pocketed;
        ball.Pocket = -1;
        _stepper.BallChanged(index);
    }

    /// <inheritdoc />
    public override CushionId CushionOf(int feature) => Geometry.CushionOf(feature);

    /// <inheritdoc />
    public override string FeatureName(EventKind kind, int feature) =>
        kind == EventKind.BallPocket ? Geometry.PocketName(feature) : Geometry.CushionName(feature);
}
