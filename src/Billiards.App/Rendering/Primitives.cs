using System.Numerics;

namespace Billiards.App.Rendering;

/// <summary>The balls' sphere and the cue, built in code.</summary>
public static class Primitives
{
    /// <summary>Cue length (m): the seed's 145 cm.</summary>
    public const float CueLength = (float)Billiards.Core.Cue.CueClearance.CueLength;

    /// <summary>Radius at the tip (m): 0.5 cm.</summary>
    public const float CueTipRadius = (float)Billiards.Core.Cue.CueClearance.TipRadius;

    /// <summary>Radius at the butt (m): 1.25 cm, closed by a sphere of 1.26 cm.</summary>
    public const float CueButtRadius = (float)Billiards.Core.Cue.CueClearance.ButtRadius;

    /// <summary>
    /// A unit sphere of <paramref name="slices"/> x <paramref name="stacks"/> quads; uv is the
    /// equirectangular mapping of <see cref="BallTextures"/> (u longitude from +x, v latitude from -z).
    /// </summary>
    public static MeshBuilder Sphere(int slices = 64, int stacks = 48)
    {
        var mesh = new MeshBuilder(new MeshMaterial("ball", Vector3.One, Vector3.One, 100));
        for (int j = 0; j <= stacks; j++)
        {
            float v = (float)j / stacks;
            for (int i = 0; i <= slices; i++)
            {
                float u = (float)i / slices;
                var d = BallTextures.Direction(u, v);
                mesh.Vertex(d, d, new Vector2(u, v));
            }
        }
        for (int j = 0; j < stacks; j++)
        {
            for (int i = 0; i < slices; i++)
            {
                uint a = (uint)((j * (slices + 1)) + i), b = a + 1, c = a + (uint)slices + 1, d = c + 1;
                mesh.Triangle(a, b, d);
                mesh.Triangle(a, d, c);
            }
        }
        return mesh;
    }

