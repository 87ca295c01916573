using Billiards.App.Camera;
using Billiards.App.Game;
using Billiards.App.Nodes;
using Billiards.App.Platform;

namespace Billiards.App.Input.Modes;

/// <summary>
/// The seed's control modes (seed 4.4) as a state machine. Keys switch modes (v, s, e, m); the
/// mouse does the rest: in view mode left-drag orbits (Listing 5) and right-drag zooms
/// (Listing 6); in shot mode left-drag strokes (Formel 31); in effet mode left-drag moves the tip
/// (Formel 32-33); in move mode left-drag moves the cue ball (Formel 34-35). While balls roll only
/// viewing works; a strike switches back to view mode, as the seed does.
/// </summary>
/// <remarks>
/// Additions to the seed: the cue's elevation (Up/Down or PageUp/PageDown, or the wheel in shot and
/// spin mode) feeds the strike; the wheel zooms in view mode; Shift orbits (aims) a tenth as fast;
/// the cursor is hidden while stroking. The stroke reads the pointer's position, not its motion, so
/// that absolute pointers (tablets, remote desktops, virtual machines) stroke as a mouse does.
/// </remarks>
public sealed class InputModeNode : Node
{
    private readonly StrokeTracker _stroke = new();
    private PhysicsNode? _physics;
    private CameraNode? _camera;
    private CueNode? _cue;
    private bool _leftDown;
    private bool _rightDown;
    private bool _captured;
    private bool _heldAfterStrike;

    /// <summary>The current mode.</summary>
    public InputMode Mode { get; private set; } = InputMode.View;

    /// <summary>True while balls roll: every action but viewing is locked.</summary>
    public bool IsLocked => _physics is { IsRolling: true };

    /// <summary>True while a stroke is under way (shot mode, button held).</summary>
    public bool IsStroking => _stroke.IsActive;

    /// <summary>The backswing so far (pixels) while stroking.</summary>
    public double PullBackPixels => _stroke.PullBackPixels;

    /// <summary>The speed the cue is pushed at now (m/s, Formel 31), 0 when not pushing: the power meter's reading.</summary>
    public double LiveSpeed => SeedControls.ToMetresPerSecond(_stroke.LiveSpeed(_now));

    private double _now;

    /// <summary>Signal: the mode changed.</summary>
    public event Action<InputMode>? ModeChanged;

    /// <summary>Signal: the mouse should be captured (true) or released (false).</summary>
    public event Action<bool>? MouseCaptureChanged;

