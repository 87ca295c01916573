using Billiards.App.Nodes;
using Billiards.App.Rendering;
using Billiards.Core.Table;
using System.Numerics;

namespace Billiards.App.Game;

/// <summary>
/// The table: the frame's table and the debug collision view. Until Core exposes its cushion
/// geometry, the debug view shows each cushion's contact plane (the nose line up to the contact
/// height) as two triangles with the normal pointing onto the bed; pocket jaws are not cut out.
/// </summary>
public sealed class TableNode(TableSpec table) : Node
{
    private readonly IReadOnlyList<DebugTriangle> _triangles = CushionPlanes(table);

    /// <summary>The table.</summary>
    public TableSpec Table { get; } = table;

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        frame.Frame.Table = Table;
        frame.Frame.CollisionTriangles = _triangles;
    }

    /// <summary>The four cushion planes as triangles with inward normals (m).</summary>
    public static IReadOnlyList<DebugTriangle> CushionPlanes(TableSpec table)
    {
        float x = (float)table.HalfLength, y = (float)table.HalfWidth, h = (float)table.CushionHeight;
        var list = new List<DebugTriangle>(8);
        void Quad(Vector3 a, Vector3 b, Vector3 normal)
        {
            var up = new Vector3(0, 0, h);
            list.Add(new DebugTriangle(a, b, b + up, normal));
            list.Add(new DebugTriangle(a, b + up, a + up, normal));
        }
        Quad(new(-x, -y, 0), new(x, -y, 0), Vector3.UnitY);   // the y = -W/2 side rail
        Quad(new(x, y, 0), new(-x, y, 0), -Vector3.UnitY);    // the y = +W/2 side rail
        Quad(new(x, -y, 0), new(x, y, 0), -Vector3.UnitX);    // the foot rail
        Quad(new(-x, y, 0), new(-x, -y, 0), Vector3.UnitX);   // the head rail
        return list;
    }
}
