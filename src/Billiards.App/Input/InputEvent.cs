using System.Numerics;
using Billiards.App.Platform;

namespace Billiards.App.Input;

/// <summary>
/// One input event as the node tree sees it, stamped with the game clock's time (s) when the
/// window reported it: the stroke (Formel 31) measures time between mouse events.
/// </summary>
/// <param name="Time">Clock time of the event (s).</param>
public abstract record InputEvent(double Time)
{
    /// <summary>True when Shift was held: the fine version of an aim key or of a mouse orbit.</summary>
    public bool Shift { get; init; }
}

/// <summary>A key went down or up; <see cref="IsRepeat"/> marks a held key's repeat (see <see cref="KeyRepeat"/>).</summary>
public sealed record KeyInput(double Time, Key Key, bool Pressed) : InputEvent(Time)
{
    /// <summary>True for a repeat of a held key rather than the key going down.</summary>
    public bool IsRepeat { get; init; }
}

/// <summary>The cursor moved; <paramref name="Delta"/> is the movement since the previous event (pixels, y down).</summary>
public sealed record MouseMoveInput(double Time, Vector2 Position, Vector2 Delta) : InputEvent(Time);

/// <summary>A mouse button went down or up at a cursor position (pixels, y down).</summary>
public sealed record MouseButtonInput(double Time, MouseButton Button, bool Pressed, Vector2 Position) : InputEvent(Time);

/// <summary>The wheel turned by <paramref name="Amount"/> notches (positive away from the user).</summary>
public sealed record ScrollInput(double Time, float Amount) : InputEvent(Time);
