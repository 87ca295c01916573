using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Rules;

/// <summary>
/// A plain shot-maker for whole-game tests: ghost-ball aiming at a target into the pocket with the
/// smallest cut and clear lines, straight-in from a placed cue ball when it has ball in hand. It
/// only produces shot lists; the tests judge nothing by it.
/// </summary>
internal static class Aimer
{
    private const double R = ShotBuilder.R;

    // Cue speeds that send the ball off as fast as an elastic tip did at the speeds below
    // (pool's leather tip returns (1 + 0.73) / 2 of it).
    private const double Tip = 2 / 1.73;

    public static GameShot Next(Match game, Func<BallId, bool> isTarget, bool callShots)
    {
        var balls = game.Balls.ToDictionary();
        var table = game.Setup.Table;
        if (game.State.Shot == 0 && game.State.Rules != GameRules.StraightPool)
        {
            return Break(game, callShots ? null : null);
        }
        var pockets = Billiards.Core.Table.TableGeometry.Build(table, R).Pockets.ToArray();
        var hand = game.BallInHand;
        var targets = balls.Where(b => !PoolBalls.IsCue(b.Key) && isTarget(b.Key)).OrderBy(b => b.Key.Value).ToList();
        (double Score, BallId Target, int Pocket, Vec3 Cue, Vec3? Place)? best = null;
        foreach (var (target, t) in targets)
        {
            foreach (var pocket in pockets)
            {
                var toPocket = pocket.Centre with { Z = R } - t;
                var u = toPocket.Normalized();
                var ghost = t - u * (2 * R);
                if (!Clear(balls, t, pocket.Centre with { Z = R }, target, PoolBalls.Cue))
                {
                    continue;
                }
                var candidates = new List<(Vec3 Cue, Vec3? Place)>();
                if (hand != BallInHand.None)
                {
                    foreach (double d in new[] { 0.25, 0.4, 0.6 })
                    {
                        var p = ghost - u * d;
                        if (Placeable(p, balls, table, hand))
                        {
                            candidates.Add((p, p));
                        }
                    }
                }
                if (balls.TryGetValue(PoolBalls.Cue, out var cue))
                {
                    candidates.Add((cue, null));
                }
                foreach (var (c, place) in candidates)
                {
                    var v = ghost - c;
                    double cos = Dot(v.Normalized(), u);
                    if (cos < Math.Cos(65 * Math.PI / 180) || !Clear(balls, c, ghost, target, PoolBalls.Cue))
                    {
                        continue;
                    }
                    double score = (1 - cos) * 4 + v.Length + toPocket.Length * 0.5;
                    if (best is null || score < best.Value.Score)
                    {
                        best = (score, target, pocket.Pocket, c, place);
                    }
                }
            }
        }
        if (best is { } b)
        {
            var t = balls[b.Target];
            var pocketCentre = pockets.First(p => p.Pocket == b.Pocket).Centre with { Z = R };
            var ghost = t - (pocketCentre - t).Normalized() * (2 * R);
            var v = ghost - b.Cue;
            double distance = v.Length + (pocketCentre - t).Length;
            double speed = Tip * Math.Min(4.5, 1.4 + 1.3 * distance);
            var shot = new ShotSpec(speed, Math.Atan2(v.Y, v.X) * 180 / Math.PI, 0, -0.3);
            return new GameShot(shot, callShots ? new Call(b.Target, PoolPockets.Set.Id(b.Pocket)) : null, b.Place);
        }
        // Nothing makeable: hit the first target full and firmly.
        var target0 = targets[0];
        Vec3? placed = null;
        var from = balls.TryGetValue(PoolBalls.Cue, out var c0) ? c0 : Initializer(table);
        if (hand != BallInHand.None)
        {
            foreach (double d in new[] { 0.3, 0.5, 0.8 })
            {
                var p = target0.Value - new Vec3(d, 0, 0);
                if (Placeable(p, balls, table, hand))
                {
                    placed = p;
                    from = p;
                    break;
                }
            }
        }
        var dir = target0.Value - from;
        var nearest = pockets.OrderBy(p => (p.Centre - target0.Value).LengthXY).First();
        return new GameShot(new ShotSpec(Tip * 3.0, Math.Atan2(dir.Y, dir.X) * 180 / Math.PI), callShots ? new Call(target0.Key, PoolPockets.Set.Id(nearest.Pocket)) : null, placed);
    }

    /// <summary>A hard break at the apex ball from the head spot.</summary>
    public static GameShot Break(Match game, Call? call)
    {
        var head = Initializer(game.Setup.Table);
        var apex = Billiards.Core.Setup.Initializer.FootSpot(game.Setup.Table, R);
        var d = apex - head;
        return new GameShot(new ShotSpec(Tip * 9.0, Math.Atan2(d.Y, d.X) * 180 / Math.PI), call, head);
    }

    /// <summary>A soft roll into the clearest direction: touches no ball (a no-contact foul, or a push-out).</summary>
    public static GameShot Roll(Match game, bool pushOut = false, RefereeOption? choice = null)
    {
        var balls = game.Balls.ToDictionary();
        var table = game.Setup.Table;
        var cue = balls.TryGetValue(PoolBalls.Cue, out var c) ? c : Initializer(table);
        var pockets = Billiards.Core.Table.TableGeometry.Build(table, R).Pockets.ToArray();
        double bestAngle = 0, bestClearance = -1;
        for (int k = 0; k < 72; k++)
        {
            double a = k * 5 * Math.PI / 180;
            var end = cue + new Vec3(Math.Cos(a), Math.Sin(a), 0) * 0.5;
            if (Math.Abs(end.X) > table.HalfLength - 2 * R || Math.Abs(end.Y) > table.HalfWidth - 2 * R)
            {
                continue;
            }
            double clearance = balls.Where(b => !PoolBalls.IsCue(b.Key)).Select(b => Distance(b.Value, cue, end)).DefaultIfEmpty(1).Min();
            clearance = Math.Min(clearance, pockets.Select(p => Distance(p.Centre with { Z = R }, cue, end) - 0.1).Min());
            if (clearance > bestClearance)
            {
                bestClearance = clearance;
                bestAngle = k * 5;
            }
        }
        return new GameShot(new ShotSpec(Tip * 0.15, bestAngle), null, null, pushOut, choice);
    }

    private static Vec3 Initializer(TableSpec table) => Billiards.Core.Setup.Initializer.HeadSpot(table, R);

    private static bool Placeable(Vec3 p, IReadOnlyDictionary<BallId, Vec3> balls, TableSpec table, BallInHand hand) =>
        Math.Abs(p.X) < table.HalfLength - 2 * R && Math.Abs(p.Y) < table.HalfWidth - 2 * R
        && (hand != BallInHand.Kitchen || p.X < -table.HalfLength / 2)
        && balls.Where(b => !PoolBalls.IsCue(b.Key)).All(b => (b.Value - p).Length > 2 * R + 0.005);

    private static bool Clear(IReadOnlyDictionary<BallId, Vec3> balls, Vec3 a, Vec3 b, BallId skip1, BallId skip2) =>
        balls.Where(x => x.Key != skip1 && x.Key != skip2).All(x => Distance(x.Value, a, b) > 2 * R + 0.003);

    private static double Distance(Vec3 p, Vec3 a, Vec3 b)
    {
        var ab = b - a;
        double t = Math.Clamp(Dot(p - a, ab) / Math.Max(Dot(ab, ab), 1e-12), 0, 1);
        return (a + ab * t - p).LengthXY;
    }

    private static double Dot(Vec3 a, Vec3 b) => a.X * b.X + a.Y * b.Y;
}
