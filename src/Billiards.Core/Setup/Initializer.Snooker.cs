using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Table;

namespace Billiards.Core.Setup;

public static partial class Initializer
{
    /// <summary>
    /// Gap between the pink and the apex red (m): "as close to the pink as it can be without
    /// touching" (rules.md), with room for the rack's jitter, which is drawn again where it would
    /// touch.
    /// </summary>
    public const double PinkGap = 0.0005;

    /// <summary>
    /// Where a rack's cue ball starts: the head spot, or for snooker in the D, on the baulk line
    /// halfway between the brown and yellow spots (ours: a common break-off position).
    /// </summary>
    public static Vec3 CueStart(RackGame game, TableSpec table, double radius) => game == RackGame.Snooker
        ? new Vec3(SnookerTable.BaulkLineX(table), -SnookerTable.DRadius / 2, radius)
        : HeadSpot(table, radius);

    // Snooker: the six colours on their spots, then the fifteen reds in a triangle of rows 1-5
    // opening towards the top cushion, its apex PinkGap behind the pink, red-1 at the apex and row by
    // row from -y to +y, jittered like every rack; the cue ball in the D. All 22 balls.
    private static List<(BallId, Vec3)> SnookerRack(TableSpec table, double radius, Random random)
    {
        var set = BallSet.Snooker;
        var placed = new List<(BallId, Vec3)>(set.Count)
        {
            (set.CueBalls[0], CueStart(RackGame.Snooker, table, radius)),
        };
        foreach (string colour in BallSet.Colours)
        {
            placed.Add((BallSet.Colour(colour), SnookerTable.Spot(table, colour, radius)));
        }
        var pink = SnookerTable.Spot(table, "pink", radius);
        double spacing = 2 * radius + RackGap;
        double rowStep = spacing * Math.Sqrt(3) / 2;
        double apex = pink.X + 2 * radius + PinkGap + RackJitter;
        int red = 0;
        for (int row = 0; row < 5; row++)
        {
            for (int j = 0; j <= row; j++)
            {
                var ideal = new Vec3(apex + row * rowStep, (j - row / 2.0) * spacing, radius);
                placed.Add((new BallId(BallSet.FirstRed + red++), Jittered(ideal, placed, radius, random)));
            }
        }
        return placed;
    }
}
