using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>
/// The balls on the table between two shots (pocketed balls are left out), as the planner and the
/// self-play loop see them: ids and centres (m, z = R). Immutable.
/// </summary>
public sealed class TablePosition
{
    private readonly BallId[] _ids;
    private readonly Vec3[] _positions;

    /// <summary>A position of the given balls.</summary>
    /// <param name="balls">Ids and centres (m); the order is kept.</param>
    /// <param name="cueBall">The ball the player at the table strikes (<see cref="Ruleset.CueBall"/>).</param>
    public TablePosition(IEnumerable<(BallId Id, Vec3 Position)> balls, BallId cueBall)
    {
        ArgumentNullException.ThrowIfNull(balls);
        var list = balls.ToList();
        _ids = [.. list.Select(b => b.Id)];
        _positions = [.. list.Select(b => b.Position)];
        CueBall = cueBall;
    }

    /// <summary>The ball the player at the table strikes; every other ball is an object ball to them.</summary>
    public BallId CueBall { get; }

    /// <summary>Ball ids, index-aligned with <see cref="Positions"/>.</summary>
    public IReadOnlyList<BallId> Ids => _ids;

    /// <summary>Ball centres (m), index-aligned with <see cref="Ids"/>.</summary>
    public IReadOnlyList<Vec3> Positions => _positions;

    /// <summary>Number of balls on the table.</summary>
    public int Count => _ids.Length;

    /// <summary>The centre of <see cref="CueBall"/>, or null when it is off the table (pocketed).</summary>
    public Vec3? Cue => IndexOf(CueBall) is var i and >= 0 ? _positions[i] : null;

    /// <summary>The object balls on the table: every ball but <see cref="CueBall"/>.</summary>
    public IEnumerable<BallId> ObjectBalls => _ids.Where(b => b != CueBall);

    /// <summary>This position for a player who strikes <paramref name="cueBall"/>.</summary>
    public TablePosition ForCueBall(BallId cueBall) => cueBall == CueBall ? this : new(Enumerate(), cueBall);

    /// <summary>The balls at rest in a simulation, pocketed ones left out, for a player who strikes <paramref name="cueBall"/>.</summary>
    public static TablePosition Of(Simulation simulation, BallId cueBall)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        var list = new List<(BallId, Vec3)>();
        var balls = simulation.Balls;
        for (int i = 0; i < balls.Length; i++)
        {
            if (!balls[i].IsOutOfPlay)
            {
                list.Add((simulation.Ids[i], balls[i].Position));
            }
        }
        return new TablePosition(list, cueBall);
    }

    /// <summary>The balls after a shot, pocketed ones left out, for the player who struck it (<see cref="ShotRecord.CueBall"/>).</summary>
    public static TablePosition After(ShotRecord record)
    {
        ArgumentNullException.ThrowIfNull(record);
        var list = new List<(BallId, Vec3)>();
        var balls = record.BallsAfter;
        var ids = record.Ids;
        for (int i = 0; i < balls.Length; i++)
        {
            if (!balls[i].IsOutOfPlay)
            {
                list.Add((ids[i], balls[i].Position));
            }
        }
        return new TablePosition(list, record.CueBall);
    }

    /// <summary>A fresh rack of <paramref name="rack"/> with <paramref name="cueBall"/> where the rack puts it (the head spot; snooker's rack has it in the D).</summary>
    public static TablePosition Rack(RackSpec rack, TableSpec table, double radius, BallId cueBall)
    {
        var racked = Initializer.Rack(rack, table, radius);
        var balls = new List<(BallId, Vec3)>();
        if (!racked.Any(b => b.Id == cueBall))
        {
            balls.Add((cueBall, Initializer.HeadSpot(table, radius)));
        }
        balls.AddRange(racked);
        return new TablePosition(balls, cueBall);
    }

    /// <summary>Index of a ball, or -1 when it is not on the table.</summary>
    public int IndexOf(BallId id) => Array.IndexOf(_ids, id);

    /// <summary>This position with <paramref name="id"/> at <paramref name="position"/> (added if absent).</summary>
    public TablePosition With(BallId id, Vec3 position)
    {
        var list = Enumerate().Where(b => b.Id != id).ToList();
        list.Add((id, position));
        return new TablePosition(list, CueBall);
    }

    /// <summary>This position without <paramref name="id"/>.</summary>
    public TablePosition Without(BallId id) => new(Enumerate().Where(b => b.Id != id), CueBall);

    /// <summary>
    /// True when a ball of radius <paramref name="radius"/> at <paramref name="p"/> may be placed
    /// there (<see cref="Placement.FitsOnTable"/>: on the bed inside the region, over no pocket) and
    /// touches no ball but <paramref name="ignore"/>, a small margin clear of every limit.
    /// </summary>
    public bool CanPlace(Vec3 p, BallInHand region, TableSpec table, double radius, BallId ignore)
    {
        ArgumentNullException.ThrowIfNull(table);
        if (!Placement.FitsOnTable(table, radius, p, region.Region(), PlacementMargin))
        {
            return false;
        }
        for (int i = 0; i < _ids.Length; i++)
        {
            if (_ids[i] != ignore && Placement.Overlaps(radius, _positions[i], p, PlacementMargin))
            {
                return false;
            }
        }
        return true;
    }

    // The planner's placements keep this far (m) from every limit of the placement test.
    private const double PlacementMargin = 1e-4;

    /// <summary>
    /// A simulation of this position with the standard model's event integrator (the fastest),
    /// the planner's way to try shots: <see cref="Simulation.Reset"/> brings it back here.
    /// </summary>
    public StandardSimulation CreateSimulation(TableSpec table, PhysicsParams physics) =>
        new(Scene(table, PlannerPhysics(physics)));

    /// <summary>
    /// A simulation of this position on a shared table model (no geometry is built): its
    /// snapshots restore into every other simulation of the same model and balls.
    /// </summary>
    public Simulation CreateSimulation(TableModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        return model.CreateSimulation(Scene(model.Table, model.Physics));
    }

    /// <summary>The physics the planner simulates with: the standard model's event integrator, <paramref name="physics"/> and the collision models (the defaults when null).</summary>
    public static PhysicsConfig PlannerPhysics(PhysicsParams physics, Physics.Collisions.InteractionModels? models = null) =>
        new(ModelRegistry.Standard, ModelRegistry.Event, PhysicsConfig.DefaultDt, physics) { Models = models ?? Physics.Collisions.InteractionModels.Default };

    private Scene Scene(TableSpec table, PhysicsConfig physics)
    {
        var balls = Enumerate().Select(b => new BallSetup(b.Id, b.Position, Vec3.Zero, Vec3.Zero)).ToList();
        return new Scene("planner", null, table, physics, null, balls, null, null);
    }

    /// <summary>The balls as (id, centre) pairs.</summary>
    public IEnumerable<(BallId Id, Vec3 Position)> Enumerate()
    {
        for (int i = 0; i < _ids.Length; i++)
        {
            yield return (_ids[i], _positions[i]);
        }
    }
}
