using System.Diagnostics;

namespace Billiards.App.Game;

/// <summary>A source of time for the game loop and input events (s, monotonic).</summary>
public interface IClock
{
    /// <summary>Seconds since an arbitrary start.</summary>
    double Now { get; }
}

/// <summary>The real clock: a <see cref="Stopwatch"/>.</summary>
public sealed class StopwatchClock : IClock
{
    private readonly Stopwatch _stopwatch = Stopwatch.StartNew();

    /// <inheritdoc />
    public double Now => _stopwatch.Elapsed.TotalSeconds;
}

/// <summary>A clock that only moves when told to (osu!framework's ManualClock): tests drive time exactly.</summary>
public sealed class ManualClock : IClock
{
    /// <inheritdoc />
    public double Now { get; set; }

    /// <summary>Moves the clock forward by <paramref name="seconds"/>.</summary>
    public void Advance(double seconds) => Now += seconds;
}
