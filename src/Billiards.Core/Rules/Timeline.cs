namespace Billiards.Core.Rules;

/// <summary>
/// The take-back timeline: what stood before each shot, newest last, taken back one by one. A
/// match's session keeps the game before each shot in one (<see cref="Session.TakeBack"/>);
/// practice, with no referee, keeps the table before each shot in another of the same kind.
/// </summary>
/// <typeparam name="T">What is kept of each shot's start.</typeparam>
/// <param name="capacity">The most shots kept; the oldest is dropped beyond it.</param>
public sealed class Timeline<T>(int capacity = int.MaxValue)
{
    private readonly List<T> _before = [];

    /// <summary>The shots that can be taken back.</summary>
    public int Count => _before.Count;

    /// <summary>The most shots kept.</summary>
    public int Capacity { get; } = capacity > 0 ? capacity : throw new ArgumentOutOfRangeException(nameof(capacity), capacity, "a timeline keeps at least one shot");

    /// <summary>Keeps what stood before the shot now struck.</summary>
    public void Push(T before)
    {
        _before.Add(before);
        if (_before.Count > Capacity)
        {
            _before.RemoveAt(0);
        }
    }

    /// <summary>Takes the newest shot back: what stood before it; false when there is none.</summary>
    public bool TryTakeBack(out T before)
    {
        if (_before.Count == 0)
        {
            before = default!;
            return false;
        }
        before = _before[^1];
        _before.RemoveAt(_before.Count - 1);
        return true;
    }

    /// <summary>Forgets every shot (a new game, a restart).</summary>
    public void Clear() => _before.Clear();
}
