using System.Numerics;
using Billiards.App.Platform;

namespace Billiards.App.Input;

/// <summary>
/// One input event as the node tree sees it, stamped with the game clock's time (s) when the
/// window reported it: the stroke (Formel 31) measures time between mouse events.
/// </summary>
/// <param name="Time">Clock time of the event (s).</param>
public abstract record InputEvent(double Time);

/// <summary>A key went down or up.</summary>
public sealed record KeyInput(double Time, Key Key, bool Pressed) : InputEvent(Time);

/// <summary>The cursor moved; <paramref name="Delta"/> is the movement since the previous event (pixels, y down).</summary>
public sealed record MouseMoveInput(double Time, Vector2 Position, Vector2 Delta) : InputEvent(Time);

/// <summary>A mouse button went down or up at a cursor position (pixels, y down).</summary>
public sealed record MouseButtonInput(double Time, MouseButton Button, bool Pressed, Vector2 Position) : InputEvent(Time);

/// <summary>The wheel turned by <paramref name="Amount"/> notches (positive away from the user).</summary>
public sealed record ScrollInput(double Time, float Amount) : InputEvent(Time);
