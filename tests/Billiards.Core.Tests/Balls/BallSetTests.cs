using Billiards.Core.Balls;

namespace Billiards.Core.Tests.Balls;

/// <summary>Ball sets: pool's is the cue ball and 1-15.</summary>
public class BallSetTests
{
    [Fact]
    public void PoolIsTheCueBallAndFifteenNumberedBalls()
    {
        var pool = BallSet.Pool;
        Assert.Equal(16, pool.Count);
        Assert.Equal(15, pool.HighestNumber);
        Assert.Equal(BallId.Cue, pool.Ids[0]);
        Assert.Equal(Enumerable.Range(0, 16), pool.Ids.Select(b => b.Value));
        Assert.True(pool.Contains(new BallId(15)));
        Assert.False(pool.Contains(new BallId(16)));
        Assert.Equal("\"cue\" or \"1\" .. \"15\"", pool.Describe());
    }

    [Theory]
    [InlineData("cue", 0)]
    [InlineData("1", 1)]
    [InlineData("15", 15)]
    public void IdsOfTheSetParse(string text, int value)
    {
        Assert.True(BallSet.Pool.TryParse(text, out var id));
        Assert.Equal(value, id.Value);
        Assert.Equal(text, id.ToString());
    }

    [Theory]
    [InlineData("16")]
    [InlineData("0")]
    [InlineData("01")]
    [InlineData("-1")]
    [InlineData("")]
    [InlineData(null)]
    [InlineData("9999999999")]
    public void OtherTextIsNoBallOfTheSet(string? text)
    {
        Assert.False(BallSet.Pool.TryParse(text, out _));
        Assert.False(BallId.TryParse(text, out _));
    }
}
