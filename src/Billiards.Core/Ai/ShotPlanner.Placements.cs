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
            var region = state.Shot == 0 ? BallInHand.Kitchen : state.BallInHand;
            if (region == BallInHand.None && position.Cue is { } cue)
            {
                return [new Root(position, cue, null)];
            }
            if (region == BallInHand.None)
            {
                region = BallInHand.Table;
            }
            var spots = state.Shot == 0 ? BreakSpots() : Placements(region);
            return [.. spots.Select(p => new Root(position.With(position.CueBall, p), p, p))];
        }

        private List<Vec3> BreakSpots()
        {
            var t = _table.Table;
            double r = _table.R;
            double x = -t.HalfLength / 2 - 2 * r;
            var spots = new List<Vec3> { new(x, 0, r) };
            if (level.Level >= 3)
            {
                spots.Add(new Vec3(x, 0.45 * t.HalfWidth, r));
                spots.Add(new Vec3(x, -0.45 * t.HalfWidth, r));
            }
            return [.. spots.Where(p => position.CanPlace(p, BallInHand.Kitchen, t, r, position.CueBall))];
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
                        var back = new Vec3(u.X * Math.Cos(a) - u.Y * Math.Sin(a), u.X * Math.Sin(a) + u.Y * Math.Cos(a), 0);
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
