using System.Collections;

namespace Billiards.Core.Rules;

/// <summary>
/// A set of ball numbers kept in ascending order in one array: what a referee asks of the balls on
/// the table (is it there, how many, the lowest, in number order), without a tree node per ball as
/// a sorted set has; the computer player judges thousands of shots a decision.
/// </summary>
internal sealed class BallNumbers(int capacity) : IReadOnlyCollection<int>
{
    private readonly List<int> _numbers = new(capacity);

    /// <summary>How many numbers the set holds.</summary>
    public int Count => _numbers.Count;

    /// <summary>The lowest number.</summary>
    /// <exception cref="InvalidOperationException">When the set is empty.</exception>
    public int Min => _numbers.Count > 0 ? _numbers[0] : throw new InvalidOperationException("the set is empty");

    /// <summary>Adds <paramref name="number"/> in its place; a number already there is not added again.</summary>
    public void Add(int number)
    {
        int i = _numbers.BinarySearch(number);
        if (i < 0)
        {
            _numbers.Insert(~i, number);
        }
    }

    /// <summary>True when the set holds <paramref name="number"/>.</summary>
    public bool Contains(int number) => _numbers.BinarySearch(number) >= 0;

    /// <summary>The numbers in ascending order.</summary>
    public List<int>.Enumerator GetEnumerator() => _numbers.GetEnumerator();

    IEnumerator<int> IEnumerable<int>.GetEnumerator() => GetEnumerator();

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
