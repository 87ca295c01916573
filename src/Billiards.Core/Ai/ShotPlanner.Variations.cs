using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.Core.Ai;

/// <summary>The variations the search simulates: each candidate at several speeds and spins, and the break.</summary>
public sealed partial class ShotPlanner
{
    /// <summary>The most samples <see cref="Sensitivity"/> takes.</summary>
    public const int MaxSensitivitySamples = 1000;

    /// <summary>
    /// The variation sampler turned on a person's shot: <paramref name="shot"/> played
    /// <paramref name="samples"/> times from <paramref name="position"/>, each time with the error of
    /// <paramref name="level"/> drawn anew (<see cref="SkillLevel.Execute"/>: aim, speed and tip), as
    /// the search samples its own shots. A sample pots when <paramref name="target"/> (or, with none,
    /// any object ball) drops and the cue ball stays on the table. Sample i draws from the stream
    /// <see cref="PlannerRandom.Derive"/>(<paramref name="seed"/>, i): the same arguments, the same endings.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">When <paramref name="samples"/> is not 1 to <see cref="MaxSensitivitySamples"/>.</exception>
    public ShotSensitivity Sensitivity(TablePosition position, ShotSpec shot, SkillLevel level, int samples, ulong seed, BallId? target = null)
    {
        ArgumentNullException.ThrowIfNull(position);
        ArgumentNullException.ThrowIfNull(shot);
        ArgumentNullException.ThrowIfNull(level);
        ArgumentOutOfRangeException.ThrowIfLessThan(samples, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(samples, MaxSensitivitySamples);
        var sim = position.CreateSimulation(Model);
        var start = sim.CreateSnapshot();
        int cue = sim.IndexOf(position.CueBall);
        int aimed = target is { } t ? sim.IndexOf(t) : -1;
        var endings = new ShotEnding[samples];
        for (int i = 0; i < samples; i++)
        {
            var played = level.Execute(shot, new PlannerRandom(PlannerRandom.Derive(seed, i)));
            sim.Restore(start);
            sim.Strike(played, position.CueBall);
            sim.AdvanceTo(MaxShotTime);
            var balls = sim.Balls;
            bool cueOn = cue >= 0 && !balls[cue].IsOutOfPlay;
            bool dropped = false;
            for (int k = 0; k < balls.Length; k++)
            {
                dropped |= k != cue && (aimed < 0 || k == aimed) && balls[k].IsOutOfPlay;
            }
            endings[i] = new ShotEnding(
                played,
                cueOn && dropped,
                cueOn ? balls[cue].Position : null,
                aimed >= 0 && !balls[aimed].IsOutOfPlay ? balls[aimed].Position : null);
        }
        return new ShotSensitivity(level, endings);
    }

    private sealed partial class Search
    {
        // The levels that look ahead (3 to 5) search the wide break grid when they play for the noise.
        private bool PlaysBreakForNoise => level.Error == SearchError.Noise && level.LookAhead > 0;

        // This search is of such a break (the wide grid), whose rounds BreakSearch sizes.
        private bool SearchesNoiseBreak => PlaysBreakForNoise && Ruleset.For(state.Rules).IsPowerBreak(state);

        private void AddVariations(int rootIndex, Root root, int candidates, List<Variation> variations)
        {
            var cue = root.Cue;
            var ruleset = Ruleset.For(state.Rules);
            if (state.Shot == 0)
            {
                if (ruleset.PowerBreak)
                {
                    AddBreak(rootIndex, root, variations);
                }
                else
                {
                    AddBreakOff(rootIndex, root, variations);
                }
                return;
            }
            bool call = ruleset.NeedsCall(state);
            bool nominates = ruleset.Nominates(state);
            var pots = CandidateGenerator.Pots(_table, state, root.Position, cue)
                // A nominated ball must be the one struck first and the one potted (snooker).
                .Where(c => !nominates || c.Called == c.Target)
                .OrderByDescending(c => c.Prior).Take(candidates).ToList();
            // Where frames turn on safety exchanges (the policy counts safeties per ball, snooker's
            // two a ball on up to 24), the stronger levels try that many, not just one for the first few balls.
            int safetyCount = level.Level < 3 ? 2
                : ruleset.Policy.SafetiesPerTarget > 0 ? Math.Max(candidates / 2 + 2, Math.Min(ruleset.Policy.MaxSafeties, ruleset.Policy.SafetiesPerTarget * PlannerTable.LegalTargets(state, root.Position).Count))
                : candidates / 2 + 2;
            var safeties = CandidateGenerator.Safeties(_table, state, root.Position, cue).Take(safetyCount).ToList();
            if (pots.Count == 0 && safeties.Count == 0)
            {
                safeties = CandidateGenerator.LastResort(_table, state, root.Position, cue);
            }
            var before = state with { Placement = root.Place, PushOut = false };
            foreach (var c in pots)
            {
                var withCall = before with { Call = call ? new Call(c.Called, c.Pocket) : ruleset.Nomination(state, c.Target) };
                Vary(rootIndex, c, cue, withCall, level.Speeds, level.Spins, variations);
            }
            foreach (var c in safeties)
            {
                var withCall = before with { Call = call ? Call.Safety : ruleset.Nomination(state, c.Target) };
                Vary(rootIndex, c, cue, withCall, Math.Min(level.Speeds, 3), Math.Min(level.Spins, 3), variations);
            }
            AddJumps(rootIndex, root, before, call, variations);
            // 9-ball and 10-ball: the shot after the break may be a push-out (no contact needed).
            if (level.LookAhead > 0 && Ruleset.For(state.Rules).MayPushOut(state)
                && pots.All(c => c.Prior < 0.2))
            {
                var push = state with { Placement = root.Place, PushOut = true, Call = null };
                foreach (var c in safeties.Take(3))
                {
                    Vary(rootIndex, c with { Kind = ShotKind.PushOut }, cue, push, 2, 1, variations);
                }
            }
        }

        private void AddBreak(int rootIndex, Root root, List<Variation> variations)
        {
            var balls = root.Position.Balls.Where(b => b.Id != root.Position.CueBall).ToList();
            if (balls.Count == 0)
            {
                return;
            }
            var foot = Setup.Initializer.FootSpot(_table.Table, _table.R);
            var apex = balls.OrderBy(b => (b.Position - foot).LengthXY).First();
            var before = state with { Placement = root.Place, Call = null, PushOut = false };
            if (PlaysBreakForNoise)
            {
                AddBreakUnderNoise(rootIndex, root, balls, foot, before, variations);
                return;
            }
            var n = (apex.Position - root.Cue).XY.Normalized();
            var side = new Vec3(-n.Y, n.X, 0);
            var offsets = level.Level >= 3 ? new[] { 0.0, 0.3, -0.3 } : [0.0];
            var speeds = level.Level >= 2 ? new[] { 6.0, 7.5 } : [6.5];
            foreach (double offset in offsets)
            {
                var aimPoint = apex.Position + side * (offset * _table.R);
                var c = new Candidate(ShotKind.Break, apex.Id, apex.Id, PocketId.None, apex.Position, Vec3.Zero, aimPoint, 7, 0.5);
                foreach (double speed in speeds)
                {
                    var d = aimPoint - root.Cue;
                    var shot = new ShotSpec(speed * _table.TipScale, DeterministicMath.Atan2(d.Y, d.X) * 180 / Math.PI, 0, -0.2, 0);
                    variations.Add(new Variation(rootIndex, c, shot, before));
                }
            }
        }

        // The break of the planner that plays for the noise (NoiseBreakSpots and the grids beside
        // it): from each spot, at the head ball and at the second-row ball nearer the cue ball, full
        // or cut, at every speed and tip height of the grid; the search's rounds then keep the one
        // whose outcomes under the noise on this rack (its own gaps) score best. In the rotation
        // games a second-row ball struck first is a foul, which the search scores as one.
        private void AddBreakUnderNoise(int rootIndex, Root root, List<(BallId Id, Vec3 Position)> balls, Vec3 foot, GameState before, List<Variation> variations)
        {
            var cue = root.Cue;
            var byFoot = balls.OrderBy(b => (b.Position - foot).LengthXY).ToList();
            var second = byFoot.Skip(1).Take(2).OrderBy(b => (b.Position - cue).LengthXY).ToList();
            var targets = second.Count > 0 ? new[] { byFoot[0], second[0] } : [byFoot[0]];
            // The cut mirrors with the spot: from the y >= 0 half to the ball's side nearer the -y rail, and back.
            double towards = cue.Y >= 0 ? -1 : 1;
            foreach (var target in targets)
            {
                var n = (target.Position - cue).XY.Normalized();
                var side = new Vec3(-n.Y, n.X, 0);
                foreach (double offset in NoiseBreakOffsets)
                {
                    var aimPoint = target.Position + side * (towards * offset * _table.R);
                    var d = aimPoint - cue;
                    double aim = DeterministicMath.Atan2(d.Y, d.X) * 180 / Math.PI;
                    var c = new Candidate(ShotKind.Break, target.Id, target.Id, PocketId.None, target.Position, Vec3.Zero, aimPoint, 7, 0.5);
                    foreach (double speed in NoiseBreakSpeeds)
                    {
                        foreach (double height in NoiseBreakHeights)
                        {
                            variations.Add(new Variation(rootIndex, c, new ShotSpec(speed * _table.TipScale, aim, 0, height, 0), before));
                        }
                    }
                }
            }
        }

        // An opening safety (snooker's break-off): the cue ball glances thinly off the outside of
        // one of the pack's outermost balls as seen from the cue ball, at a few thicknesses, speeds
        // and sides, to come back off the cushions and leave the pack barely disturbed.
        private void AddBreakOff(int rootIndex, Root root, List<Variation> variations)
        {
            var balls = PlannerTable.LegalTargets(state, root.Position)
                .Select(b => (Id: b, Position: root.Position.Positions[root.Position.IndexOf(b)])).ToList();
            if (balls.Count == 0)
            {
                return;
            }
            var cue = root.Cue;
            var centre = balls.Aggregate(Vec3.Zero, (sum, b) => sum + b.Position) * (1.0 / balls.Count);
            var axis = (centre - cue).XY.Normalized();
            double Across(Vec3 p) => Vec3.Cross(axis, (p - cue).XY.Normalized()).Z;
            int each = level.Level >= 3 ? 2 : 1;
            var outermost = balls.OrderByDescending(b => Across(b.Position)).Take(each)
                .Concat(balls.OrderBy(b => Across(b.Position)).Take(each));
            var before = state with { Placement = root.Place, Call = null, PushOut = false };
            double[] offsets = level.Level >= 3 ? [1.45, 1.65, 1.85] : [1.65];
            double[] speeds = level.Level >= 2 ? [3.2, 4.0, 4.8] : [4.0];
            double[] sides = level.Level >= 3 ? [0, 0.3, -0.3] : [0];
            foreach (var (id, o) in outermost)
            {
                var line = (o - cue).XY.Normalized();
                // The side of the ball away from the pack's centre line.
                var outward = new Vec3(-line.Y, line.X, 0) * Math.Sign(Across(o) == 0 ? 1 : Across(o));
                foreach (double offset in offsets)
                {
                    var aimPoint = o + (outward * (offset * _table.R));
                    var c = new Candidate(ShotKind.Safety, id, id, PocketId.None, o, Vec3.Zero, aimPoint, 4, 0.1);
                    var d = aimPoint - cue;
                    double aim = DeterministicMath.Atan2(d.Y, d.X) * 180 / Math.PI;
                    foreach (double speed in speeds)
                    {
                        foreach (double side in sides)
                        {
                            variations.Add(new Variation(rootIndex, c, new ShotSpec(speed * _table.TipScale, aim, side, 0.1, 0), before));
                        }
                    }
                }
            }
        }

        private void Vary(int rootIndex, Candidate c, Vec3 cue, GameState before, int speeds, int spins, List<Variation> variations)
        {
            var factors = SpeedFactors.Take(speeds).Order().ToArray();
            for (int k = 0; k < spins; k++)
            {
                var (sideTip, height, elevation) = SpinSet[k];
                double aim = planner.AimFor(c, cue, sideTip, height);
                foreach (double f in factors)
                {
                    double speed = Math.Min(MaxNormalSpeed, c.BaseSpeed * f) * _table.TipScale;
                    variations.Add(new Variation(rootIndex, c, new ShotSpec(speed, aim, sideTip, height, elevation), before));
                }
            }
        }
    }
}
