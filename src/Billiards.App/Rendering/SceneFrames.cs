using System.Numerics;
using Billiards.Core.Balls;
using Billiards.Core.Scenes;

namespace Billiards.App.Rendering;

/// <summary>Builds the <see cref="RenderFrame"/> of a scene at a time, for `render` and tests.</summary>
public static class SceneFrames
{
    /// <summary>
    /// The scene at <paramref name="time"/> seconds: at 0, the balls as placed (and the cue
    /// addressing the cue ball when the scene has a shot); later, the simulation's state after the
    /// shot, with orientations tracked. Default camera: <see cref="RenderMath.DefaultCamera"/>.
    /// </summary>
    public static RenderFrame Build(Scene scene, double time, int width, int height)
    {
        var frame = new RenderFrame { Table = scene.Table, Width = width, Height = height, BallRadius = (float)scene.BallRadius };
        (frame.Eye, frame.Target) = RenderMath.DefaultCamera(scene.Table, (float)width / height, frame.FovYDegrees);
        if (time <= 0)
        {
            foreach (var ball in scene.Balls)
            {
                frame.Balls.Add(new BallVisual(ball.Id, ToVector(ball.Position), RestingOrientation(ball.Id)));
            }
            if (scene.Shot is { } shot && scene.Balls.FirstOrDefault(b => b.Id.IsCue) is { } cueBall)
            {
                float aim = (float)(shot.AimDeg * Math.PI / 180);
                frame.Cue = new CueVisual(true, ToVector(cueBall.Position), new Vector3(MathF.Cos(aim), MathF.Sin(aim), 0),
                    (float)shot.ElevationDeg, 0.06f, new Vector2((float)shot.TipSide, (float)shot.TipHeight));
            }
            return frame;
        }
        Billiards.Core.Physics.Simulation simulation;
        try
        {
            simulation = SimulationFactory.Create(scene);
            simulation.TrackOrientation = true;
            if (scene.Shot is { } s)
            {
                simulation.Strike(s);
            }
            simulation.AdvanceTo(time);
        }
        catch (NotImplementedException)
        {
            throw new Cli.CliException($"--at {time}: the '{scene.Physics.Model}' physics model cannot simulate yet");
        }
        var states = simulation.Balls;
        for (int i = 0; i < states.Length; i++)
        {
            var state = states[i];
            frame.Balls.Add(new BallVisual(simulation.Ids[i], ToVector(state.Position), state.Orientation, !state.IsPocketed));
        }
        return frame;
    }

    /// <summary>
    /// How a ball rests before play: its number turned towards the head rail (where the default
    /// camera stands) and tipped up a little, each ball turned a little differently so the rack looks natural.
    /// </summary>
    public static Quaternion RestingOrientation(BallId id)
    {
        // The number discs are on the ball's x axis; the -x disc faces the head rail, tipped up by the pitch.
        float yaw = ((id.Value * 37) % 50 - 25) * MathF.PI / 180;
        float pitch = 30 * MathF.PI / 180;
        return Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw) * Quaternion.CreateFromAxisAngle(Vector3.UnitY, pitch);
    }

    private static Vector3 ToVector(Billiards.Core.Mathematics.Vec3 v) => new((float)v.X, (float)v.Y, (float)v.Z);
}
