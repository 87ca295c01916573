using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Platform;

namespace Billiards.App.Input;

/// <summary>
/// Turns a window's raw callbacks into <see cref="InputEvent"/>s stamped with the game clock and
/// with mouse deltas (the window reports absolute positions; the seed's controls use deltas).
/// Events are forwarded as they arrive, so their times are the times the window saw them. It
/// also keeps which keys are held: Shift marks every event (fine aim), and held stepping keys
/// repeat at each <see cref="Repeat"/> (<see cref="KeyRepeat"/>).
/// </summary>
public sealed class InputRouter : IDisposable
{
    private readonly IGameWindow _window;
    private readonly IClock _clock;
    private readonly Action<InputEvent> _sink;
    private readonly KeyRepeat _repeat = new();
    private readonly Action<Key, double> _pressAgain;
    private Vector2? _lastPosition;
    private bool _shift;

    /// <summary>Subscribes to <paramref name="window"/> and forwards every event to <paramref name="sink"/>.</summary>
    public InputRouter(IGameWindow window, IClock clock, Action<InputEvent> sink)
    {
        _window = window;
        _clock = clock;
        _sink = sink;
        _pressAgain = (key, time) => _sink(new KeyInput(time, key, true) { Shift = _shift, IsRepeat = true });
        window.KeyDown += OnKeyDown;
        window.KeyUp += OnKeyUp;
        window.MouseMove += OnMouseMove;
        window.MouseDown += OnMouseDown;
        window.MouseUp += OnMouseUp;
        window.Scroll += OnScroll;
    }

    /// <summary>The last cursor position reported (pixels), or zero before the first.</summary>
    public Vector2 CursorPosition => _lastPosition ?? Vector2.Zero;

    /// <summary>True while a Shift key is held.</summary>
    public bool IsShiftHeld => _shift;

    /// <summary>
    /// Sends the repeats of held keys that fell due by now: once a frame, before the frame's work,
    /// and before every event, so that they keep their time order with it (a key held in a script
    /// repeats as often whether its release comes in the same frame or frames later).
    /// </summary>
    public void Repeat() => _repeat.Due(_clock.Now, _pressAgain);

    private void OnKeyDown(Key key)
    {
        Repeat();
        double now = _clock.Now;
        _shift |= key == Key.Shift;
        _repeat.Down(key, now);
        _sink(new KeyInput(now, key, true) { Shift = _shift });
    }

    private void OnKeyUp(Key key)
    {
        Repeat();
        _shift &= key != Key.Shift;
        _repeat.Up(key);
        _sink(new KeyInput(_clock.Now, key, false) { Shift = _shift });
    }

    private void OnMouseMove(Vector2 position)
    {
        Repeat();
        // The first report has nothing to compare with: a zero delta rather than a jump from (0, 0).
        var delta = _lastPosition is { } last ? position - last : Vector2.Zero;
        _lastPosition = position;
        _sink(new MouseMoveInput(_clock.Now, position, delta) { Shift = _shift });
    }

    private void OnMouseDown(MouseButton button)
    {
        Repeat();
        _sink(new MouseButtonInput(_clock.Now, button, true, CursorPosition) { Shift = _shift });
    }

    private void OnMouseUp(MouseButton button)
    {
        Repeat();
        _sink(new MouseButtonInput(_clock.Now, button, false, CursorPosition) { Shift = _shift });
    }

    private void OnScroll(float amount)
    {
        Repeat();
        _sink(new ScrollInput(_clock.Now, amount) { Shift = _shift });
    }

    /// <summary>Unsubscribes from the window.</summary>
    public void Dispose()
    {
        _window.KeyDown -= OnKeyDown;
        _window.KeyUp -= OnKeyUp;
        _window.MouseMove -= OnMouseMove;
        _window.MouseDown -= OnMouseDown;
        _window.MouseUp -= OnMouseUp;
        _window.Scroll -= OnScroll;
    }
}
