namespace Billiards.Core.Physics.Standard.Events;

/// <summary>
/// The event engine's queue: each ball's earliest prediction as a key (time, rank, a, b), and an
/// indexed binary min-heap of the balls on their keys, so the next event is the top in O(1) and a
/// changed key costs O(log n). Keys are totally ordered (time, then rank, then ball indices), which
/// is the deterministic tie order of simultaneous events that every integrator shares.
/// </summary>
internal sealed class EventQueue
{
    /// <summary>Rank of a motion state's end (first among simultaneous predictions).</summary>
    public const byte RankTransition = 0;

    /// <summary>Rank of a cushion face, jaw nose or pocket contact.</summary>
    public const byte RankRail = 1;

    /// <summary>Rank of a ball-ball contact.</summary>
    public const byte RankPair = 2;

    /// <summary>Rank of a pair look-ahead refresh (not an event: it changes no state).</summary>
    public const byte RankRefresh = 3;

    private readonly int _n;
    private readonly double[] _time;
    private readonly byte[] _rank;
    private readonly int[] _a;
    private readonly int[] _b;
    private readonly int[] _heap;
    private readonly int[] _heapPos;

    /// <summary>A queue for <paramref name="n"/> balls; call <see cref="Build"/> once every key is set.</summary>
    public EventQueue(int n)
    {
        _n = n;
        _time = new double[n];
        _rank = new byte[n];
        _a = new int[n];
        _b = new int[n];
        _heap = new int[n];
        _heapPos = new int[n];
    }

    /// <summary>The ball whose key is the earliest.</summary>
    public int Top => _heap[0];

    /// <summary>Time of ball i's key (s, absolute).</summary>
    public double TimeOf(int i) => _time[i];

    /// <summary>Rank of ball i's key.</summary>
    public byte RankOf(int i) => _rank[i];

    /// <summary>First ball index of ball i's key.</summary>
    public int AOf(int i) => _a[i];

    /// <summary>Second ball index of ball i's key (pairs only).</summary>
    public int BOf(int i) => _b[i];

    /// <summary>Sets ball i's key without moving it in the heap.</summary>
    public void Set(int i, double t, byte rank, int a, int b)
    {
        _time[i] = t;
        _rank[i] = rank;
        _a[i] = a;
        _b[i] = b;
    }

    /// <summary>True when the key (t, rank, a, b) comes before ball j's key.</summary>
    public bool Precedes(double t, byte rank, int a, int b, int j) => Less(t, rank, a, b, _time[j], _rank[j], _a[j], _b[j]);

    /// <summary>Restores the heap order after ball i's key changed either way.</summary>
    public void Update(int i)
    {
        int pos = _heapPos[i];
        SiftUp(pos);
        SiftDown(_heapPos[i]);
    }

    /// <summary>Restores the heap order after ball i's key moved earlier.</summary>
    public void Lowered(int i) => SiftUp(_heapPos[i]);

    /// <summary>Builds the heap over every ball's key.</summary>
    public void Build()
    {
        for (int i = 0; i < _n; i++)
        {
            _heap[i] = i;
            _heapPos[i] = i;
        }
        for (int k = _n / 2 - 1; k >= 0; k--)
        {
            SiftDown(k);
        }
    }

    /// <summary>Copies another queue's keys and heap (same ball count).</summary>
    public void CopyFrom(EventQueue other)
    {
        other._time.CopyTo(_time, 0);
        other._rank.CopyTo(_rank, 0);
        other._a.CopyTo(_a, 0);
        other._b.CopyTo(_b, 0);
        other._heap.CopyTo(_heap, 0);
        other._heapPos.CopyTo(_heapPos, 0);
    }

    /// <summary>The total order of keys.</summary>
    public static bool Less(double t1, byte r1, int a1, int b1, double t2, byte r2, int a2, int b2) =>
        t1 != t2 ? t1 < t2 : r1 != r2 ? r1 < r2 : a1 != a2 ? a1 < a2 : b1 < b2;

    private bool Before(int x, int y) =>
        Less(_time[x], _rank[x], _a[x], _b[x], _time[y], _rank[y], _a[y], _b[y]);

    private void SiftUp(int pos)
    {
        int ball = _heap[pos];
        while (pos > 0)
        {
            int parent = (pos - 1) >> 1;
            int other = _heap[parent];
            if (!Before(ball, other))
            {
                break;
            }
            _heap[pos] = other;
            _heapPos[other] = pos;
            pos = parent;
        }
        _heap[pos] = ball;
        _heapPos[ball] = pos;
    }

    private void SiftDown(int pos)
    {
        int ball = _heap[pos];
        while (true)
        {
            int child = 2 * pos + 1;
            if (child >= _n)
            {
                break;
            }
            if (child + 1 < _n && Before(_heap[child + 1], _heap[child]))
            {
                child++;
            }
            int other = _heap[child];
            if (!Before(other, ball))
            {
                break;
            }
            _heap[pos] = other;
            _heapPos[other] = pos;
            pos = child;
        }
        _heap[pos] = ball;
        _heapPos[ball] = pos;
    }
}
