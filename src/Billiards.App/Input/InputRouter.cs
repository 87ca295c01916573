using System.Numerics;
using Billiards.App.Game;
using Billiards.App.Platform;

namespace Billiards.App.Input;

/// <summary>
/// Turns a window's raw callbacks into <see cref="InputEvent"/>s stamped with the game clock and
/// with mouse deltas (the window reports absolute positions; the seed's controls use deltas).
/// Events are forwarded as they arrive, so their times are the times the window saw them.
/// </summary>
public sealed class InputRouter : IDisposable
{
    private readonly IGameWindow _window;
    private readonly IClock _clock;
    private readonly Action<InputEvent> _sink;
    private Vector2? _lastPosition;

    /// <summary>Subscribes to <paramref name="window"/> and forwards every event to <paramref name="sink"/>.</summary>
    public InputRouter(IGameWindow window, IClock clock, Action<InputEvent> sink)
    {
        _window = window;
        _clock = clock;
        _sink = sink;
        window.KeyDown += OnKeyDown;
        window.KeyUp += OnKeyUp;
        window.MouseMove += OnMouseMove;
        window.MouseDown += OnMouseDown;
        window.MouseUp += OnMouseUp;
        window.Scroll += OnScroll;
    }

    /// <summary>The last cursor position reported (pixels), or zero before the first.</summary>
    public Vector2 CursorPosition => _lastPosition ?? Vector2.Zero;

    private void OnKeyDown(Key key) => _sink(new KeyInput(_clock.Now, key, true));

    private void OnKeyUp(Key key) => _sink(new KeyInput(_clock.Now, key, false));

    private void OnMouseMove(Vector2 position)
    {
        // The first report has nothing to compare with: a zero delta rather than a jump from (0, 0).
        var delta = _lastPosition is { } last ? position - last : Vector2.Zero;
        _lastPosition = position;
        _sink(new MouseMoveInput(_clock.Now, position, delta));
    }

    private void OnMouseDown(MouseButton button) => _sink(new MouseButtonInput(_clock.Now, button, true, CursorPosition));

    private void OnMouseUp(MouseButton button) => _sink(new MouseButtonInput(_clock.Now, button, false, CursorPosition));

    private void OnScroll(float amount) => _sink(new ScrollInput(_clock.Now, amount));

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
