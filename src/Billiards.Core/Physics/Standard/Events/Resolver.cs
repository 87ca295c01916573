using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard.Events;

/// <summary>
/// Resolves one contact of balls already synced to its time: applies the collision model (with the
/// TC model's elastic repeat rule), re-classifies the balls' motion states and logs the event.
/// Re-predicting what changed is the engine's business.
/// </summary>
internal sealed class Resolver
{
    private readonly BallState[] _balls;
    private readonly BallId[] _ids;
    private readonly int _n;
    private readonly PhysicsParams _params;
    private readonly PhysicsParams _elastic;
    private readonly MotionConstants _k;
    private readonly TableGeometry _geometry;
    private readonly IBallBallModel _ballBall;
    private readonly IBallCushionModel _ballCushion;
    private readonly ContactMemory _contacts;
    private readonly EventLog _log;
    private readonly Landing _landing;

    /// <summary>A resolver over the balls (changed in place), logging to <paramref name="log"/>.</summary>
    public Resolver(BallState[] balls, BallId[] ids, StandardTableModel model, ContactMemory contacts, EventLog log)
    {
        _balls = balls;
        _ids = ids;
        _n = balls.Length;
        _params = model.Parameters;
        // Repeat contacts of the TC model are elastic in the normal direction.
        _elastic = _params with { EB = 1, EC = 1, ECModel = CushionRestitution.Constant };
        _k = model.Constants;
        _geometry = model.Geometry;
        _ballBall = model.BallBall;
        _ballCushion = model.BallCushion;
        _contacts = contacts;
        _log = log;
        _landing = new Landing(model, ids, log);
    }

    /// <summary>Balls i and j collide at <paramref name="time"/> (s).</summary>
    public void Pair(int i, int j, double time)
    {
        ref var a = ref _balls[i];
        ref var b = ref _balls[j];
        // In the air the line of centres leaves the bed plane; the model takes it in space.
        bool inSpace = a.State == MotionState.Airborne || b.State == MotionState.Airborne;
        var n = inSpace ? (b.Position - a.Position).Normalized() : (b.Position - a.Position).XY.Normalized();
        double approach = Vec3.Dot(a.Velocity - b.Velocity, n);
        bool repeat = _contacts.IsRepeat(i, j, time) || _contacts.IsRepeat(j, i, time);
        _ballBall.Resolve(ref a, ref b, repeat ? _elastic : _params);
        double separation = Vec3.Dot(b.Velocity - a.Velocity, n);
        if (repeat && separation < EventEngine.RepeatSeparationSpeed)
        {
            var push = n * (0.5 * (EventEngine.RepeatSeparationSpeed - separation));
            a.Velocity -= push;
            b.Velocity += push;
        }
        _contacts.Remember(i, j, time);
        _contacts.Remember(j, i, time);
        var stateA = a.State;
        var stateB = b.State;
        BallMotion.Classify(ref a, _k);
        BallMotion.Classify(ref b, _k);
        _log.Add(new SimEvent(time, EventKind.BallBall, _ids[i], _ids[j], -1, approach));
        LogLift(i, stateA, time);
        LogLift(j, stateB, time);
    }

    /// <summary>Ball i meets the face, nose, pocket or rail top <paramref name="index"/> at <paramref name="time"/> (s), or comes down off the table.</summary>
    public void Rail(int i, RailKind kind, int index, double time)
    {
        switch (kind)
        {
            case RailKind.Segment:
                {
                    var s = _geometry.Segments[index];
                    Cushion(i, s.Normal, s.Feature, time);
                    break;
                }
            case RailKind.Nose:
                {
                    var nose = _geometry.Noses[index];
                    var normal = (_balls[i].Position - nose.Centre).XY.Normalized();
                    Cushion(i, normal, nose.Feature, time);
                    break;
                }
            case RailKind.Pocket:
                _landing.Drop(ref _balls[i], i, _geometry.Pockets[index].Pocket, time);
                break;
            case RailKind.RailTop:
                _landing.OnRail(ref _balls[i], i, index, time);
                break;
            case RailKind.OffTable:
                _landing.OffTable(ref _balls[i], i, time);
                break;
        }
    }

    private void Cushion(int i, Vec3 normal, int feature, double time)
    {
        ref var ball = ref _balls[i];
        double approach = -Vec3.Dot(ball.Velocity, normal);
        bool repeat = _contacts.IsRepeat(i, _n + feature, time);
        // The cushion models work in the bed plane; a ball in the air keeps its vertical speed.
        double vz = ball.Velocity.Z;
        _ballCushion.Resolve(ref ball, normal, _geometry.CushionHeight, repeat ? _elastic : _params);
        if (ball.State == MotionState.Airborne)
        {
            ball.Velocity = ball.Velocity with { Z = vz };
        }
        double separation = Vec3.Dot(ball.Velocity, normal);
        if (repeat && separation < EventEngine.RepeatSeparationSpeed)
        {
            ball.Velocity += normal * (EventEngine.RepeatSeparationSpeed - separation);
        }
        _contacts.Remember(i, _n + feature, time);
        var before = ball.State;
        BallMotion.Classify(ref ball, _k);
        _log.Add(new SimEvent(time, EventKind.BallCushion, _ids[i], _ids[i], feature, approach));
        LogLift(i, before, time);
    }

    /// <summary>Ball i, in the air, reaches the bed at <paramref name="time"/> (s): it lands, and may bounce.</summary>
    public void Land(int i, double time) => _landing.OnBed(ref _balls[i], i, time);

    // Logs a ball that a contact lifted off the bed.
    private void LogLift(int i, MotionState before, double time)
    {
        ref readonly var ball = ref _balls[i];
        if (before != MotionState.Airborne && ball.State == MotionState.Airborne)
        {
            _log.Add(new SimEvent(time, EventKind.BallAirborne, _ids[i], _ids[i], -1, ball.Velocity.Z));
        }
    }
}
