using System.Numerics;
using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// Calling with the mouse: a click (press and release without a drag) on a ball calls that ball
/// (with its easiest pocket; in snooker it nominates the ball), a click then on a pocket calls that pocket. A drag still orbits
/// the camera; the click is told from it by moving less than <see cref="ClickSlopPixels"/>.
/// </summary>
public sealed class CallPickerNode : Node
{
    /// <summary>Largest movement (pixels) between press and release that is still a click.</summary>
    public const float ClickSlopPixels = 4;

    private MatchNode? _match;
    private PhysicsNode? _physics;
    private Camera.CameraNode? _camera;
    private PocketSet _pocketSet = PocketSet.None;
    private PocketCircle[] _pockets = [];
    private Matrix4x4 _viewProjection;
    private (int Width, int Height) _size;
    private Vector2? _down;

    /// <inheritdoc />
    protected override void Ready()
    {
        _match = GetInTree<MatchNode>();
        _physics = GetInTree<PhysicsNode>();
        _camera = FindInTree<Camera.CameraNode>();
        _pockets = TableGeometry.Build(_physics.Table, _physics.BallRadius).Pockets.ToArray();
        _pocketSet = _physics.Table.Pockets;
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        switch (e)
        {
            case MouseButtonInput { Button: MouseButton.Left, Pressed: true } down:
                _down = down.Position;
                return false;
            case MouseButtonInput { Button: MouseButton.Left, Pressed: false } up when _down is { } start:
                _down = null;
                if (Vector2.Distance(start, up.Position) <= ClickSlopPixels)
                {
                    Click(up.Position);
                }
                // The release goes on to the control modes, which track the button.
                return false;
            default:
                return false;
        }
    }

    // The ball under the cursor calls that ball; else, with a ball called, the pocket under it.
    private bool Click(Vector2 at)
    {
        if (_match is not { CanShoot: true, IsWatching: false } match || !(match.NeedsCall || match.NeedsNomination) || _physics is null || _size.Width == 0)
        {
            return false;
        }
        if (_camera is not null)
        {
            // The view of the click's moment: a view switched (T) in the same frame counts.
            var (eye, target) = _camera.View(_size.Width, _size.Height);
            _viewProjection = RenderMath.View(eye, target) * RenderMath.Projection(Camera.CameraNode.FovYDegrees, (float)_size.Width / Math.Max(1, _size.Height)) * RenderMath.BelowHud(_camera.FramesBelowHud ? RenderMath.HudInset(_size.Height) : 0);
        }
        var sim = _physics.Simulation;
        float r = (float)_physics.BallRadius;
        BallId? best = null;
        float bestDistance = float.MaxValue;
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            if (sim.Ids[i] == _physics.CueBall || sim.Balls[i].IsPocketed)
            {
                continue;
            }
            var p = sim.Balls[i].Position.ToVector3();
            if (Pixel(p) is { } centre && Pixel(p + new Vector3(r, 0, 0)) is { } edge)
            {
                float d = Vector2.Distance(centre, at);
                float reach = MathF.Max(Vector2.Distance(centre, edge), Vector2.Distance(centre, Pixel(p + new Vector3(0, r, 0)) ?? centre)) + 3;
                if (d <= reach && d < bestDistance)
                {
                    (best, bestDistance) = (sim.Ids[i], d);
                }
            }
        }
        if (best is { } ball)
        {
            match.Call.CallBall(ball);
            return true;
        }
        if (!match.NeedsCall)
        {
            // A nomination names a ball, never a pocket.
            return false;
        }
        foreach (var pocket in _pockets)
        {
            // The capture circle sits in the mouth, a ball's radius past the jaws; the hole a player
            // sees opens beyond it into the rail. A click anywhere on the line from the one out over
            // the other (HoleReach radii) calls the pocket.
            var c = pocket.Centre.ToVector3() with { Z = 0 };
            var outward = Outward(c);
            var far = c + (outward * (float)(HoleReach * pocket.Radius));
            if (Pixel(c) is { } centre && Pixel(far) is { } hole && Pixel(c + new Vector3((float)pocket.Radius, 0, 0)) is { } edge
                && DistanceToSegment(at, centre, hole) <= MathF.Max(Vector2.Distance(centre, edge) * 1.5f, 12))
            {
                match.Call.CallPocket(_pocketSet.Id(pocket.Pocket));
                return true;
            }
        }
        return false;
    }

    /// <summary>How far past the capture circle's centre a click still calls the pocket, in its radii: over the hole cut into the rail.</summary>
    public const double HoleReach = 3;

    // Out of the table from a pocket: a side pocket straight across, a corner one along its diagonal.
    private static Vector3 Outward(Vector3 pocket)
    {
        float x = MathF.Abs(pocket.X) > 0.1f ? MathF.Sign(pocket.X) : 0;
        return Vector3.Normalize(new Vector3(x, MathF.Sign(pocket.Y), 0));
    }

    private static float DistanceToSegment(Vector2 p, Vector2 a, Vector2 b)
    {
        var ab = b - a;
        float t = ab.LengthSquared() > 1e-6f ? Math.Clamp(Vector2.Dot(p - a, ab) / ab.LengthSquared(), 0, 1) : 0;
        return Vector2.Distance(p, a + (t * ab));
    }

    private Vector2? Pixel(Vector3 world) => RenderMath.ToPixel(_viewProjection, world, _size.Width, _size.Height);

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        // The size clicks are seen in (and, without a camera node, the view).
        _viewProjection = RenderMath.ViewProjection(frame.Frame);
        _size = (frame.Frame.Width, frame.Frame.Height);
    }
}
