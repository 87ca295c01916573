using Billiards.App.Platform;

namespace Billiards.App.Input;

/// <summary>
/// Repeats held keys that step a value (aim, power, elevation, volume) and speeds the repeat up
/// the longer the key is held: after <see cref="Delay"/> a press every 1/<see cref="StartRate"/> s,
/// rising to <see cref="TopRate"/> presses a second over <see cref="RampSeconds"/>. The game makes
/// its own repeats rather than taking the system's: those come at one fixed rate that the player
/// set for typing, and a script or a test has none. The times are the game clock's, so the same
/// holds give the same presses at any frame rate.
/// </summary>
public sealed class KeyRepeat
{
    /// <summary>Seconds a key is held before its first repeat.</summary>
    public const double Delay = 0.35;

    /// <summary>Repeats a second at the first repeat.</summary>
    public const double StartRate = 10;

    /// <summary>Repeats a second once the key has been held <see cref="Delay"/> + <see cref="RampSeconds"/>.</summary>
    public const double TopRate = 40;

    /// <summary>Seconds over which the rate rises from <see cref="StartRate"/> to <see cref="TopRate"/>.</summary>
    public const double RampSeconds = 1.2;

    private readonly Dictionary<Key, (double Down, double Next)> _held = [];
    private readonly List<Key> _due = [];

    /// <summary>True for the keys that repeat: the ones that step a value.</summary>
    public static bool Repeats(Key key) =>
        key is Key.Left or Key.Right or Key.A or Key.D or Key.W or Key.Q
            or Key.Up or Key.Down or Key.PageUp or Key.PageDown or Key.Plus or Key.Minus;

    /// <summary>The rate (repeats/s) after a key has been held <paramref name="held"/> seconds.</summary>
    public static double RateAt(double held) =>
        StartRate + ((TopRate - StartRate) * Math.Clamp((held - Delay) / RampSeconds, 0, 1));

    /// <summary>A key went down at <paramref name="time"/> (s).</summary>
    public void Down(Key key, double time)
    {
        if (Repeats(key) && !_held.ContainsKey(key))
        {
            _held[key] = (time, time + Delay);
        }
    }

    /// <summary>A key went up.</summary>
    public void Up(Key key) => _held.Remove(key);

    /// <summary>Forgets every held key (the window lost the keyboard).</summary>
    public void Clear() => _held.Clear();

    /// <summary>
    /// Calls <paramref name="press"/> with each repeat due by <paramref name="now"/> (s), in time
    /// order for each key, with the time it fell due.
    /// </summary>
    public void Due(double now, Action<Key, double> press)
    {
        ArgumentNullException.ThrowIfNull(press);
        _due.Clear();
        _due.AddRange(_held.Keys);
        _due.Sort();
        foreach (var key in _due)
        {
            var (down, next) = _held[key];
            while (next <= now)
            {
                press(key, next);
                next += 1 / RateAt(next - down);
            }
            _held[key] = (down, next);
        }
    }
}
