using System.Numerics;
using Billiards.Core.Table;

namespace Billiards.App.Rendering;

/// <summary>
/// The room round the table, drawn with it: four walls and a ceiling a few metres off, and the
/// lamps over the bed (the seed's three at <see cref="Renderer.LampHeight"/>) with their shades,
/// whose undersides glow. Plain and few triangles: the walls are only refined as far as their
/// light, lit at the vertices, needs. Metres, Core's frame (z up, origin at the bed's centre).
/// </summary>
public static class Room
{
    /// <summary>Clearance from the table's outline to the walls (m).</summary>
    public const float WallClearance = 2.2f;

    /// <summary>Height of the ceiling above the floor (m).</summary>
    public const float CeilingHeight = 2.9f;

    /// <summary>Radius of a lamp shade's rim (m): the renderer's lamp radius.</summary>
    public const float ShadeRadius = Renderer.LampRadius;

    /// <summary>Height of a lamp shade (m).</summary>
    public const float ShadeHeight = 0.16f;

    public static readonly MeshMaterial Wall = new("wall", new(0.42f, 0.36f, 0.29f), new(0.02f, 0.02f, 0.02f), 4);
    public static readonly MeshMaterial Ceiling = new("ceiling", new(0.30f, 0.28f, 0.26f), new(0.0f, 0.0f, 0.0f), 1);
    public static readonly MeshMaterial Shade = new("shade", new(0.05f, 0.22f, 0.12f), new(0.5f, 0.5f, 0.5f), 60);
    public static readonly MeshMaterial Bulb = new("bulb", new(1.0f, 0.95f, 0.82f), new(0, 0, 0), 1);

    /// <summary>True when <paramref name="eye"/> is inside the walls and under the ceiling.</summary>
    public static bool Contains(TableSpec table, Vector3 eye) =>
        MathF.Abs(eye.X) < table.HalfLength + WallClearance && MathF.Abs(eye.Y) < table.HalfWidth + WallClearance
        && eye.Z < -TableModelGenerator.BedHeight + CeilingHeight;

    /// <summary>The four walls.</summary>
    public static MeshBuilder Walls(TableSpec table)
    {
        float hx = (float)table.HalfLength + WallClearance, hy = (float)table.HalfWidth + WallClearance;
        float floor = -TableModelGenerator.BedHeight, top = floor + CeilingHeight;
        var walls = new MeshBuilder(Wall);
        // Each wall faces the table (its normal points inwards).
        walls.Quad(new(-hx, -hy, floor), new(hx, -hy, floor), new(hx, -hy, top), new(-hx, -hy, top), Vector3.UnitY);
        walls.Quad(new(hx, hy, floor), new(-hx, hy, floor), new(-hx, hy, top), new(hx, hy, top), -Vector3.UnitY);
        walls.Quad(new(hx, -hy, floor), new(hx, hy, floor), new(hx, hy, top), new(hx, -hy, top), -Vector3.UnitX);
        walls.Quad(new(-hx, hy, floor), new(-hx, -hy, floor), new(-hx, -hy, top), new(-hx, hy, top), Vector3.UnitX);
        return walls;
    }

    /// <summary>The ceiling over the walls.</summary>
    public static MeshBuilder CeilingMesh(TableSpec table)
    {
        float hx = (float)table.HalfLength + WallClearance, hy = (float)table.HalfWidth + WallClearance;
        float top = -TableModelGenerator.BedHeight + CeilingHeight;
        var ceiling = new MeshBuilder(Ceiling);
        ceiling.Quad(new(-hx, -hy, top), new(-hx, hy, top), new(hx, hy, top), new(hx, -hy, top), -Vector3.UnitZ);
        return ceiling;
    }

    /// <summary>
    /// The lamp shades: open cones over each lamp, rim at <see cref="Renderer.LampHeight"/>, with a
    /// rod to the ceiling. <paramref name="lamps"/> holds x, y, z, intensity per lamp.
    /// </summary>
    public static MeshBuilder Shades(ReadOnlySpan<float> lamps)
    {
        const int Sides = 24;
        var shades = new MeshBuilder(Shade);
        float top = -TableModelGenerator.BedHeight + CeilingHeight;
        for (int k = 0; k + 3 < lamps.Length; k += 4)
        {
            var c = new Vector3(lamps[k], lamps[k + 1], lamps[k + 2]);
            float topRadius = 0.35f * ShadeRadius;
            for (int i = 0; i < Sides; i++)
            {
                float a0 = i * 2 * MathF.PI / Sides, a1 = (i + 1) * 2 * MathF.PI / Sides;
                var d0 = new Vector3(MathF.Cos(a0), MathF.Sin(a0), 0);
                var d1 = new Vector3(MathF.Cos(a1), MathF.Sin(a1), 0);
                // The cone's outward normal leans up by the slope of its side.
                float slope = (ShadeRadius - topRadius) / ShadeHeight;
                var n0 = Vector3.Normalize(d0 + new Vector3(0, 0, slope));
                var n1 = Vector3.Normalize(d1 + new Vector3(0, 0, slope));
                shades.Quad(c + (ShadeRadius * d0), c + (ShadeRadius * d1), c + (topRadius * d1) + new Vector3(0, 0, ShadeHeight), c + (topRadius * d0) + new Vector3(0, 0, ShadeHeight), n0, n1, n1, n0);
                // The rod, a thin square tube up to the ceiling.
                if (i % (Sides / 4) == 0)
                {
                    var r0 = c + (0.006f * d0) + new Vector3(0, 0, ShadeHeight);
                    var r1 = c + (0.006f * new Vector3(MathF.Cos(a0 + (MathF.PI / 2)), MathF.Sin(a0 + (MathF.PI / 2)), 0)) + new Vector3(0, 0, ShadeHeight);
                    shades.Quad(r0, r1, new(r1.X, r1.Y, top), new(r0.X, r0.Y, top), d0);
                }
            }
        }
        return shades;
    }

    /// <summary>The glowing discs under the shades, facing down.</summary>
    public static MeshBuilder Bulbs(ReadOnlySpan<float> lamps)
    {
        const int Sides = 24;
        var bulbs = new MeshBuilder(Bulb);
        for (int k = 0; k + 3 < lamps.Length; k += 4)
        {
            var c = new Vector3(lamps[k], lamps[k + 1], lamps[k + 2] + 0.02f);
            uint centre = bulbs.Vertex(c, -Vector3.UnitZ);
            for (int i = 0; i < Sides; i++)
            {
                float a = i * 2 * MathF.PI / Sides;
                bulbs.Vertex(c + (0.9f * ShadeRadius * new Vector3(MathF.Cos(a), MathF.Sin(a), 0)), -Vector3.UnitZ);
            }
            for (int i = 0; i < Sides; i++)
            {
                bulbs.Triangle(centre, centre + 1 + (uint)((i + 1) % Sides), centre + 1 + (uint)i);
            }
        }
        return bulbs;
    }
}
