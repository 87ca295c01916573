using Billiards.Core.Balls;
using Billiards.Core.Table;

namespace Billiards.Core.Physics;

/// <summary>The kinds of event a shot's log holds.</summary>
public enum EventKind : byte
{
    /// <summary>The cue strikes the cue ball: a shot starts. <see cref="SimEvent.Speed"/> is the cue's speed.</summary>
    CueStrike,
    /// <summary>Two balls collide; <see cref="SimEvent.B"/> is the second ball.</summary>
    BallBall,
    /// <summary>A ball hits a cushion or a pocket jaw; <see cref="SimEvent.Feature"/> names which.</summary>
    BallCushion,
    /// <summary>A ball drops into a pocket; <see cref="SimEvent.Feature"/> is the pocket index.</summary>
    BallPocket,
    /// <summary>
    /// A ball leaves the bed (an elevated cue's strike returned by the slate, a bounce, a collision
    /// that lifts it); <see cref="SimEvent.Speed"/> is its upward speed (m/s).
    /// </summary>
    BallAirborne,
    /// <summary>A ball lands on the bed or bounces on it; <see cref="SimEvent.Speed"/> is its vertical speed at impact (m/s).</summary>
    BallTable,
    /// <summary>A ball leaves the table over a rail; <see cref="SimEvent.Speed"/> is its speed as it lands beyond (m/s).</summary>
    BallOffTable,
    /// <summary>
    /// The cue's tip slid off the cue ball (its offset was past the miscue limit): logged at the
    /// strike, right after its <see cref="CueStrike"/>; <see cref="SimEvent.Speed"/> is the cue's speed.
    /// </summary>
    Miscue,
}

/// <summary>
/// One entry of a shot's event log, the shared language of rules, sound, HUD, replays and tests.
/// </summary>
/// <param name="Time">Simulated time of the event (s).</param>
/// <param name="Kind">What happened.</param>
/// <param name="A">The (first) ball.</param>
/// <param name="B">The second ball of a ball-ball event; equal to <paramref name="A"/> otherwise.</param>
/// <param name="Feature">Cushion or pocket index, named by <see cref="Simulation.FeatureName"/>; -1 for ball-ball and cue-strike.</param>
/// <param name="Speed">
/// Normal approach speed at impact (m/s); for a pocket drop the ball's speed as it drops; for a
/// cue strike the cue's speed.
/// </param>
public readonly record struct SimEvent(double Time, EventKind Kind, BallId A, BallId B, int Feature, double Speed);

/// <summary>
/// An append-only list of events that reuses its buffer between shots: after warm-up, logging an
/// event allocates nothing.
/// </summary>
public sealed class EventLog
{
    private SimEvent[] _items = new SimEvent[256];

    /// <summary>Number of events logged.</summary>
    public int Count { get; private set; }

    /// <summary>The events logged, in time order.</summary>
    public ReadOnlySpan<SimEvent> AsSpan() => _items.AsSpan(0, Count);

    /// <summary>The i-th event.</summary>
    public ref readonly SimEvent this[int index] => ref _items[index];

    /// <summary>Appends an event; grows the buffer only when full.</summary>
    public void Add(in SimEvent e)
    {
        if (Count == _items.Length)
        {
            Array.Resize(ref _items, _items.Length * 2);
        }
        _items[Count++] = e;
    }

    /// <summary>Makes this log hold the events of <paramref name="other"/>; grows the buffer only when too small.</summary>
    public void CopyFrom(EventLog other)
    {
        if (_items.Length < other.Count)
        {
            _items = new SimEvent[other._items.Length];
        }
        Array.Copy(other._items, _items, other.Count);
        Count = other.Count;
    }

    /// <summary>Forgets every event but keeps the buffer.</summary>
    public void Clear() => Count = 0;
}
