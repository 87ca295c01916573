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
    /// <summary>A position of the given balls.</summary>
    /// <param name="balls">Ids and centres (m); the order is kept.</param>
    /// <param name="cueBall">The ball the player at the table strikes (<see cref="Ruleset.CueBall"/>).</param>
    public TablePosition(BallLayout balls, BallId cueBall)
    {
        ArgumentNullException.ThrowIfNull(balls);
        Balls = balls;
        CueBall = cueBall;
    }

    /// <inheritdoc cref="TablePosition(BallLayout, BallId)"/>
    public TablePosition(IEnumerable<(BallId Id, Vec3 Position)> balls, BallId cueBall)
        : this(balls as BallLayout ?? new BallLayout(balls), cueBall)
    {
    }

    /// <summary>The balls and their centres.</summary>
    public BallLayout Balls { get; }

    /// <summary>The ball the player at the table strikes; every other ball is an object ball to them.</summary>
    public BallId CueBall { get; }

    /// <summary>Ball ids, index-aligned with <see cref="Positions"/>.</summary>
    public IReadOnlyList<BallId> Ids => Balls.Ids;

    /// <summary>Ball centres (m), index-aligned with <see cref="Ids"/>.</summary>
    public IReadOnlyList<Vec3> Positions => Balls.Positions;

    /// <summary>Number of balls on the table.</summary>
    public int Count => Balls.Count;

    /// <summary>The centre of <see cref="CueBall"/>, or null when it is off the table (pocketed).</summary>
    public Vec3? Cue => Balls.PositionOf(CueBall);

    /// <summary>The object balls on the table: every ball but <see cref="CueBall"/>.</summary>
    public IEnumerable<BallId> ObjectBalls => Balls.Ids.Where(b => b != CueBall);

    /// <summary>This position for a player who strikes <paramref name="cueBall"/>.</summary>
    public TablePosition ForCueBall(BallId cueBall) => cueBall == CueBall ? this : new(Balls, cueBall);

    /// <summary>The balls at rest in a simulation, pocketed ones left out, for a player who strikes <paramref name="cueBall"/>.</summary>
    public static TablePosition Of(Simulation simulation, BallId cueBall)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        return new TablePosition(simulation.InPlay(), cueBall);
    }

    /// <summary>The balls after a shot, pocketed ones left out, for the player who struck it (<see cref="ShotRecord.CueBall"/>).</summary>
    public static TablePosition After(ShotRecord record)
    {
        ArgumentNullException.ThrowIfNull(record);
        return new TablePosition(record.InPlayAfter(), record.CueBall);
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
    public int IndexOf(BallId id) => Balls.IndexOf(id);

    /// <summary>This position with <paramref name="id"/> at <paramref name="position"/>, last in the order (the ball placed last).</summary>
    public TablePosition With(BallId id, Vec3 position) => new(Balls.Without(id).With(id, position), CueBall);

    /// <summary>This position without <paramref name="id"/>.</summary>
    public TablePosition Without(BallId id) => new(Balls.Without(id), CueBall);

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
        var ids = Balls.IdSpan;
        var positions = Balls.PositionSpan;
        for (int i = 0; i < ids.Length; i++)
        {
            if (ids[i] != ignore && Placement.Overlaps(radius, positions[i], p, PlacementMargin))
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

    private Scene Scene(TableSpec table, PhysicsConfig physics) =>
        Scenes.Scene.Of(Balls, table, physics, BallSet.Pool) with { Path = "planner" };
}