    /// <summary>
    /// Switches mode; returns false (and stays) when the mode is not available: shot, effet and
    /// move need a cue and are locked while balls roll.
    /// </summary>
    public bool TrySetMode(InputMode mode)
    {
        if (mode != InputMode.View && (_cue is null || IsLocked))
        {
            return false;
        }
        if (mode != Mode)
        {
            EndStroke();
            Mode = mode;
            ModeChanged?.Invoke(mode);
        }
        return true;
    }

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _camera = GetInTree<CameraNode>();
        _cue = FindInTree<CueNode>();
        // Seed 4.4: "at the latest after the strike it switches back to view mode".
        _physics.Struck += _ => TrySetMode(InputMode.View);
        // A scratch puts the cue ball in hand: move mode, ready to drag it.
        _physics.CueBallReturned += _ => TrySetMode(InputMode.Move);
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        _now += dt;
        // A push polled in one frame took at most one frame (see StrokeTracker.MinimumInterval).
        _stroke.MinimumInterval = dt;
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        // Input times are the clock's; between events the frames' time carries it on.
        _now = Math.Max(_now, e.Time);
        return Handle(e);
    }

    private bool Handle(InputEvent e) => e switch
    {
        KeyInput { Pressed: true } key => OnKey(key),
        MouseButtonInput button => OnButton(button),
        MouseMoveInput move => OnMove(move),
        ScrollInput scroll => OnScroll(scroll.Amount),
        _ => false,
    };

    private bool OnKey(KeyInput input)
    {
        var key = input.Key;
        if (Mode == InputMode.Move && !IsLocked && key is Key.Up or Key.Down or Key.Left or Key.Right)
        {
            NudgeCueBall(key, input.Shift ? SeedControls.FineKeyMoveMetres : SeedControls.KeyMoveMetres);
            return true;
        }
        switch (key)
        {
            case Key.V:
                TrySetMode(InputMode.View);
                return true;
            case Key.S:
                TrySetMode(InputMode.Shot);
                return true;
            case Key.E:
                TrySetMode(InputMode.Spin);
                return true;
            case Key.M:
                TrySetMode(InputMode.Move);
                return true;
            case Key.Up or Key.PageUp:
                ChangeElevation(+SeedControls.ElevationStepDegrees);
                return true;
            case Key.Down or Key.PageDown:
                ChangeElevation(-SeedControls.ElevationStepDegrees);
                return true;
            default:
                return false;
        }
    }

    private bool OnButton(MouseButtonInput e)
    {
        switch (e.Button)
        {
            case MouseButton.Left:
                _leftDown = e.Pressed;
                _heldAfterStrike &= e.Pressed;
                if (e.Pressed && Mode == InputMode.Shot && !IsLocked && _cue is not null)
                {
                    // Seed 4.4.3: the mouse Y where the cue starts is the line where the tip touches the ball.
                    _stroke.Begin(e.Position.Y, e.Time);
                    SetCaptured(true);
                }
                else if (!e.Pressed)
                {
                    EndStroke();
                }
                return true;
            case MouseButton.Right:
                _rightDown = e.Pressed;
                return true;
            default:
                return false;
        }
    }

    private bool OnMove(MouseMoveInput e)
    {
        double dx = e.Delta.X, dy = e.Delta.Y;
        if (_rightDown && Mode == InputMode.View)
        {
            _camera!.Camera.Zoom(dy);
            return true;
        }
        if (!_leftDown)
        {
            return false;
        }
        if (_heldAfterStrike)
        {
            // The follow-through of a stroke, button still down: it must not orbit the camera.
            return true;
        }
        switch (Mode)
        {
            case InputMode.View when e.Shift:
                _camera!.Camera.Orbit(dx * SeedControls.FineOrbitFactor, dy * SeedControls.FineOrbitFactor);
                break;
            case InputMode.View:
                _camera!.Camera.Orbit(dx, dy);
                break;
            case InputMode.Shot:
                Stroke(e);
                break;
            case InputMode.Spin when !IsLocked:
                _cue!.Tip.Move(dx, dy);
                break;
            case InputMode.Move when !IsLocked && e.Shift:
                MoveCueBall(dx * SeedControls.FineMoveFactor, dy * SeedControls.FineMoveFactor);
                break;
            case InputMode.Move when !IsLocked:
                MoveCueBall(dx, dy);
                break;
        }
        return true;
    }

    private bool OnScroll(float notches)
    {
        if (Mode is InputMode.Shot or InputMode.Spin)
        {
            ChangeElevation(notches * SeedControls.ElevationStepDegrees);
        }
        else if (Mode == InputMode.View)
        {
            // Away from the user zooms in, as a downward drag does in Listing 6.
            _camera!.Camera.Zoom(notches * SeedControls.ZoomPixelsPerNotch);
        }
        return true;
    }

    private void Stroke(MouseMoveInput e)
    {
        if (!_stroke.IsActive || _cue is null || _physics is null)
        {
            return;
        }
        double? seedSpeed = _stroke.Move(e.Position.Y, e.Time);
        _cue.PullBackPixels = _stroke.PullBackPixels;
        if (seedSpeed is not { } speed)
        {
            return;
        }
        EndStroke();
        _heldAfterStrike = _leftDown;
        if (speed > 0 && !IsLocked && _physics.HasCueBall)
        {
            _physics.Strike(_cue.MakeShot(SeedControls.ToMetresPerSecond(speed)));
        }
    }

    private void MoveCueBall(double dx, double dy)
    {
        if (_physics is null || _camera is null)
        {
            return;
        }
        var old = _physics.CueBallPosition;
        // In the view drawn the ball follows the pointer on the bed (behind the ball or from above);
        // before any frame, Formel 34 along the cue's aim (or the camera's azimuth): exact whatever
        // the eye's height.
        Billiards.Core.Mathematics.Vec3? moved = _camera.CurrentView() is { } view
            ? CueBallMover.MoveOnBed(old, view.ViewProjection, view.Width, view.Height, dx, dy, _physics.Table, _physics.BallRadius)
            : _cue is null
            ? CueBallMover.Move(old, _camera.Camera.Eye, dx, dy, _physics.Table, _physics.BallRadius)
            : CueBallMover.MoveAlong(old, _cue.AimDirection, dx, dy, _physics.Table, _physics.BallRadius);
        PlaceCueBall(old, moved);
    }

    // An arrow key in move mode: the ball a fixed distance along the screen's up, down, left or right on the bed.
    private void NudgeCueBall(Key key, double metres)
    {
        if (_physics is null || _camera is null)
        {
            return;
        }
        var old = _physics.CueBallPosition;
        var (px, py) = key switch
        {
            Key.Up => (0.0, -1.0),
            Key.Down => (0.0, 1.0),
            Key.Left => (-1.0, 0.0),
            _ => (1.0, 0.0),
        };
        var onBed = _camera.CurrentView() is { } view
            ? CueBallMover.MoveOnBed(old, view.ViewProjection, view.Width, view.Height, px, py, _physics.Table, _physics.BallRadius)
            : CueBallMover.Move(old, _camera.Camera.Eye, px, py, _physics.Table, _physics.BallRadius);
        if (onBed is not { } towards || (towards - old).LengthXY < 1e-12)
        {
            return;
        }
        var step = towards - old;
        PlaceCueBall(old, CueBallMover.ClampToBed(old + (step * (metres / step.LengthXY)), _physics.Table, _physics.BallRadius));
    }

    // The ball where the drag or key puts it, else slid along the edge it meets: one of the move's
    // two components alone (along the head string at the break, where the ball starts on it and a
    // sideways drag a hair across it was refused whole).
    private void PlaceCueBall(Billiards.Core.Mathematics.Vec3 old, Billiards.Core.Mathematics.Vec3? moved)
    {
        if (moved is not { } p)
        {
            return;
        }
        foreach (var at in new[] { p, p with { X = old.X }, p with { Y = old.Y } })
        {
            // A component of less than a micrometre is the other's rounding, not a move.
            if ((at == p || (at - old).LengthXY > 1e-6) && _physics!.TryPlaceCueBall(at))
            {
                // Formel 35: camera = p + c with c = camera_old - ball_old, i.e. it moves with the ball.
                _camera!.Camera.Translate(at - old);
                return;
            }
        }
    }

    private void ChangeElevation(double degrees)
    {
        if (_cue is not null && !IsLocked)
        {
            _cue.ChangeElevation(degrees);
        }
    }

    private void EndStroke()
    {
        _stroke.Cancel();
        if (_cue is not null)
        {
            _cue.PullBackPixels = 0;
        }
        SetCaptured(false);
    }

    private void SetCaptured(bool captured)
    {
        if (_captured != captured)
        {
            _captured = captured;
            MouseCaptureChanged?.Invoke(captured);
        }
    }
}
