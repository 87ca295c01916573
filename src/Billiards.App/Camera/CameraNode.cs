using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Input;
using Billiards.App.Input.Modes;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.App.Camera;

/// <summary>
/// The game's camera: an <see cref="OrbitCamera"/> around the cue ball, which it follows while the
/// player aims. When the balls come to rest it moves by the cue ball's displacement over the shot
/// (seed 4.3), so the view is kept and the camera is back behind the cue ball. While they roll it
/// follows them from behind the shot's line (<see cref="ChaseView"/>, <see cref="Following"/>);
/// <see cref="OverheadKey"/> switches to a view straight down on the whole table
/// (<see cref="Overhead"/>) and back at any time. It never goes below the rail's height, nor
/// through the cue.
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

    /// <summary>The key that switches between the overhead view and the orbit around the cue ball.</summary>
    public const Key OverheadKey = Key.T;

    /// <summary>Least height of the eye above the rail's top (m).</summary>
    public const double RailMargin = 0.03;

    /// <summary>Least height of the eye above the cue's line where the eye is over it (m): well clear of the cue and the near plane.</summary>
    public const double CueMargin = 0.10;

    /// <summary>Largest polar angle of the orbit (rad): the eye looks down on the cue ball by at least 10 degrees.</summary>
    public const double LowestView = (Math.PI / 2) - (10 * Math.PI / 180);

    /// <summary>Part of the screen's height the HUD's panel takes at the top; the overhead view frames the table below it.</summary>
    public const double HudBand = 0.27;

    private PhysicsNode? _physics;
    private CueNode? _cue;
    private readonly ChaseView _chase = new();

    /// <summary>True while the camera looks down on the whole table.</summary>
    public bool Overhead { get; private set; }

    /// <summary>True from a stroke until the balls rest: the view follows them unless <see cref="Overhead"/>.</summary>
    public bool Following { get; private set; }

    /// <summary>The view that follows the rolling balls.</summary>
    public ChaseView Chase => _chase;

    /// <summary>The camera; valid from <see cref="Node.Ready"/> on (placed at the table centre until then).</summary>
    public OrbitCamera Camera { get; private set; } = new(Vec3.Zero, OverviewTheta, StartPhi, OverviewDistance);

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        Camera = _physics.HasCueBall
            ? new OrbitCamera(_physics.CueBallPosition, StartTheta, StartPhi, StartDistance)
            : new OrbitCamera(new Vec3(0, 0, _physics.BallRadius), OverviewTheta, StartPhi, OverviewDistance);
        _cue = FindInTree<CueNode>();
        _physics.CameToRest += OnCameToRest;
        _physics.Struck += _ => StartFollowing();
        if (_physics.IsRolling)
        {
            StartFollowing(); // a scene's opening shot was struck before this node was ready
        }
    }

    private void StartFollowing()
    {
        Following = true;
        Overhead = false;
        _chase.Start(Camera.Eye.ToVector3(), Camera.Centre.ToVector3());
    }

    private void OnCameToRest(Vec3 cueDisplacement)
    {
        Overhead = false;
        Following = false;
        // Seed 4.3: the camera moves by the cue ball's displacement; a pocketed cue ball leaves it put.
        if (_physics is { HasCueBall: true })
        {
            Camera.Translate(cueDisplacement);
        }
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is KeyInput { Pressed: true, Key: OverheadKey })
        {
            Overhead = !Overhead;
            return true;
        }
        return false;
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (_physics is null)
        {
            return;
        }
        // While aiming the camera follows the cue ball (placed by hand, or back after a scratch).
        if (!_physics.IsRolling && _physics.HasCueBall)
        {
            Camera.Centre = _physics.CueBallPosition;
        }
        if (Following && _physics.IsRolling)
        {
            var table = _physics.Table;
            double lowest = CueClearance.RailTop(table) + RailMargin;
            _chase.Follow(_physics.Simulation.Balls, dt, table.HalfLength, table.HalfWidth, Room.WallClearance - 0.4, lowest);
        }
        Camera.LimitTheta(HighestTheta());
    }

    /// <summary>
    /// The largest polar angle (rad) at which the eye looks down by <see cref="LowestView"/> at least, is
    /// above the rail's top by <see cref="RailMargin"/> and, while the cue is shown, above the cue's
    /// line by <see cref="CueMargin"/> where the eye is over it.
    /// </summary>
    public double HighestTheta()
    {
        if (_physics is null)
        {
            return LowestView;
        }
        double railHeight = CueClearance.RailTop(_physics.Table) + RailMargin;
        double elevation = _cue is { IsVisible: true } cue ? cue.EffectiveElevationDegrees * Math.PI / 180 : double.NaN;
        double r = _physics.BallRadius;
        var centre = Camera.Centre;
        double distance = Camera.Distance;
        bool Clear(double theta)
        {
            double height = centre.Z + (distance * Math.Cos(theta));
            if (height < railHeight)
            {
                return false;
            }
            double behind = distance * Math.Sin(theta);
            return double.IsNaN(elevation) || behind > Primitives.CueLength + SeedControls.MaxPullBack
                || height >= r + (behind * Math.Tan(elevation)) + CueMargin;
        }
        if (Clear(LowestView))
        {
            return LowestView;
        }
        if (!Clear(OrbitCamera.ThetaMin))
        {
            return OrbitCamera.ThetaMin;
        }
        double lo = OrbitCamera.ThetaMin, hi = LowestView;
        for (int i = 0; i < 40; i++)
        {
            double mid = 0.5 * (lo + hi);
            (lo, hi) = Clear(mid) ? (mid, hi) : (lo, mid);
        }
        return lo;
    }

    /// <summary>
    /// True (the default) to frame the view below the scoreboard; false frames the whole window, as
    /// the input scripts recorded before the scoreboard's band was framed out expect their pixels.
    /// </summary>
    public bool FramesBelowHud { get; set; } = true;

    private (int Width, int Height) _drawn;

    /// <summary>
    /// The view-projection the next frame will show, on the framebuffer last drawn (as
    /// <see cref="RenderMath.ViewProjection(RenderFrame)"/> gives it), and that framebuffer's size;
    /// null before the first frame. A drag of the cue ball maps the pointer onto the bed through it.
    /// </summary>
    public (Matrix4x4 ViewProjection, int Width, int Height)? CurrentView()
    {
        var (width, height) = _drawn;
        if (width <= 0 || height <= 0)
        {
            return null;
        }
        var (eye, target) = View(width, height);
        var vp = RenderMath.View(eye, target) * RenderMath.Projection(FovYDegrees, (float)width / height);
        float inset = FramesBelowHud ? RenderMath.HudInset(height) : 0;
        return (inset > 0 ? vp * RenderMath.BelowHud(inset) : vp, width, height);
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        _drawn = (frame.Frame.Width, frame.Frame.Height);
        frame.Frame.FovYDegrees = FovYDegrees;
        (frame.Frame.Eye, frame.Frame.Target) = View(frame.Frame.Width, frame.Frame.Height);
        // The view is framed below the scoreboard (RenderMath.BelowHud): the called ball, its pocket and the ball the aim meets are never under it.
        frame.Frame.TopInset = FramesBelowHud ? RenderMath.HudInset(frame.Frame.Height) : 0;
    }

    /// <summary>
    /// The eye and the point looked at as the next frame of <paramref name="width"/> x
    /// <paramref name="height"/> pixels shows them, from the camera as it is now: a click is seen in
    /// the view of its moment (a key that switched the view just before it counts), not in the last
    /// frame drawn.
    /// </summary>
    public (Vector3 Eye, Vector3 Target) View(int width, int height)
    {
        if (Overhead && _physics is not null)
        {
            return OverheadView(_physics.Table, width, height, FovYDegrees);
        }
        return Following ? (_chase.Eye, _chase.Target) : (Camera.Eye.ToVector3(), Camera.Centre.ToVector3());
    }

    /// <summary>
    /// The overhead view of a table for a framebuffer: looking down (tilted a little so the table's
    /// length runs across the screen), the whole table with its rails framed below the HUD's band.
    /// </summary>
    public static (Vector3 Eye, Vector3 Target) OverheadView(TableSpec table, int width, int height, float fovYDegrees)
    {
        double hx = table.HalfLength + TableModelGenerator.CushionDepth + TableModelGenerator.RailWidth;
        double hy = table.HalfWidth + TableModelGenerator.CushionDepth + TableModelGenerator.RailWidth;
        double tan = Math.Tan(fovYDegrees * Math.PI / 360);
        double aspect = width / (double)Math.Max(height, 1);
        const double Band = 0.98 - HudBand, Across = 0.96;
        double z = Math.Max(hy / (Band * tan), hx / (Across * tan * aspect));
        // The table's centre goes to the middle of the band below the HUD, i.e. below the screen's centre.
        double shift = (((HudBand + 0.98) / 2) - 0.5) * 2 * z * tan;
        var target = new Vector3(0, (float)shift, 0);
        return (target + new Vector3(0, (float)(-0.03 * z), (float)z), target);
    }
}
