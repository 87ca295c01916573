using Billiards.Core.Rules;

namespace Billiards.Core.Tests.Rules;

/// <summary>The referee's set of ball numbers answers as a sorted set does.</summary>
public class BallNumbersTests
{
    [Fact]
    public void NumbersAddedInAnyOrderComeOutAscendingOnceEachWithTheLowestFirst()
    {
        var numbers = new BallNumbers(4);
        int[] added = [9, 3, 15, 3, 1, 21, 9, 8];
        var sorted = new SortedSet<int>();
        foreach (int n in added)
        {
            numbers.Add(n);
            sorted.Add(n);
            Assert.Equal(sorted, numbers);
            Assert.Equal(sorted.Count, numbers.Count);
            Assert.Equal(sorted.Min, numbers.Min);
        }
        Assert.All(Enumerable.Range(0, 23), n => Assert.Equal(sorted.Contains(n), numbers.Contains(n)));
        Assert.Throws<InvalidOperationException>(() => new BallNumbers(0).Min);
    }
}