    /// <summary>
    /// The cue in its own frame: the tip at the origin, the butt at x = -<see cref="CueLength"/>,
    /// a cone from the tip radius to the butt radius with coloured sections (chalked tip, ferrule,
    /// maple shaft, joint, ebony forearm, wrap, butt cap), closed at the butt by a sphere.
    /// </summary>
    public static MeshBuilder Cue(int sides = 32)
    {
        var mesh = new MeshBuilder(new MeshMaterial("cue", Vector3.One, new Vector3(0.35f), 50));
        (float From, Vector3 Color)[] sections =
        [
            (0.000f, new(0.18f, 0.36f, 0.62f)), // chalked leather tip
            (0.012f, new(0.95f, 0.93f, 0.86f)), // ferrule
            (0.035f, new(0.87f, 0.72f, 0.50f)), // maple shaft
            (0.760f, new(0.80f, 0.80f, 0.78f)), // joint ring
            (0.780f, new(0.10f, 0.06f, 0.05f)), // ebony forearm
            (1.050f, new(0.55f, 0.08f, 0.06f)), // inlay ring
            (1.060f, new(0.08f, 0.08f, 0.09f)), // wrap
            (1.350f, new(0.55f, 0.08f, 0.06f)), // ring
            (1.360f, new(0.12f, 0.07f, 0.05f)), // butt sleeve
            (1.430f, new(0.05f, 0.05f, 0.05f)), // butt cap
        ];
        float Radius(float x) => CueTipRadius + ((CueButtRadius - CueTipRadius) * x / CueLength);
        float slope = (CueButtRadius - CueTipRadius) / CueLength;
        for (int s = 0; s < sections.Length; s++)
        {
            float x0 = sections[s].From;
            float x1 = s + 1 < sections.Length ? sections[s + 1].From : CueLength;
            var color = sections[s].Color;
            float r0 = Radius(x0), r1 = Radius(x1);
            uint first = (uint)mesh.Positions.Count;
            for (int i = 0; i <= sides; i++)
            {
                float a = 2 * MathF.PI * i / sides;
                var radial = new Vector3(0, MathF.Cos(a), MathF.Sin(a));
                // The cone's normal leans towards the tip.
                var normal = Vector3.Normalize(radial + new Vector3(slope, 0, 0));
                mesh.Vertex(new Vector3(-x0, 0, 0) + (r0 * radial), normal, default, color);
                mesh.Vertex(new Vector3(-x1, 0, 0) + (r1 * radial), normal, default, color);
            }
            for (int i = 0; i < sides; i++)
            {
                uint a = first + (uint)(2 * i);
                mesh.Triangle(a, a + 1, a + 3);
                mesh.Triangle(a, a + 3, a + 2);
            }
        }
        // The tip: a shallow dome over the tip's radius.
        var tipColor = sections[0].Color;
        uint centre = mesh.Vertex(new Vector3(0.0012f, 0, 0), Vector3.UnitX, default, tipColor);
        uint ring = (uint)mesh.Positions.Count;
        for (int i = 0; i <= sides; i++)
        {
            float a = 2 * MathF.PI * i / sides;
            var radial = new Vector3(0, MathF.Cos(a), MathF.Sin(a));
            mesh.Vertex(CueTipRadius * radial, Vector3.Normalize(radial + new Vector3(1.5f, 0, 0)), default, tipColor);
        }
        for (int i = 0; i < sides; i++)
        {
            mesh.Triangle(centre, ring + (uint)i, ring + (uint)i + 1);
        }
        // The butt: a sphere of radius 1.26 cm, its back half showing.
        const float ButtSphere = 0.0126f;
        const int Stacks = 8;
        var buttColor = sections[^1].Color;
        var buttCentre = new Vector3(-CueLength, 0, 0);
        uint start = (uint)mesh.Positions.Count;
        for (int j = 0; j <= Stacks; j++)
        {
            float polar = MathF.PI / 2 * j / Stacks; // 0 at the rim, pi/2 at the very end
            for (int i = 0; i <= sides; i++)
            {
                float a = 2 * MathF.PI * i / sides;
                var d = new Vector3(-MathF.Sin(polar), MathF.Cos(polar) * MathF.Cos(a), MathF.Cos(polar) * MathF.Sin(a));
                mesh.Vertex(buttCentre + (ButtSphere * d), d, default, buttColor);
            }
        }
        for (int j = 0; j < Stacks; j++)
        {
            for (int i = 0; i < sides; i++)
            {
                uint a = start + (uint)((j * (sides + 1)) + i), b = a + 1, c = a + (uint)sides + 1, d = c + 1;
                mesh.Triangle(a, b, d);
                mesh.Triangle(a, d, c);
            }
        }
        return mesh;
    }

    /// <summary>
    /// The cue's model matrix (row vectors) for a frame's <see cref="CueVisual"/> and ball radius:
    /// the cue's x axis along the stroke (tilted down by the elevation), its tip at the contact point
    /// given by the tip offset, pulled back by <see cref="CueVisual.PullBack"/>.
    /// </summary>
    public static Matrix4x4 CuePlacement(CueVisual cue, float ballRadius)
    {
        var aim = new Vector3(cue.AimDirection.X, cue.AimDirection.Y, 0);
        aim = aim.LengthSquared() > 1e-12f ? Vector3.Normalize(aim) : Vector3.UnitX;
        float elevation = cue.ElevationDegrees * MathF.PI / 180;
        var forward = (aim * MathF.Cos(elevation)) - (Vector3.UnitZ * MathF.Sin(elevation));
        var up = (aim * MathF.Sin(elevation)) + (Vector3.UnitZ * MathF.Cos(elevation));
        var right = new Vector3(aim.Y, -aim.X, 0);
        float side = Math.Clamp(cue.TipOffset.X, -0.95f, 0.95f);
        float height = Math.Clamp(cue.TipOffset.Y, -0.95f, 0.95f);
        float depth = MathF.Sqrt(MathF.Max(0, 1 - (side * side) - (height * height)));
        var contact = cue.BallCentre + (ballRadius * ((side * right) + (height * up) - (depth * forward)));
        var tip = contact - (forward * MathF.Max(0, cue.PullBack));
        var y = Vector3.Cross(up, forward);
        return new Matrix4x4(
            forward.X, forward.Y, forward.Z, 0,
            y.X, y.Y, y.Z, 0,
            up.X, up.Y, up.Z, 0,
            tip.X, tip.Y, tip.Z, 1);
    }
}
