using System.Numerics;
using Billiards.App.Nodes;
using Billiards.App.Rendering;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// The table: the frame's table and the debug collision view, which shows the geometry the
/// scene's physics model really collides with (<see cref="PhysicsModel.CollisionFaces"/>).
/// </summary>
public sealed class TableNode(Scene scene) : Node
{
    private readonly IReadOnlyList<DebugTriangle> _triangles = CollisionGeometryOf(scene);

    /// <summary>The table.</summary>
    public TableSpec Table { get; } = scene.Table;

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        frame.Frame.Table = Table;
        frame.Frame.CollisionTriangles = _triangles;
    }

    /// <summary>The collision geometry of the scene's model as triangles with unit normals pointing onto the bed (m).</summary>
    public static IReadOnlyList<DebugTriangle> CollisionGeometryOf(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        return [.. scene.Physics.Model.CollisionFaces(scene.Table, scene.Physics.Params)
            .Select(f => new DebugTriangle(ToVector(f.A), ToVector(f.B), ToVector(f.C), ToVector(f.Normal)))];
    }

    private static Vector3 ToVector(Vec3 v) => new((float)v.X, (float)v.Y, (float)v.Z);
}
