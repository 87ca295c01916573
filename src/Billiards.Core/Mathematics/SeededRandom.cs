namespace Billiards.Core.Mathematics;

/// <summary>
/// A seeded <see cref="Random"/> whose whole state can be copied without allocating: it draws
/// exactly the sequence of <c>new Random(seed)</c> (Knuth's subtractive generator as .NET keeps it
/// for seeded instances), so swapping it in changes no result, and a simulation snapshot can save
/// and restore it.
/// </summary>
public sealed class SeededRandom : Random
{
    private const int Seed = 161803398;
    private const int Size = 56;

    private readonly int[] _state = new int[Size];
    private int _next;
    private int _nextP;

    /// <summary>A generator that repeats <c>new Random(<paramref name="seed"/>)</c>.</summary>
    public SeededRandom(int seed)
        : base(seed)
    {
        int subtraction = seed == int.MinValue ? int.MaxValue : Math.Abs(seed);
        int mj = Seed - subtraction;
        _state[55] = mj;
        int mk = 1;
        int ii = 0;
        for (int i = 1; i < 55; i++)
        {
            if ((ii += 21) >= 55)
            {
                ii -= 55;
            }
            _state[ii] = mk;
            mk = mj - mk;
            if (mk < 0)
            {
                mk += int.MaxValue;
            }
            mj = _state[ii];
        }
        for (int k = 1; k < 5; k++)
        {
            for (int i = 1; i < Size; i++)
            {
                int n = i + 30;
                if (n >= 55)
                {
                    n -= 55;
                }
                _state[i] -= _state[1 + n];
                if (_state[i] < 0)
                {
                    _state[i] += int.MaxValue;
                }
            }
        }
        _next = 0;
        _nextP = 21;
    }

    /// <summary>Copies another generator's state: this one then draws what that one would.</summary>
    public void CopyFrom(SeededRandom other)
    {
        other._state.CopyTo(_state, 0);
        _next = other._next;
        _nextP = other._nextP;
    }

    /// <inheritdoc />
    public override int Next() => InternalSample();

    /// <inheritdoc />
    public override int Next(int maxValue)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(maxValue);
        return (int)(Sample() * maxValue);
    }

    /// <inheritdoc />
    public override int Next(int minValue, int maxValue)
    {
        ArgumentOutOfRangeException.ThrowIfGreaterThan(minValue, maxValue);
        long range = (long)maxValue - minValue;
        return range <= int.MaxValue
            ? (int)(Sample() * range) + minValue
            : (int)((long)(LargeRangeSample() * range) + minValue);
    }

    /// <inheritdoc />
    public override double NextDouble() => Sample();

    /// <inheritdoc />
    public override float NextSingle() => (float)Sample();

    /// <inheritdoc />
    protected override double Sample() => InternalSample() * (1.0 / int.MaxValue);

    private double LargeRangeSample()
    {
        int result = InternalSample();
        if (InternalSample() % 2 == 0)
        {
            result = -result;
        }
        double d = result;
        d += int.MaxValue - 1;
        d /= 2.0 * int.MaxValue - 1;
        return d;
    }

    private int InternalSample()
    {
        int next = _next;
        if (++next >= Size)
        {
            next = 1;
        }
        int nextP = _nextP;
        if (++nextP >= Size)
        {
            nextP = 1;
        }
        int value = _state[next] - _state[nextP];
        if (value == int.MaxValue)
        {
            value--;
        }
        if (value < 0)
        {
            value += int.MaxValue;
        }
        _state[next] = value;
        _next = next;
        _nextP = nextP;
        return value;
    }
}
