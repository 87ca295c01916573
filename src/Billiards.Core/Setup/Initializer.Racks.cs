using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Setup;

/// <summary>
/// The seed's Initializer (seed 4.1.3): places the racks, builds the collision geometry and
/// resets a game. Racks are model-independent and in SI: the seed's spacing of 2r + 0.2 cm and
/// its jitter of +-0.1 cm on both axes ("no break equals another") become 2R + 2 mm and +-1 mm.
/// </summary>
public static partial class Initializer
{
    /// <summary>Gap between neighbouring racked balls before jitter (m); the seed's 0.2 cm.</summary>
    public const double RackGap = 0.002;

    /// <summary>Largest jitter added to x and y of each racked ball (m); the seed's 0.1 cm.</summary>
    public const double RackJitter = 0.001;

    /// <summary>The foot spot, where the apex ball of a rack stands: a quarter of the length from the foot rail.</summary>
    public static Vec3 FootSpot(TableSpec table, double radius) => new(table.HalfLength / 2, 0, radius);

    /// <summary>The head spot, where the cue ball starts: a quarter of the length from the head rail.</summary>
    public static Vec3 HeadSpot(TableSpec table, double radius) => new(-table.HalfLength / 2, 0, radius);

    /// <summary>
    /// The balls of a rack with their centres (z = radius). 8-ball: a triangle of 15 with the 1 at
    /// the apex, the 8 in the centre, a solid and a stripe on the two back corners (which corner
    /// gets which, and the order of the rest, follow the seed). 9-ball: a diamond of 9 with the 1
    /// at the apex and the 9 in the centre. 10-ball: a triangle of 10 (rows 1-4) with the 1 at the
    /// apex and the 10 in the middle of the third row. 14.1: a triangle of 15 in the seed's random
    /// order. The apex stands on the foot spot and the rack opens towards the foot rail (+x).
    /// </summary>
    /// <remarks>
    /// The seed's jitter can make two neighbours overlap (each may move sqrt(2) * 0.1 cm towards
    /// the other across a 0.2 cm gap). We draw a ball's jitter again, from the same seeded
    /// generator, until it overlaps no ball placed before it, so a rack is always valid.
    /// </remarks>
    public static IReadOnlyList<(BallId Id, Vec3 Position)> Rack(RackSpec rack, TableSpec table, double radius)
    {
        var random = new Random(rack.Seed);
        if (rack.Game == RackGame.Snooker)
        {
            return SnookerRack(table, radius, random);
        }
        if (rack.Game == RackGame.ThreeCushion)
        {
            return CaromBreak(table, radius, rack.Breaker ?? BallSet.White);
        }
        int[] rowSizes = RowSizes(rack.Game);
        int[] numbers = rack.Game switch
        {
            RackGame.EightBall => EightBallOrder(random),
            RackGame.NineBall => NineBallOrder(random),
            RackGame.TenBall => TenBallOrder(random),
            _ => StraightPoolOrder(random),
        };
        return Place(rowSizes, numbers, table, radius, random);
    }

    /// <summary>
    /// 14.1's rerack: <paramref name="balls"/> (normally the 14 pocketed ones) in the 15-ball
    /// triangle with the apex spot left empty, in order of their numbers from the second row on,
    /// with the rack's jitter. Fewer than 14 balls fill the rows from the front; 15 fill the apex too.
    /// </summary>
    public static IReadOnlyList<(BallId Id, Vec3 Position)> Rerack(IReadOnlyList<BallId> balls, TableSpec table, double radius, int seed)
    {
        ArgumentNullException.ThrowIfNull(balls);
        if (balls.Count > Triangle)
        {
            throw new ArgumentException($"a triangle holds {Triangle} balls, not {balls.Count}", nameof(balls));
        }
        var random = new Random(seed);
        int[] numbers = [.. balls.Select(b => b.Value).Order()];
        if (numbers.Length == Triangle)
        {
            return Place([1, 2, 3, 4, 5], numbers, table, radius, random);
        }
        // Place() fills the triangle apex first; a marker that is no ball holds the empty apex and is dropped.
        var placed = Place([1, 2, 3, 4, 5], [EmptySpot, .. numbers], table, radius, random);
        return [.. placed.Where(b => b.Item1.Value != EmptySpot)];
    }

    /// <summary>
    /// The spots of a rack's shape before jitter (z = radius), in the order racks fill them: the
    /// apex on the foot spot first, then row by row towards the foot rail, each row from -y to +y,
    /// neighbours 2R + <see cref="RackGap"/> apart.
    /// </summary>
    public static IReadOnlyList<Vec3> RackSpots(RackGame game, TableSpec table, double radius) =>
        Spots(RowSizes(game), table, radius);

