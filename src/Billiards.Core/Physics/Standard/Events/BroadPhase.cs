using Billiards.Core.Table;

namespace Billiards.Core.Physics.Standard.Events;

/// <summary>
/// The broad phase: a uniform grid over the table in which each ball is listed under the cells that
/// its pair window box (the box around its path until its pair look-ahead ends, grown by R) touches.
/// Two balls can only meet if they share a cell, so only those pairs are solved. Up to
/// <see cref="SmallTable"/> balls the grid is one cell: every pair is a candidate anyway.
/// </summary>
internal sealed class BroadPhase
{
    /// <summary>
    /// Up to this many balls the grid is one cell and pairs look ahead to the end of the states:
    /// refreshes would only add work.
    /// </summary>
    public const int SmallTable = 32;

    // Balls per grid cell aimed at on larger tables (the cell is also the look-ahead distance).
    private const double BallsPerCell = 2;

    private readonly double _r;
    private readonly double _gridX0;
    private readonly double _gridY0;
    private readonly double _invCell;
    private readonly int _nx;
    private readonly int _ny;
    private readonly int[][] _cells;
    private readonly int[] _cellCount;
    private readonly (int X0, int Y0, int X1, int Y1)[] _cellRect;
    private readonly int[] _stamp;
    private readonly int[] _candidates;
    private int _stampValue;

    /// <summary>A grid for <paramref name="n"/> balls of radius <paramref name="r"/> (m) on the table.</summary>
    public BroadPhase(int n, TableSpec table, double r)
    {
        _r = r;
        // The grid covers the bed and a margin for the pockets; anything outside lands in the
        // border cells (clamping keeps overlapping boxes in shared cells).
        double halfX = table.HalfLength + 0.25;
        double halfY = table.HalfWidth + 0.25;
        if (n > SmallTable)
        {
            double cell = Math.Max(Math.Sqrt(4 * halfX * halfY * BallsPerCell / n), 8 * r);
            _nx = Math.Max(1, (int)Math.Ceiling(2 * halfX / cell));
            _ny = Math.Max(1, (int)Math.Ceiling(2 * halfY / cell));
            _invCell = 1 / cell;
            LookAhead = cell - 2 * r;
        }
        else
        {
            _nx = 1;
            _ny = 1;
            _invCell = 0;
            LookAhead = double.PositiveInfinity;
        }
        _gridX0 = -halfX;
        _gridY0 = -halfY;
        _cells = new int[_nx * _ny][];
        for (int c = 0; c < _cells.Length; c++)
        {
            _cells[c] = new int[n > SmallTable ? 8 : n];
        }
        _cellCount = new int[_cells.Length];
        _cellRect = new (int, int, int, int)[n];
        _stamp = new int[n];
        _candidates = new int[n];
    }

    /// <summary>
    /// How far a ball's pair window reaches along its path (m): about one cell, so that a ball
    /// stays listed in few cells; infinite on a one-cell grid.
    /// </summary>
    public double LookAhead { get; }

    /// <summary>True when the grid is one cell (small tables): every listed ball is every other's candidate.</summary>
    public bool IsSingleCell => _cells.Length == 1;

    /// <summary>Lists no ball anywhere.</summary>
    public void Clear()
    {
        Array.Clear(_cellCount);
        _cellRect.AsSpan().Fill((-1, -1, -1, -1));
    }

    /// <summary>
    /// The balls that share a cell with ball i, each once; ball i itself may be among them (valid
    /// until the next call).
    /// </summary>
    public ReadOnlySpan<int> Candidates(int i)
    {
        var rect = _cellRect[i];
        if (rect.X0 < 0)
        {
            return [];
        }
        if (IsSingleCell)
        {
            // One cell: its list is the answer, with no need to weed out repeats.
            return _cells[0].AsSpan(0, _cellCount[0]);
        }
        if (++_stampValue == int.MaxValue)
        {
            Array.Clear(_stamp);
            _stampValue = 1;
        }
        _stamp[i] = _stampValue;
        int count = 0;
        for (int y = rect.Y0; y <= rect.Y1; y++)
        {
            for (int x = rect.X0; x <= rect.X1; x++)
            {
                int cell = y * _nx + x;
                var list = _cells[cell];
                for (int k = 0; k < _cellCount[cell]; k++)
                {
                    int j = list[k];
                    if (_stamp[j] != _stampValue)
                    {
                        _stamp[j] = _stampValue;
                        _candidates[count++] = j;
                    }
                }
            }
        }
        return _candidates.AsSpan(0, count);
    }

    /// <summary>Lists ball i under the cells its window box (grown by R) touches.</summary>
    public void Register(int i, (double X0, double Y0, double X1, double Y1) box)
    {
        double r = _r;
        var rect = (CellOf(box.X0 - r - _gridX0, _nx), CellOf(box.Y0 - r - _gridY0, _ny),
            CellOf(box.X1 + r - _gridX0, _nx), CellOf(box.Y1 + r - _gridY0, _ny));
        if (rect == _cellRect[i])
        {
            return;
        }
        Unregister(i);
        _cellRect[i] = rect;
        for (int y = rect.Item2; y <= rect.Item4; y++)
        {
            for (int x = rect.Item1; x <= rect.Item3; x++)
            {
                int cell = y * _nx + x;
                int count = _cellCount[cell];
                if (count == _cells[cell].Length)
                {
                    Array.Resize(ref _cells[cell], 2 * count);
                }
                _cells[cell][count] = i;
                _cellCount[cell] = count + 1;
            }
        }
    }

    /// <summary>Takes ball i off the grid.</summary>
    public void Unregister(int i)
    {
        var rect = _cellRect[i];
        if (rect.X0 < 0)
        {
            return;
        }
        for (int y = rect.Y0; y <= rect.Y1; y++)
        {
            for (int x = rect.X0; x <= rect.X1; x++)
            {
                int cell = y * _nx + x;
                var list = _cells[cell];
                int count = _cellCount[cell];
                for (int k = 0; k < count; k++)
                {
                    if (list[k] == i)
                    {
                        list[k] = list[count - 1];
                        _cellCount[cell] = count - 1;
                        break;
                    }
                }
            }
        }
        _cellRect[i] = (-1, -1, -1, -1);
    }

    /// <summary>Copies another grid's lists (same table and ball count); cells grow only when too short.</summary>
    public void CopyFrom(BroadPhase other)
    {
        for (int c = 0; c < _cells.Length; c++)
        {
            int count = other._cellCount[c];
            if (_cells[c].Length < count)
            {
                _cells[c] = new int[other._cells[c].Length];
            }
            Array.Copy(other._cells[c], _cells[c], count);
            _cellCount[c] = count;
        }
        other._cellRect.CopyTo(_cellRect, 0);
        other._stamp.CopyTo(_stamp, 0);
        _stampValue = other._stampValue;
    }

    private int CellOf(double offset, int cells)
    {
        double f = offset * _invCell;
        return f <= 0 ? 0 : f >= cells - 1 ? cells - 1 : (int)f;
    }
}
