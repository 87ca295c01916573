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
    /// <summary>The model of a table and physics configuration, with the given collision models.</summary>
    public StandardTableModel(TableSpec table, PhysicsConfig physics, IBallBallModel ballBall, IBallCushionModel ballCushion)
        : base(table, physics)
    {
        Parameters = physics.Params;
        Constants = new MotionConstants(Parameters);
        Geometry = TableGeometry.Build(table, Parameters.R);
        BallBall = ballBall;
        BallCushion = ballCushion;
        Features = new FeatureBoxes(Geometry, Parameters.R);
    }

    /// <summary>The model of a table and physics configuration with the default collision models.</summary>
    public StandardTableModel(TableSpec table, PhysicsConfig physics)
        : this(table, physics, FrictionalInelastic.Instance, Han2005.Instance)
    {
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

    internal FeatureBoxes Features { get; }

    /// <inheritdoc />
    protected override Simulation Create(Scene scene) => new StandardSimulation(this, scene);
}