    private static int[] RowSizes(RackGame game) => game switch
    {
        RackGame.NineBall => [1, 2, 3, 2, 1],
        RackGame.TenBall => [1, 2, 3, 4],
        _ => [1, 2, 3, 4, 5],
    };

    private static List<Vec3> Spots(int[] rowSizes, TableSpec table, double radius)
    {
        double spacing = 2 * radius + RackGap;
        double rowStep = spacing * Math.Sqrt(3) / 2;
        var foot = FootSpot(table, radius);
        var spots = new List<Vec3>(rowSizes.Sum());
        for (int row = 0; row < rowSizes.Length; row++)
        {
            for (int j = 0; j < rowSizes[row]; j++)
            {
                spots.Add(new Vec3(foot.X + row * rowStep, (j - (rowSizes[row] - 1) / 2.0) * spacing, radius));
            }
        }
        return spots;
    }

    private static List<(BallId, Vec3)> Place(int[] rowSizes, int[] numbers, TableSpec table, double radius, Random random)
    {
        var spots = Spots(rowSizes, table, radius);
        var placed = new List<(BallId, Vec3)>(numbers.Length);
        for (int k = 0; k < numbers.Length && k < spots.Count; k++)
        {
            placed.Add((new BallId(numbers[k]), Jittered(spots[k], placed, radius, random)));
        }
        return placed;
    }

    private static Vec3 Jittered(Vec3 ideal, List<(BallId, Vec3)> placed, double radius, Random random)
    {
        for (int attempt = 0; attempt < 1000; attempt++)
        {
            var p = ideal + new Vec3((random.NextDouble() * 2 - 1) * RackJitter, (random.NextDouble() * 2 - 1) * RackJitter, 0);
            if (placed.TrueForAll(b => (b.Item2 - p).Length >= 2 * radius))
            {
                return p;
            }
        }
        return ideal; // unreachable in practice: the unjittered spot keeps a 2 mm gap
    }

    // Pool's triangle holds every object ball of its set (15).
    private static int Triangle => BallSet.Pool.HighestNumber;

    // Marks the empty apex of a rerack: no ball has it.
    private const int EmptySpot = -1;

    // Rows are filled apex first, left to right: index 0 is the apex, 4 the centre, 10 and 14 the back corners.
    private static int[] EightBallOrder(Random random)
    {
        // The 1 at the apex, the 8 in the centre: the others of each group are drawn.
        var solids = BallSet.Pool.Group("solids").Select(b => b.Value).Where(n => n != 1).ToList();
        var stripes = BallSet.Pool.Group("stripes").Select(b => b.Value).ToList();
        int solid = Take(solids, random);
        int stripe = Take(stripes, random);
        bool solidLeft = random.Next(2) == 0;
        var rest = solids.Concat(stripes).ToArray();
        random.Shuffle(rest);
        var order = new int[Triangle];
        order[0] = 1;
        order[4] = 8;
        order[10] = solidLeft ? solid : stripe;
        order[14] = solidLeft ? stripe : solid;
        int r = 0;
        for (int i = 0; i < Triangle; i++)
        {
            if (order[i] == 0)
            {
                order[i] = rest[r++];
            }
        }
        return order;
    }

    // Diamond rows 1, 2, 3, 2, 1: index 0 is the apex and 4 the centre.
    private static int[] NineBallOrder(Random random)
    {
        int[] rest = [2, 3, 4, 5, 6, 7, 8];
        random.Shuffle(rest);
        return [1, rest[0], rest[1], rest[2], 9, rest[3], rest[4], rest[5], rest[6]];
    }

    // Rows 1, 2, 3, 4: index 0 is the apex and 4 the centre of the third row.
    private static int[] TenBallOrder(Random random)
    {
        int[] rest = [2, 3, 4, 5, 6, 7, 8, 9];
        random.Shuffle(rest);
        return [1, rest[0], rest[1], rest[2], 10, rest[3], rest[4], rest[5], rest[6], rest[7]];
    }

    private static int[] StraightPoolOrder(Random random)
    {
        int[] all = [.. Enumerable.Range(1, Triangle)];
        random.Shuffle(all);
        return all;
    }

    private static int Take(List<int> from, Random random)
    {
        int i = random.Next(from.Count);
        int value = from[i];
        from.RemoveAt(i);
        return value;
    }
}
