using Billiards.App.Game;
using Billiards.App.Nodes;
using Billiards.Core.Mathematics;

namespace Billiards.App.Camera;

/// <summary>
/// The game's camera: an <see cref="OrbitCamera"/> around the cue ball. When the balls come to rest
/// it moves by the cue ball's displacement over the shot (seed 4.3), so the view is kept; while
/// they roll it keeps orbiting the cue ball's previous centre (seed 4.4.3).
/// </summary>
public sealed class CameraNode : Node
{
    /// <summary>Start: polar angle from the vertical (rad), about 20° above the bed, a player's eye line.</summary>
    public const double StartTheta = 1.22;

    /// <summary>Start: behind the cue ball looking along +x, towards the rack on the foot spot.</summary>
    public const double StartPhi = Math.PI;

    /// <summary>Start: distance to the cue ball (m).</summary>
    public const double StartDistance = 1.0;

    /// <summary>Start without a cue ball: distance from the table centre (m), to see the whole bed.</summary>
    public const double OverviewDistance = 3.0;

    /// <summary>Start without a cue ball: polar angle (rad), looking down steeply.</summary>
    public const double OverviewTheta = 0.7;

    /// <summary>Vertical field of view (deg).</summary>
    public const float FovYDegrees = 45;

    private PhysicsNode? _physics;

    /// <summary>The camera; valid from <see cref="Node.Ready"/> on (placed at the table centre until then).</summary>
    public OrbitCamera Camera { get; private set; } = new(Vec3.Zero, OverviewTheta, StartPhi, OverviewDistance);

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        Camera = _physics.HasCueBall
            ? new OrbitCamera(_physics.CueBallPosition, StartTheta, StartPhi, StartDistance)
            : new OrbitCamera(new Vec3(0, 0, _physics.BallRadius), OverviewTheta, StartPhi, OverviewDistance);
        _physics.CameToRest += OnCameToRest;
    }

    private void OnCameToRest(Vec3 cueDisplacement)
    {
        // Seed 4.3: the camera moves by the cue ball's displacement; a pocketed cue ball leaves it put.
        if (_physics is { HasCueBall: true })
        {
            Camera.Translate(cueDisplacement);
        }
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        frame.Frame.Eye = Camera.Eye.ToVector3();
        frame.Frame.Target = Camera.Centre.ToVector3();
        frame.Frame.FovYDegrees = FovYDegrees;
    }
}
