using System.Numerics;

namespace Billiards.App.Platform;

/// <summary>Keys the game uses.</summary>
public enum Key
{
    /// <summary>Any other key.</summary>
    Unknown,
    /// <summary>Letters.</summary>
    A, B, C, D, E, F, G, H, I, J, K, L, M, N, O, P, Q, R, S, T, U, V, W, X, Y, Z,
    /// <summary>Digits.</summary>
    D0, D1, D2, D3, D4, D5, D6, D7, D8, D9,
    /// <summary>Other keys.</summary>
    Space, Escape, Enter, Tab, Up, Down, Left, Right, PageUp, PageDown, Plus, Minus, F1, F2, F3, F11,
    /// <summary>Practice's keys: save, sensitivity, its level, load; add, remove a ball; retry.</summary>
    F5, F6, F7, F9, Insert, Delete, Backspace,
    /// <summary>Either Shift key: fine aim.</summary>
    Shift,
    /// <summary>Three-cushion's diamond aid.</summary>
    F4,
    /// <summary>The full stop and the semicolon (a colon with Shift): typed into an address.</summary>
    Period, Semicolon,
}

/// <summary>Mouse buttons.</summary>
public enum MouseButton
{
    /// <summary>Left button.</summary>
    Left,
    /// <summary>Right button.</summary>
    Right,
    /// <summary>Middle button.</summary>
    Middle,
}

/// <summary>
/// A window as the game sees it: input events, a frame callback and a few switches. The GLFW
/// window implements it; tests drive the game with a fake one.
/// </summary>
public interface IGameWindow
{
    /// <summary>A key went down.</summary>
    event Action<Key>? KeyDown;

    /// <summary>A key went up.</summary>
    event Action<Key>? KeyUp;

    /// <summary>The cursor moved to a position (pixels, y down).</summary>
    event Action<Vector2>? MouseMove;

    /// <summary>A mouse button went down.</summary>
    event Action<MouseButton>? MouseDown;

    /// <summary>A mouse button went up.</summary>
    event Action<MouseButton>? MouseUp;

    /// <summary>The wheel turned (positive away from the user).</summary>
    event Action<float>? Scroll;

    /// <summary>The framebuffer was resized (pixels).</summary>
    event Action<int, int>? Resize;

    /// <summary>Framebuffer size (pixels).</summary>
    (int Width, int Height) FramebufferSize { get; }

    /// <summary>Hides the cursor (for stroking) or shows it again.</summary>
    void SetMouseCaptured(bool captured);

    /// <summary>Switches between windowed and fullscreen.</summary>
    void ToggleFullscreen();

    /// <summary>Asks the window to close.</summary>
    void Close();
}
