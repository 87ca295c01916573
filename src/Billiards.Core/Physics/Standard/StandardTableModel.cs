using Billiards.Core.Physics.Collisions;
using Billiards.Core.Physics.Standard.Events;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard;

/// <summary>
/// The standard model's shared, immutable part: parameters, motion constants, the table's collision
/// geometry with its broad-phase boxes, and the collision models (which keep no state).
/// </summary>
public sealed class StandardTableModel : TableModel
{
    /// <summary>The model of a table and physics configuration, with its collision models (<see cref="PhysicsConfig.Models"/>).</summary>
    public StandardTableModel(TableSpec table, PhysicsConfig physics)
        : base(table, physics)
    {
        ArgumentNullException.ThrowIfNull(physics);
        Parameters = physics.Params;
        Constants = new MotionConstants(Parameters);
        Geometry = TableGeometry.Build(table, Parameters.R);
        BallBall = physics.Models.BallBall;
        BallCushion = physics.Models.BallCushion;
        BallTable = physics.Models.BallTable;
        BallPocket = physics.Models.BallPocket;
        Features = new FeatureBoxes(Geometry, Parameters.R);
    }

    /// <summary>The model parameters.</summary>
    public PhysicsParams Parameters { get; }

    /// <summary>The motion constants derived from <see cref="Parameters"/>.</summary>
    public MotionConstants Constants { get; }

    /// <summary>The table's collision geometry.</summary>
    public TableGeometry Geometry { get; }

    /// <summary>Ball-ball collision model.</summary>
    public IBallBallModel BallBall { get; }

    /// <summary>Ball-cushion collision model.</summary>
    public IBallCushionModel BallCushion { get; }

    /// <summary>Ball-table model: landings on the bed and on the rails' top.</summary>
    public IBallTableModel BallTable { get; }

    /// <summary>Ball-pocket model: drops into the holes.</summary>
    public IBallPocketModel BallPocket { get; }

    internal FeatureBoxes Features { get; }

    /// <inheritdoc />
    protected override Simulation Create(Scene scene) => new StandardSimulation(this, scene);
}
