using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;

namespace Billiards.Core.Ai;

/// <summary>Where the search puts the cue ball: the roots of the search with ball in hand and on the break.</summary>
public sealed partial class ShotPlanner
{
    private sealed partial class Search
    {
        private List<Root> Roots()
        {
            var ruleset = Ruleset.For(state.Rules);
            var region = state.Shot == 0 ? ruleset.BreakBallInHand : state.BallInHand;
            if (region == BallInHand.None && position.Cue is { } cue)
            {
                return [new Root(position, cue, null)];
            }
            if (region == BallInHand.None)
            {
                region = BallInHand.Table;
            }
            var spots = state.Shot > 0 ? Placements(region) : ruleset.PowerBreak ? BreakSpots() : OpeningSpots(region);
            return [.. spots.Select(p => new Root(position.With(position.CueBall, p), p, p))];
        }

        private List<Vec3> BreakSpots()
        {
            var t = _table.Table;
            double r = _table.R;
            double x = -t.HalfLength / 2 - 2 * r;
            var spots = new List<Vec3> { new(x, 0, r) };
            if (PlaysBreakForNoise)
            {
                // Playing for the noise: the spots across the kitchen towards either rail (NoiseBreakSpots).
                spots = [.. NoiseBreakSpots.Select(f => new Vec3(x, f * (t.HalfWidth - r), r))];
            }
            else if (level.Level >= 3)
            {
                spots.Add(new Vec3(x, 0.45 * t.HalfWidth, r));
                spots.Add(new Vec3(x, -0.45 * t.HalfWidth, r));
            }
            return [.. spots.Where(p => position.CanPlace(p, BallInHand.Kitchen, t, r, position.CueBall))];
        }

        // An opening safety's spots (snooker's break-off from the D): across the region's front,
        // the middle first, then out to either side.
        private List<Vec3> OpeningSpots(BallInHand region)
        {
            var t = _table.Table;
            double r = _table.R;
            var spots = new List<Vec3>();
            foreach (double y in (ReadOnlySpan<double>)[0.06, -0.06, 0.14, -0.14, 0.22, -0.22, 0.1, -0.1])
            {
                var p = FrontOf(region, y);
                if (position.CanPlace(p, region, t, r, position.CueBall) && spots.Count < Math.Max(1, level.Placements))
                {
                    spots.Add(p);
                }
            }
            return spots;
        }

        // The point of the region at the front of it (nearest the table's far end) at y (m): the
        // baulk line for the D, the head string for the kitchen, a ball's width behind the line.
        private Vec3 FrontOf(BallInHand region, double y)
        {
            var t = _table.Table;
            double r = _table.R;
            double x = region switch
            {
                BallInHand.D => Billiards.Core.Table.SnookerTable.BaulkLineX(t) - (1.5 * r),
                BallInHand.Kitchen => Setup.Placement.HeadString(t) - (1.5 * r),
                _ => 0,
            };
            return new Vec3(x, y, r);
        }

        private List<Vec3> Placements(BallInHand region)
        {
            var t = _table.Table;
            double r = _table.R;
            var scored = new List<(Vec3 P, double Ease)>();
            var without = position.Without(position.CueBall);
            foreach (var target in PlannerTable.LegalTargets(state, without))
            {
                var o = without.Positions[without.IndexOf(target)];
                foreach (var pocket in _table.Pockets)
                {
                    var aim = _table.AimPoint(pocket);
                    var u = (aim - o).XY.Normalized();
                    if (_table.Window(pocket, u) <= 0 || _table.Blocked(without, o, aim, target))
                    {
                        continue;
                    }
                    var ghost = _table.Ghost(o, aim);
                    foreach (double cutDeg in (ReadOnlySpan<double>)[0, 15, -15, 30, -30])
                    {
                        double a = cutDeg * Math.PI / 180;
                        var back = new Vec3(u.X * DeterministicMath.Cos(a) - u.Y * DeterministicMath.Sin(a), u.X * DeterministicMath.Sin(a) + u.Y * DeterministicMath.Cos(a), 0);
                        foreach (double distance in (ReadOnlySpan<double>)[0.15, 0.3, 0.55])
                        {
                            var p = (ghost - back * distance) with { Z = r };
                            if (without.CanPlace(p, region, t, r, position.CueBall))
                            {
                                double ease = _table.DirectEase(without.With(position.CueBall, p), p, target, pocket);
                                if (ease > 0)
                                {
                                    scored.Add((p, ease - 0.02 * Math.Abs(cutDeg) / 15));
                                }
                            }
                        }
                    }
                }
            }
            var chosen = new List<Vec3>();
            foreach (var (p, _) in scored.OrderByDescending(s => s.Ease))
            {
                if (chosen.Count >= level.Placements)
                {
                    break;
                }
                if (chosen.All(q => (q - p).LengthXY > 0.1))
                {
                    chosen.Add(p);
                }
            }
            if (chosen.Count == 0)
            {
                // Nothing to pot: a spot with a clear look at a target, else any free spot.
                var grid = new List<Vec3>();
                for (double gx = -0.9; gx <= 0.9; gx += 0.15)
                {
                    for (double gy = -0.8; gy <= 0.8; gy += 0.2)
                    {
                        var p = new Vec3(gx * (t.HalfLength - r), gy * (t.HalfWidth - r), r);
                        if (without.CanPlace(p, region, t, r, position.CueBall))
                        {
                            grid.Add(p);
                        }
                    }
                }
                if (region == BallInHand.D)
                {
                    // The D is too small for the table's grid: its own, along the line and round the arc.
                    double baulk = Billiards.Core.Table.SnookerTable.BaulkLineX(t), d = Billiards.Core.Table.SnookerTable.DRadius - (2 * r);
                    for (int k = -4; k <= 4; k++)
                    {
                        double a = k * Math.PI / 10;
                        grid.Add(new Vec3(baulk - (2 * r), k * d / 4, r));
                        grid.Add(new Vec3(baulk - (2 * r) - (0.5 * d * DeterministicMath.Cos(a)), 0.5 * d * DeterministicMath.Sin(a), r));
                        grid.Add(new Vec3(baulk - (2 * r) - (d * DeterministicMath.Cos(a)), d * DeterministicMath.Sin(a), r));
                    }
                    grid.RemoveAll(p => !without.CanPlace(p, region, t, r, position.CueBall));
                }
                var targets = PlannerTable.LegalTargets(state, without);
                chosen.AddRange(grid.Where(p => targets.Any(b => !_table.Blocked(without, p, without.Positions[without.IndexOf(b)], b))).Take(2));
                if (chosen.Count == 0 && grid.Count > 0)
                {
                    chosen.Add(grid[0]);
                }
            }
            return chosen;
        }
    }
}
