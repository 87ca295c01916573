using System.Numerics;
using Billiards.App.Platform;

namespace Billiards.App.Game;

/// <summary>
/// A window as the game sees it, with a script's events added to the real window's: at the start
/// of each frame (<see cref="Pump"/>) every event whose time has come is raised, as the window's
/// own callbacks raise events polled at the start of a frame. While an event is raised the clock
/// reads its scheduled time, so timings measured from input (the stroke's speed) follow the
/// script, not the frame rate. A wait stops the script's clock until <see cref="IsAtRest"/> holds,
/// so a script's shots never meet a table still rolling, whatever the frame rate.
/// </summary>
public sealed class ScriptedInput : IGameWindow, IDisposable
{
    private readonly IGameWindow _inner;
    private readonly InputScript _script;
    private readonly ScriptClock _clock;
    private int _next;
    private double? _start;
    private double _waited;
    private Vector2 _cursor;

    /// <summary>Wraps <paramref name="inner"/>; <paramref name="clock"/> is the one the game reads (it is overridden while events are raised).</summary>
    public ScriptedInput(IGameWindow inner, InputScript script, ScriptClock clock)
    {
        _inner = inner;
        _script = script;
        _clock = clock;
        inner.KeyDown += OnKeyDown;
        inner.KeyUp += OnKeyUp;
        inner.MouseMove += OnMouseMove;
        inner.MouseDown += OnMouseDown;
        inner.MouseUp += OnMouseUp;
        inner.Scroll += OnScroll;
        inner.Resize += OnResize;
    }

    /// <inheritdoc />
    public event Action<Key>? KeyDown;

    /// <inheritdoc />
    public event Action<Key>? KeyUp;

    /// <inheritdoc />
    public event Action<Vector2>? MouseMove;

    /// <inheritdoc />
    public event Action<MouseButton>? MouseDown;

    /// <inheritdoc />
    public event Action<MouseButton>? MouseUp;

    /// <inheritdoc />
    public event Action<float>? Scroll;

    /// <inheritdoc />
    public event Action<int, int>? Resize;

    /// <summary>Signal: a scripted event was raised, at this frame start time (clock seconds).</summary>
    public event Action<ScriptEvent, double>? Raised;

    /// <summary>True once the script's duration has passed: the game should close.</summary>
    public bool Finished { get; private set; }

    /// <summary>True once every event of the script has been raised (or, a wait, waited out) so far: a script that grows as it plays (a maker's) has caught up.</summary>
    public bool CaughtUp => _next >= _script.Events.Count;

    /// <summary>Clock time of the script's zero (the first frame), or null before it.</summary>
    public double? Start => _start;

    /// <summary>Whether the game is at rest (a wait ends when it is); true when not set.</summary>
    public Func<bool>? IsAtRest { get; set; }

    /// <summary>Seconds the script's clock has stood still in waits.</summary>
    public double Waited => _waited;

    /// <inheritdoc />
    public (int Width, int Height) FramebufferSize => _inner.FramebufferSize;

    /// <summary>Raises every event due at clock time <paramref name="now"/>; the first call sets the script's zero.</summary>
    public void Pump(double now)
    {
        _start ??= now;
        double scriptTime = now - _start.Value - _waited;
        while (_next < _script.Events.Count && _script.Events[_next].Time <= scriptTime)
        {
            var e = _script.Events[_next];
            if (e.Action == ScriptAction.WaitRest)
            {
                // The script's clock stands at the wait until the balls rest, and goes on from
                // there: the events after it keep their spacing from the frame that saw the rest.
                _waited = now - _start.Value - e.Time;
                scriptTime = e.Time;
                if (IsAtRest is { } atRest && !atRest())
                {
                    return;
                }
                _next++;
                continue;
            }
            _next++;
            _clock.Override = _start.Value + _waited + e.Time;
            try
            {
                Raise(e);
            }
            finally
            {
                _clock.Override = null;
            }
            Raised?.Invoke(e, now);
        }
        if (scriptTime >= _script.Duration)
        {
            Finished = true;
        }
    }

    private void Raise(ScriptEvent e)
    {
        switch (e.Action)
        {
            case ScriptAction.KeyDown:
                KeyDown?.Invoke(e.Key);
                break;
            case ScriptAction.KeyUp:
                KeyUp?.Invoke(e.Key);
                break;
            case ScriptAction.MouseMove:
                _cursor = e.Vector;
                MouseMove?.Invoke(_cursor);
                break;
            case ScriptAction.MouseMoveBy:
                _cursor += e.Vector;
                MouseMove?.Invoke(_cursor);
                break;
            case ScriptAction.MouseDown:
                MouseDown?.Invoke(e.Button);
                break;
            case ScriptAction.MouseUp:
                MouseUp?.Invoke(e.Button);
                break;
            case ScriptAction.Wheel:
                Scroll?.Invoke(e.Amount);
                break;
        }
    }

    /// <inheritdoc />
    public void SetMouseCaptured(bool captured) => _inner.SetMouseCaptured(captured);

    /// <inheritdoc />
    public void ToggleFullscreen() => _inner.ToggleFullscreen();

    /// <inheritdoc />
    public void Close() => _inner.Close();

    private void OnKeyDown(Key k) => KeyDown?.Invoke(k);

    private void OnKeyUp(Key k) => KeyUp?.Invoke(k);

    private void OnMouseMove(Vector2 p)
    {
        _cursor = p;
        MouseMove?.Invoke(p);
    }

    private void OnMouseDown(MouseButton b) => MouseDown?.Invoke(b);

    private void OnMouseUp(MouseButton b) => MouseUp?.Invoke(b);

    private void OnScroll(float a) => Scroll?.Invoke(a);

    private void OnResize(int w, int h) => Resize?.Invoke(w, h);

    /// <summary>Stops listening to the real window.</summary>
    public void Dispose()
    {
        _inner.KeyDown -= OnKeyDown;
        _inner.KeyUp -= OnKeyUp;
        _inner.MouseMove -= OnMouseMove;
        _inner.MouseDown -= OnMouseDown;
        _inner.MouseUp -= OnMouseUp;
        _inner.Scroll -= OnScroll;
        _inner.Resize -= OnResize;
    }
}

/// <summary>A clock that reads another one, except while <see cref="Override"/> is set.</summary>
public sealed class ScriptClock(IClock inner) : IClock
{
    /// <summary>The time to report instead of the inner clock's, or null.</summary>
    public double? Override { get; set; }

    /// <inheritdoc />
    public double Now => Override ?? inner.Now;
}
