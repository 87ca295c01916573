using Billiards.App.Camera;
using Billiards.App.Input.Modes;
using Billiards.App.Nodes;
using Billiards.App.Rendering;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;

namespace Billiards.App.Game;

/// <summary>
/// The cue (the seed's Queue, seed 4.1): tip offset e_x, e_y, elevation and the backswing drawn
/// while stroking. It points from the camera at the cue ball in the bed plane and is hidden while
/// balls roll. A scene without a cue ball has no cue node.
/// </summary>
public sealed class CueNode : Node
{
    private PhysicsNode? _physics;
    private MatchNode? _match;
    private CameraNode? _camera;

    /// <summary>The tip's offset on the cue ball (seed 4.4.4).</summary>
    public TipOffset Tip { get; } = new();

    /// <summary>Cue elevation above the bed (deg), in [0, <see cref="SeedControls.MaxElevationDegrees"/>].</summary>
    public double ElevationDegrees { get; private set; }

    /// <summary>The current backswing (pixels of mouse Y), set by the shot mode; 0 at rest.</summary>
    public double PullBackPixels { get; set; }

    /// <summary>True when the cue is drawn: a cue ball on the table, nothing rolling, and the game not over (the result panel is up).</summary>
    public bool IsVisible => _physics is { IsRolling: false, HasCueBall: true } && _match is not { Session.IsOver: true };

    /// <summary>
    /// The stroke direction (unit, bed plane): from the camera to the cue ball (seed 4.4.3). The
    /// camera is centred on the cue ball while the player aims, so this is the camera's azimuth
    /// alone, -(cos φ, sin φ): the eye's height (which the rail and cue limits change from frame to
    /// frame) must not change the aim even in its last bit, or a scripted game would depend on the
    /// frame rate. DeterministicMath: the same aim on every platform (docs/determinism.md).
    /// </summary>
    public Vec3 AimDirection => _camera is null
        ? new Vec3(1, 0, 0)
        : new Vec3(-DeterministicMath.Cos(_camera.Camera.Phi), -DeterministicMath.Sin(_camera.Camera.Phi), 0);

    /// <summary>The least elevation (deg) that clears the rail behind the cue ball along the aim (<see cref="CueClearance"/>).</summary>
    public double RailElevationDegrees => _physics is null
        ? 0
        : CueClearance.RailElevationDegrees(_physics.CueBallPosition, AimDirection, _physics.Table, _physics.BallRadius, Tip.HeightFraction);

    /// <summary>The least elevation (deg) at which the cue clears the rail and every ball behind the cue ball (<see cref="CueClearance"/>).</summary>
    public double ClearanceDegrees => _physics is null
        ? 0
        : CueClearance.MinElevationDegrees(_physics.Table, _physics.BallRadius, _physics.CueBallPosition, AimDirection, BallsOnTable(), Tip.SideFraction, Tip.HeightFraction);

    /// <summary>The elevation the cue is played and drawn at (deg): the chosen one, raised over a rail or a ball when it must be.</summary>
    public double EffectiveElevationDegrees => Math.Min(Math.Max(ElevationDegrees, ClearanceDegrees), SeedControls.MaxElevationDegrees);

    /// <summary>The shot as this cue can play it from where the cue ball lies (its elevation raised to the clearance along its own aim and tip).</summary>
    public ShotSpec Playable(ShotSpec shot) => _physics is null
        ? shot
        : CueClearance.Playable(shot, _physics.Table, _physics.BallRadius, _physics.CueBallPosition, BallsOnTable());

    /// <summary>Takes a planned shot's tip offset and elevation (a hint: the aim and the power are the match's).</summary>
    public void Take(ShotSpec shot)
    {
        ArgumentNullException.ThrowIfNull(shot);
        Tip.Set(shot.TipSide * SeedControls.BallRadiusCentimetres, shot.TipHeight * SeedControls.BallRadiusCentimetres);
        // A hint's or the computer's elevation is for its one shot: the player's own comes back after it.
        _ownElevation ??= ElevationDegrees;
        ElevationDegrees = Math.Clamp(shot.ElevationDeg, 0, SeedControls.MaxElevationDegrees);
    }

    // The player's elevation while a taken shot's stands in for it, or null.
    private double? _ownElevation;

    /// <summary>Raises or lowers the cue by <paramref name="degrees"/>, within [0, max]; the player's own elevation from then on.</summary>
    public void ChangeElevation(double degrees)
    {
        ElevationDegrees = Math.Clamp(ElevationDegrees + degrees, 0, SeedControls.MaxElevationDegrees);
        _ownElevation = null;
    }

    /// <summary>The shot this cue would play at a cue speed (m/s): aim from the camera, tip offset and the effective elevation.</summary>
    public ShotSpec MakeShot(double speed) =>
        new(speed, ViewMath.AimDegrees(AimDirection), Tip.SideFraction, Tip.HeightFraction, EffectiveElevationDegrees);

    // Reused: the clearance is asked for every frame.
    private readonly List<Vec3> _balls = [];

    private List<Vec3> BallsOnTable()
    {
        _balls.Clear();
        foreach (var b in _physics!.Simulation.Balls)
        {
            if (!b.IsPocketed)
            {
                _balls.Add(b.Position);
            }
        }
        return _balls;
    }

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _match = FindInTree<MatchNode>();
        _camera = GetInTree<CameraNode>();
        // Seed 4.3: when the balls rest "the cue is reset": the tip back to the centre.
        _physics.CameToRest += _ =>
        {
            Tip.Reset();
            PullBackPixels = 0;
        };
        _physics.Struck += _ =>
        {
            if (_ownElevation is double own)
            {
                ElevationDegrees = own;
                _ownElevation = null;
            }
        };
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        if (_physics is null)
        {
            return;
        }
        double pullBack = SeedControls.CueRestGap + Math.Min(PullBackPixels * SeedControls.PullBackMetresPerPixel, SeedControls.MaxPullBack);
        frame.Frame.Cue = new CueVisual(
            IsVisible,
            _physics.CueBallPosition.ToVector3(),
            AimDirection.ToVector3(),
            (float)EffectiveElevationDegrees,
            (float)pullBack,
            Tip.Fractions);
    }
}
