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
        var frame = new RenderFrame { Table = scene.Table, BallSet = scene.BallSet, Width = width, Height = height, BallRadius = (float)scene.BallRadius };
        (frame.Eye, frame.Target) = RenderMath.DefaultCamera(scene.Table, (float)width / height, frame.FovYDegrees);
        if (time <= 0)
        {
            foreach (var ball in scene.Balls)
            {
                frame.Balls.Add(new BallVisual(ball.Id, ToVector(ball.Position), RestingOrientation(ball.Id)));
            }
            if (scene.Balls.FirstOrDefault(b => b.Id == scene.CueBall) is { } cueBall)
            {
                var centre = ToVector(cueBall.Position);
                frame.Cue = scene.Shot is { } shot
                    ? new CueVisual(true, centre, AimOf(shot.AimDeg), (float)shot.ElevationDeg, 0.06f, new Vector2((float)shot.TipSide, (float)shot.TipHeight))
                    : AddressingCue(frame, centre);
            }
            return frame;
        }
        var simulation = SimulationFactory.Create(scene);
        simulation.TrackOrientation = true;
        if (scene.Shot is { } s)
        {
            simulation.Strike(s, scene.CueBall);
        }
        // Bounded as every run is (events, wall clock): a frictionless table never rests.
        SimulationRunner.Advance(simulation, time, new RunOptions(), System.Diagnostics.Stopwatch.StartNew());
        var states = simulation.Balls;
        for (int i = 0; i < states.Length; i++)
        {
            var state = states[i];
            frame.Balls.Add(new BallVisual(simulation.Ids[i], ToVector(state.Position), state.Orientation, !state.IsOutOfPlay));
        }
        // As in the game, the cue is back, addressing the cue ball, once every ball rests.
        int cue = simulation.IndexOf(scene.CueBall);
        if (simulation.IsAtRest && cue >= 0 && !states[cue].IsOutOfPlay)
        {
            frame.Cue = AddressingCue(frame, ToVector(states[cue].Position));
        }
        return frame;
    }

    /// <summary>Elevation of a cue that addresses the ball before a shot is chosen (deg): clear of the rail.</summary>
    public const float AddressElevationDegrees = 5;

    /// <summary>
    /// The cue addressing the cue ball along the view, as the seed aims it (direction = ball - camera
    /// in the bed plane), a little raised and pulled back, hitting the centre.
    /// </summary>
    public static CueVisual AddressingCue(RenderFrame frame, Vector3 cueBall)
    {
        var along = cueBall - frame.Eye;
        along.Z = 0;
        var aim = along.LengthSquared() > 1e-12f ? Vector3.Normalize(along) : Vector3.UnitX;
        return new CueVisual(true, cueBall, aim, AddressElevationDegrees, 0.06f, Vector2.Zero);
    }

    private static Vector3 AimOf(double aimDeg)
    {
        float aim = (float)(aimDeg * Math.PI / 180);
        return new Vector3(MathF.Cos(aim), MathF.Sin(aim), 0);
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
