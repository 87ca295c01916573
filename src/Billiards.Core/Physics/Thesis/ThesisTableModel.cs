using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Physics.Thesis;

/// <summary>
/// The thesis model's shared, immutable part: the 72 collision triangles of the rails
/// (<see cref="Initializer.InitRails"/>), their bed-plane cull, and the table in the seed's units.
/// </summary>
public sealed class ThesisTableModel : TableModel
{
    /// <summary>The model of a table and physics configuration.</summary>
    public ThesisTableModel(TableSpec table, PhysicsConfig physics)
        : base(table, physics)
    {
        RailArray = Initializer.InitRails(table);
        Cull = new RailCull(RailArray);
        SeedTable = ThesisTable.From(table);
    }

    /// <summary>The collision triangles (never changed).</summary>
    public IReadOnlyList<CollisionGeometry> Rails => RailArray;

    /// <summary>The table in the seed's units, for the pocket test.</summary>
    public ThesisTable SeedTable { get; }

    // The engines read the triangles and never change them.
    internal CollisionGeometry[] RailArray { get; }

    internal RailCull Cull { get; }

    /// <inheritdoc />
    protected override Simulation Create(Scene scene) => new ThesisSimulation(this, scene);
}
