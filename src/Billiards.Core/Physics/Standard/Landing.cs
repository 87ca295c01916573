using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// What becomes of a ball that comes down, or drops, with every integrator of the standard model
/// (docs/flight.md): on the bed it lands and bounces or stays; on a rail's top it bounces, or,
/// with too little rebound to fly on, it has left the table (a ball at rest on a rail is off the
/// table, as the rules have it); over the floor it is off the table; over a hole, or rolling into
/// one, it drops. The ball-table and ball-pocket models of <see cref="InteractionModels"/> resolve
/// the contacts; this class puts the ball where they happen, decides its state and logs the events.
/// </summary>
internal sealed class Landing
{
    private readonly PhysicsParams _params;
    private readonly MotionConstants _k;
    private readonly IBallTableModel _table;
    private readonly IBallPocketModel _pocket;
    private readonly TableGeometry _geometry;
    private readonly double _railTop;
    private readonly BallId[] _ids;
    private readonly EventLog _log;

    /// <summary>The landings of the balls <paramref name="ids"/> on <paramref name="model"/>'s table, logged to <paramref name="log"/>.</summary>
    public Landing(StandardTableModel model, BallId[] ids, EventLog log)
    {
        _params = model.Parameters;
        _k = model.Constants;
        _table = model.BallTable;
        _pocket = model.BallPocket;
        _geometry = model.Geometry;
        _railTop = _geometry.Spec.RailHeight + _k.R;
        _ids = ids;
        _log = log;
    }

    /// <summary>The height of a ball's centre resting on the rails' top (m).</summary>
    public double RailTop => _railTop;

    /// <summary>
    /// Ball i lands on the bed (or is driven into it): its centre goes to z = R, the ball-table
    /// model resolves the impact, and it flies on when the rebound would lift it at least 5 mm,
    /// else it stays on the bed. Logs <see cref="EventKind.BallTable"/> and, for a bounce,
    /// <see cref="EventKind.BallAirborne"/>.
    /// </summary>
    public void OnBed(ref BallState b, int i, double time)
    {
        if (!Bounces(ref b, i, _k.R, EventKind.BallTable, -1, time))
        {
            b.Velocity = b.Velocity.XY;
            b.State = MotionState.Sliding; // whatever it was, Classify decides anew on the bed
            BallMotion.Classify(ref b, _k);
        }
    }

    /// <summary>
    /// Ball i, come down to the rails' top, meets what lies
    /// there (<see cref="TableGeometry.SurfaceUnder"/>, not the bed): it drops into the hole, bounces
    /// on the rail, or is off the table.
    /// </summary>
    public void OnSurface(ref BallState b, int i, TableSurface surface, double time)
    {
        switch (surface.Kind)
        {
            case SurfaceKind.Pocket:
                Drop(ref b, i, _geometry.Pockets[surface.Index].Pocket, time);
                break;
            case SurfaceKind.Rail:
                OnRail(ref b, i, surface.Index, time);
                break;
            case SurfaceKind.Floor:
                OffTable(ref b, i, time);
                break;
        }
    }

    /// <summary>Ball i drops into pocket <paramref name="pocket"/> (an index of the table's pockets), by the ball-pocket model; logs <see cref="EventKind.BallPocket"/>.</summary>
    public void Drop(ref BallState b, int i, int pocket, double time)
    {
        double speed = _pocket.Drop(ref b, pocket);
        _log.Add(new SimEvent(time, EventKind.BallPocket, _ids[i], _ids[i], pocket, speed));
    }

    /// <summary>Ball i is off the table where it is, out of play; logs <see cref="EventKind.BallOffTable"/>.</summary>
    public void OffTable(ref BallState b, int i, double time)
    {
        double speed = b.Velocity.Length;
        b.Velocity = Vec3.Zero;
        b.Spin = Vec3.Zero;
        b.State = MotionState.OffTable;
        _log.Add(new SimEvent(time, EventKind.BallOffTable, _ids[i], _ids[i], -1, speed));
    }

    /// <summary>
    /// Ball i comes down on a rail's top: a <see cref="EventKind.BallCushion"/> contact of cushion
    /// <paramref name="feature"/> (its top), resolved by the ball-table model; a rebound too small
    /// to fly on leaves the ball on the rail, off the table.
    /// </summary>
    public void OnRail(ref BallState b, int i, int feature, double time)
    {
        if (!Bounces(ref b, i, _railTop, EventKind.BallCushion, feature, time))
        {
            OffTable(ref b, i, time);
        }
    }

    // Puts ball i's centre at `height` on a level surface, resolves the impact (logged as `kind`
    // of `feature`), and leaves it in the air when the rebound would lift it at least 5 mm.
    private bool Bounces(ref BallState b, int i, double height, EventKind kind, int feature, double time)
    {
        b.Position = b.Position with { Z = height };
        double impact = _table.Resolve(ref b, Vec3.UnitZ, _params);
        _log.Add(new SimEvent(time, kind, _ids[i], _ids[i], feature, impact));
        if (b.Velocity.Z < _k.BounceThreshold)
        {
            return false;
        }
        b.State = MotionState.Airborne;
        _log.Add(new SimEvent(time, EventKind.BallAirborne, _ids[i], _ids[i], -1, b.Velocity.Z));
        return true;
    }
}
