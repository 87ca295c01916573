using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Setup;

public static partial class Initializer
{
    /// <summary>
    /// Three-cushion's break (rules.md): the red on the foot spot, the opponent's cue ball on the
    /// head spot and <paramref name="breaker"/>, the breaker's, on the head string
    /// <see cref="CaromTable.BreakOffset"/> beside it. All three balls, the breaker's first; no jitter.
    /// </summary>
    /// <exception cref="ArgumentException">When <paramref name="breaker"/> is not one of carom's cue balls.</exception>
    public static IReadOnlyList<(BallId Id, Vec3 Position)> CaromBreak(TableSpec table, double radius, BallId breaker)
    {
        ArgumentNullException.ThrowIfNull(table);
        if (breaker != BallSet.White && breaker != BallSet.Yellow)
        {
            throw new ArgumentException($"the breaker's ball must be \"white\" or \"yellow\", not \"{breaker}\"", nameof(breaker));
        }
        var opponent = breaker == BallSet.White ? BallSet.Yellow : BallSet.White;
        return
        [
            (breaker, CaromTable.BreakerSpot(table, radius)),
            (opponent, CaromTable.HeadSpot(table, radius)),
            (BallSet.Red, CaromTable.FootSpot(table, radius)),
        ];
    }
}
