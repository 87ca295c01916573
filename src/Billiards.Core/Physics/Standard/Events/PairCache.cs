namespace Billiards.Core.Physics.Standard.Events;

/// <summary>
/// The finite ball-ball contact predictions, stored sparsely with both balls (partner and absolute
/// time): no n x n matrix, and a ball's pairs are dropped in time proportional to their number.
/// Rows grow on demand and never shrink, so after warm-up nothing is allocated.
/// </summary>
internal sealed class PairCache
{
    private readonly int[][] _partner;
    private readonly double[][] _at;
    private readonly int[] _count;

    /// <summary>An empty cache for <paramref name="n"/> balls.</summary>
    public PairCache(int n)
    {
        _partner = new int[n][];
        _at = new double[n][];
        _count = new int[n];
        for (int i = 0; i < n; i++)
        {
            _partner[i] = new int[4];
            _at[i] = new double[4];
        }
    }

    /// <summary>Number of pairs stored with ball i.</summary>
    public int Count(int i) => _count[i];

    /// <summary>The p-th partner of ball i.</summary>
    public int Partner(int i, int p) => _partner[i][p];

    /// <summary>The p-th contact time of ball i (s, absolute).</summary>
    public double At(int i, int p) => _at[i][p];

    /// <summary>Stores the pair's contact time with ball i only (call for both balls).</summary>
    public void Add(int i, int j, double t)
    {
        int count = _count[i];
        if (count == _partner[i].Length)
        {
            Array.Resize(ref _partner[i], 2 * count);
            Array.Resize(ref _at[i], 2 * count);
        }
        _partner[i][count] = j;
        _at[i][count] = t;
        _count[i] = count + 1;
    }

    /// <summary>Drops partner j from ball i's row (not i from j's).</summary>
    public void Remove(int i, int j)
    {
        var partners = _partner[i];
        int count = _count[i];
        for (int p = 0; p < count; p++)
        {
            if (partners[p] == j)
            {
                partners[p] = partners[count - 1];
                _at[i][p] = _at[i][count - 1];
                _count[i] = count - 1;
                return;
            }
        }
    }

    /// <summary>Empties ball i's row (its partners' rows are the caller's business).</summary>
    public void ClearRow(int i) => _count[i] = 0;

    /// <summary>Copies another cache's pairs (same ball count); rows grow only when too short.</summary>
    public void CopyFrom(PairCache other)
    {
        for (int i = 0; i < _count.Length; i++)
        {
            int count = other._count[i];
            if (_partner[i].Length < count)
            {
                _partner[i] = new int[other._partner[i].Length];
                _at[i] = new double[other._at[i].Length];
            }
            Array.Copy(other._partner[i], _partner[i], count);
            Array.Copy(other._at[i], _at[i], count);
            _count[i] = count;
        }
    }
}
