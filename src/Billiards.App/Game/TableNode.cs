using System.Numerics;
using Billiards.App.Nodes;
using Billiards.App.Rendering;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// The table: the frame's table and the debug collision view, which shows the geometry the
/// scene's physics model really collides with: the thesis model's triangles (built by
/// <see cref="Initializer.InitRails"/>, offset a ball radius from the cushion faces, as the seed's
/// debug draw shows them), or the standard model's cushion segments and jaw noses (<see cref="TableGeometry"/>)
/// as vertical faces up to the contact height.
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
    public static IReadOnlyList<DebugTriangle> CollisionGeometryOf(Scene scene) =>
        scene.Physics.Model == Models.Thesis ? ThesisTriangles(scene.Table) : StandardFaces(scene.Table, scene.Physics.Params.R);

    private static List<DebugTriangle> ThesisTriangles(TableSpec table) =>
        [.. Initializer.InitRails(table).Select(t => new DebugTriangle(
            ToVector(SeedFrame.ToSi(t.P1)), ToVector(SeedFrame.ToSi(t.P2)), ToVector(SeedFrame.ToSi(t.P3)), Vector3.Normalize(ToVector(SeedFrame.ToSi(t.Normal)))))];

    private static List<DebugTriangle> StandardFaces(TableSpec table, double radius)
    {
        var geometry = TableGeometry.Build(table, radius);
        float h = (float)table.CushionHeight;
        var list = new List<DebugTriangle>();
        void Quad(Vector3 a, Vector3 b, Vector3 normal)
        {
            var up = new Vector3(0, 0, h);
            list.Add(new DebugTriangle(a, b, b + up, normal));
            list.Add(new DebugTriangle(a, b + up, a + up, normal));
        }
        foreach (var s in geometry.Segments)
        {
            Quad(ToVector(s.Start), ToVector(s.End), ToVector(s.Normal));
        }
        // A nose is a vertical cylinder: eight faces around it, each with its outward normal.
        const int Sides = 8;
        foreach (var nose in geometry.Noses)
        {
            for (int k = 0; k < Sides; k++)
            {
                double a0 = 2 * Math.PI * k / Sides, a1 = 2 * Math.PI * (k + 1) / Sides, mid = (a0 + a1) / 2;
                var p0 = nose.Centre + new Vec3(Math.Cos(a0), Math.Sin(a0), 0) * nose.Radius;
                var p1 = nose.Centre + new Vec3(Math.Cos(a1), Math.Sin(a1), 0) * nose.Radius;
                Quad(ToVector(p0), ToVector(p1), new Vector3((float)Math.Cos(mid), (float)Math.Sin(mid), 0));
            }
        }
        return list;
    }

    private static Vector3 ToVector(Vec3 v) => new((float)v.X, (float)v.Y, (float)v.Z);
}
