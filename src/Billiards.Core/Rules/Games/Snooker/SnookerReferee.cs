using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// Snooker's referee (rules.md "Snooker"). One pass over a shot: which balls were on (the reds, the
/// nominated colour, the colour in turn, or a nominated free ball), the fouls and their penalty
/// (the highest value of the ball on and of the balls wrongly struck, potted or driven off, at
/// least 4), the points of the balls legally potted, which colours are re-spotted, whether a foul
/// was a miss (and whether it was the third with a full ball view), whether the incoming player is
/// snookered (a free ball), the ball on next, and the end of the frame with the re-spotted black on
/// equal scores.
/// </summary>
/// <remarks>
/// Whether a player is snookered is read off the balls as they stand (before the shot for the
/// striker, after it and its re-spots for the incoming player) by <see cref="Sightlines"/>. Ours
/// where the rules leave a measure open: the cue ball's path length for the snookered striker's
/// miss is taken as the straight distance from where it stood to where it came to rest (a lower
/// bound of the path: a cue ball that rests that far away surely travelled that far); a jump shot
/// is a cue ball that left the bed before its first contact with an object ball lying on its
/// straight line of flight short of the ball it struck.
/// </remarks>
internal sealed class SnookerReferee(TableSpec table, double ballRadius) : RefereeBase(GameRules.Snooker, table, ballRadius)
{
    // Snooker's one cue ball, the white.
    private static readonly BallId Cue = BallSet.Snooker.CueBalls[0];

    protected override Ruling Rule(GameState before, ShotRecord shot, ShotFacts facts, RulingBuilder ruling) =>
        new Judgement(this, before, shot, facts, ruling).Rule();

    // The work of one shot, with its facts at hand.
    private sealed class Judgement(SnookerReferee referee, GameState before, ShotRecord shot, ShotFacts facts, RulingBuilder ruling)
    {
        private readonly double _r = referee.BallRadius;
        private readonly TableSpec _table = referee.Table;

        // The balls in the way of one sightline, filled anew for each (Obstacles).
        private readonly List<Vec3> _obstacles = new(shot.Ids.Length);

        public Ruling Rule()
        {
            int shooter = before.Shooter, incoming = before.Incoming;
            var onTableBefore = facts.OnTableBefore.Select(n => new BallId(n)).ToList();
            var positionsBefore = shot.BallsBefore.Length == shot.Ids.Length ? shot.InPlayBefore(_r) : shot.InPlayAfter(_r);
            string ballOn = SnookerRuleset.BallOnOf(before);
            bool redsPhase = ballOn is SnookerRuleset.Red or SnookerRuleset.Colour;
            BallId? nominated = before.Call is { IsNomination: true } c ? c.Ball : null;
            bool freeBall = SnookerPart.Of(before).FreeBall && nominated is not null;
            if (ballOn == SnookerRuleset.Colour && nominated is null && facts.FirstContact is { } firstColour && SnookerRuleset.IsColour(firstColour))
            {
                // No colour was nominated: the first colour struck is taken as the one nominated (ours).
                nominated = firstColour;
            }

            // The balls on: what may be struck first, and what may be potted.
            var firstOn = new HashSet<BallId>(freeBall ? [nominated!.Value] : BallsOn(ballOn, nominated, onTableBefore));
            var pottable = new HashSet<BallId>(firstOn);
            if (freeBall)
            {
                pottable.UnionWith(BallsOn(ballOn, null, onTableBefore));
            }
            int ballOnValue = ballOn switch
            {
                SnookerRuleset.Red => 1,
                SnookerRuleset.Colour => nominated is { } n ? SnookerRuleset.ValueOf(n) : 0,
                var name => BallSet.Snooker.TryParse(name, out var b) ? SnookerRuleset.ValueOf(b) : 0,
            };

            // Fouls and the values of the balls involved.
            int penalty = Math.Max(SnookerRuleset.MinimumPenalty, ballOnValue);
            var hand = before.Shot == 0 ? BallInHand.D : before.BallInHand;
            if (hand != BallInHand.None && before.Placement is { } placed && (facts.BadPlacement || !SnookerTable.InD(_table, placed)))
            {
                ruling.Foul(Foul.BadPlacement, "the cue ball was placed outside the D or on a ball");
            }
            if (facts.Scratch)
            {
                ruling.Foul(Foul.CueBallPocketed, "the cue ball went in off");
            }
            if (facts.CueOffTable || facts.OffTable.Count > 0)
            {
                ruling.Foul(Foul.BallOffTable);
                penalty = Math.Max(penalty, facts.OffTable.Select(SnookerRuleset.ValueOf).DefaultIfEmpty(0).Max());
            }
            bool missedTheBallOn = false;
            if (facts.FirstContact is not { } first)
            {
                ruling.Foul(Foul.NoContact, "the cue ball struck no ball");
                missedTheBallOn = true;
            }
            else if (!firstOn.Contains(first))
            {
                ruling.Foul(Foul.WrongBallFirst, $"the cue ball first struck the {first}, not {OnText(ballOn, nominated, freeBall)}");
                penalty = Math.Max(penalty, SnookerRuleset.ValueOf(first));
                missedTheBallOn = true;
            }
            var wronglyPotted = facts.Pocketed.Where(b => !pottable.Contains(b)).ToList();
            if (wronglyPotted.Count > 0)
            {
                ruling.Foul(Foul.WrongBallPotted, $"the {wronglyPotted[0]} was potted, not a ball on");
                penalty = Math.Max(penalty, wronglyPotted.Max(SnookerRuleset.ValueOf));
            }
            if (facts.FirstContact is { } struck && JumpedOver(positionsBefore, struck))
            {
                ruling.Foul(Foul.JumpShot, "the cue ball jumped over a ball");
            }

            // Points for the balls on legally potted.
            var potted = facts.Pocketed.Where(pottable.Contains).ToList();
            int points = 0;
            if (ruling.Legal && potted.Count > 0)
            {
                points = ballOn switch
                {
                    // Each red and a free ball taken as a red count 1.
                    SnookerRuleset.Red => potted.Count,
                    SnookerRuleset.Colour => ballOnValue,
                    // The colour in turn, or a free ball taken as it: its value once.
                    _ => ballOnValue,
                };
            }

            // Colours to re-spot: every colour potted or driven off, but the colour in turn potted legally in the colours phase.
            var spot = facts.Pocketed.Concat(facts.OffTable).Where(SnookerRuleset.IsColour)
                .Where(b => redsPhase || !ruling.Legal || b != BallOnBall(ballOn))
                .ToList();
            var afterTable = shot.InPlayAfter(_r);
            bool cueInHand = facts.Scratch || facts.CueOffTable;
            afterTable = !cueInHand && shot.IndexOf(Cue) is int ci and >= 0 && !shot.BallsAfter[ci].IsOutOfPlay
                ? afterTable.With(Cue, shot.BallsAfter[ci].Position)
                : afterTable.Without(Cue);

            bool scoring = ruling.Legal && points > 0;
            var score = before.Score.With(shooter, before.Score[shooter] + points);
            if (!ruling.Legal)
            {
                score = score.With(incoming, score[incoming] + penalty);
            }

            // End of the frame: the black potted or fouled with nothing else on the table.
            bool lastBlack = onTableBefore.Count == 1 && onTableBefore[0] == BallSet.Colour("black");
            if (lastBlack && (!ruling.Legal || points > 0))
            {
                return EndOfFrame(score, points, penalty);
            }

            afterTable = SnookerRuleset.Respot(afterTable, spot, _table, _r);
            var objectsAfter = afterTable.Ids.Where(b => b != Cue).ToList();
            string nextOn = scoring
                ? ballOn switch
                {
                    SnookerRuleset.Red => SnookerRuleset.Colour,
                    _ => SnookerRuleset.TurnBallOn(objectsAfter),
                }
                : SnookerRuleset.TurnBallOn(objectsAfter);

            // Foul and a miss, and the three-miss rule.
            bool miss = false;
            var misses = SnookerPart.Of(before).MissesInRow;
            if (!ruling.Legal && missedTheBallOn)
            {
                bool snookersNeeded = SnookerRuleset.NeedsSnookers(before.Score, ballOn, onTableBefore)
                    || SnookerRuleset.NeedsSnookers(score, nextOn, objectsAfter);
                miss = !lastBlack && !snookersNeeded && !SnookeredAndReached(positionsBefore, firstOn);
            }
            misses = misses.With(shooter, miss ? misses[shooter] + 1 : 0);
            // The full view matters only from a second miss in a row on.
            bool fullView = miss && misses[shooter] >= 2 && positionsBefore.PositionOf(Cue) is { } cueBefore
                && firstOn.Any(b => positionsBefore.PositionOf(b) is { } p && Sightlines.BothSides(cueBefore, p, Obstacles(positionsBefore, b), _r));
            if (miss && fullView && misses[shooter] >= 3)
            {
                ruling.Foul(Foul.ThreeMisses, "a third foul and a miss in a row with a full ball view");
                ruling.Score = score;
                ruling.Win(incoming, $"{before.IncomingName} wins the frame: {before.ShooterName} missed three times in a row with a full view of the ball on.");
                return Finish(penalty, 0, miss, false, null, misses, nextOn);
            }
            if (miss && fullView && misses[shooter] == 2)
            {
                ruling.Note = $"Warning: a third miss in a row with a full ball view loses {before.ShooterName} the frame.";
            }

            // Free ball for the incoming player, snookered after a foul; snookering behind a free ball is a foul itself.
            // Only a foul (a free ball) or a safety off a free ball asks; the sightlines are not looked at for other shots.
            bool freeBallSafety = ruling.Legal && freeBall && !scoring;
            bool incomingSnookered = (!ruling.Legal || freeBallSafety) && !cueInHand && Snookered(afterTable, nextOn);
            if (freeBallSafety && incomingSnookered && !OnlyPinkAndBlack(objectsAfter)
                && !Snookered(afterTable.Without(nominated!.Value), nextOn))
            {
                ruling.Foul(Foul.SnookeredByFreeBall, $"{before.IncomingName} was left snookered behind the free ball");
                score = score.With(incoming, score[incoming] + penalty);
            }
            bool offerFreeBall = !ruling.Legal && incomingSnookered;

            foreach (var ball in spot)
            {
                ruling.SpotBall(ball);
            }
            ruling.Score = score;
            ruling.Continue = scoring;
            ruling.BallInHand = cueInHand ? BallInHand.D : BallInHand.None;
            GameState? replaced = null;
            if (!ruling.Legal)
            {
                ruling.Options.AddRange([RefereeOption.Play, RefereeOption.PutBack]);
                if (miss)
                {
                    ruling.Options.Add(RefereeOption.Replace);
                    replaced = before with
                    {
                        Shot = before.Shot + 1,
                        Call = null,
                        Placement = null,
                        Score = score,
                        Part = SnookerPart.Of(before) with { MissesInRow = misses },
                    };
                }
                if (offerFreeBall)
                {
                    ruling.Outcome = $"{before.IncomingName} is snookered: a free ball.";
                }
            }
            return Finish(ruling.Legal ? 0 : penalty, points, miss, offerFreeBall, replaced, misses, nextOn);
        }

        // The black decided the frame: the higher score wins; on equal scores the black is re-spotted
        // and the other player plays first from in hand in the D (ours: who plays first).
        private Ruling EndOfFrame(PerPlayer<int> score, int points, int penalty)
        {
            ruling.Score = score;
            if (score.First != score.Second)
            {
                int winner = score.First > score.Second ? 0 : 1;
                ruling.Win(winner, $"{before.Players[winner]} wins the frame {Math.Max(score.First, score.Second)}-{Math.Min(score.First, score.Second)}.");
                return Finish(ruling.Legal ? 0 : penalty, points, false, false, null, SnookerPart.Of(before).MissesInRow.With(before.Shooter, 0), "black");
            }
            ruling.SpotBall(BallSet.Colour("black"));
            ruling.Continue = false;
            ruling.BallInHand = BallInHand.D;
            ruling.Outcome = $"Scores level at {score.First}: the black is re-spotted and {before.IncomingName} plays from the D.";
            return Finish(ruling.Legal ? 0 : penalty, points, false, false, null, default, "black");
        }

        private Ruling Finish(int penalty, int points, bool miss, bool freeBall, GameState? replaced, PerPlayer<int> misses, string nextOn)
        {
            // The points in words: a foul's penalty to the incoming player, a pot's points to the shooter.
            ruling.Scored = !ruling.Legal && penalty > 0 ? string.Create(CultureInfo.InvariantCulture, $"{penalty} points to {before.IncomingName}.")
                : ruling.Legal && points > 0 ? string.Create(CultureInfo.InvariantCulture, $"{before.ShooterName} pots {PotWords(facts.Pocketed)}: {points} {(points == 1 ? "point" : "points")}.")
                : null;
            var built = ruling.Build();
            var next = built.GameOver ? built.Next : built.Next with { Part = new SnookerPart { BallOn = nextOn, FreeBall = freeBall, MissesInRow = misses } };
            return built with
            {
                Next = next,
                Points = points,
                Penalty = built.Legal ? 0 : penalty,
                Part = new SnookerRulingPart { FoulAndMiss = miss, FreeBall = freeBall, Replaced = replaced },
            };
        }

        // "a red", "2 reds", "the pink", "a red and the blue" (a free ball potted with a red).
        private static string PotWords(IReadOnlyList<BallId> potted)
        {
            int reds = potted.Count(b => !SnookerRuleset.IsColour(b));
            var words = new List<string>();
            if (reds > 0)
            {
                words.Add(reds == 1 ? "a red" : string.Create(CultureInfo.InvariantCulture, $"{reds} reds"));
            }
            words.AddRange(potted.Where(SnookerRuleset.IsColour).Select(b => $"the {b}"));
            return words.Count <= 1 ? string.Concat(words) : $"{string.Join(", ", words.Take(words.Count - 1))} and {words[^1]}";
        }

        private static BallId? BallOnBall(string ballOn) => BallSet.Snooker.TryParse(ballOn, out var b) && SnookerRuleset.IsColour(b) ? b : null;

        private static IEnumerable<BallId> BallsOn(string ballOn, BallId? nominated, List<BallId> onTable) =>
            ballOn == SnookerRuleset.Colour && nominated is { } n ? [n] : onTable.Where(b => IsOn(ballOn, b));

        // A ball on before any nomination: a red, any colour, or the colour in turn.
        private static bool IsOn(string ballOn, BallId ball) => ballOn switch
        {
            SnookerRuleset.Red => SnookerRuleset.IsRed(ball),
            SnookerRuleset.Colour => SnookerRuleset.IsColour(ball),
            var name => ball == BallOnBall(name),
        };

        private static string OnText(string ballOn, BallId? nominated, bool freeBall) =>
            freeBall ? $"the free ball ({nominated})" : ballOn switch
            {
                SnookerRuleset.Red => "a red",
                SnookerRuleset.Colour => nominated is { } n ? $"the nominated {n}" : "a colour",
                var name => $"the {name}",
            };

        private static bool OnlyPinkAndBlack(List<BallId> objects) =>
            objects.All(b => b == BallSet.Colour("pink") || b == BallSet.Colour("black"));

        // The striker was snookered (no straight line to any part of any ball on) and the cue ball
        // travelled at least as far as the nearest ball on: no miss.
        private bool SnookeredAndReached(BallLayout positions, HashSet<BallId> on)
        {
            if (positions.PositionOf(Cue) is not { } cue)
            {
                return false;
            }
            var targets = on.Where(positions.Contains).ToList();
            // The nearest first: the answer does not depend on the order, and a near ball is the likeliest in view.
            targets.Sort((a, b) => (positions[a] - cue).LengthXY.CompareTo((positions[b] - cue).LengthXY));
            if (targets.Count == 0 || targets.Exists(b => Sightlines.AnyPart(cue, positions[b], Obstacles(positions, b), _r)))
            {
                return false;
            }
            double nearest = targets.Min(b => (positions[b] - cue).LengthXY - (2 * _r));
            int ci = shot.IndexOf(Cue);
            double travelled = ci >= 0 ? (shot.BallsAfter[ci].Position - cue).LengthXY : 0;
            return travelled >= nearest;
        }

        // The incoming player cannot strike both extremities of any ball on (their ball on: nextOn).
        private bool Snookered(BallLayout table, string ballOn)
        {
            if (table.PositionOf(Cue) is not { } cue)
            {
                return false;
            }
            // The balls on where they lie: snookered when there is one and none is in full view.
            bool any = false;
            foreach (var (id, position) in table)
            {
                if (id != Cue && IsOn(ballOn, id))
                {
                    if (Sightlines.BothSides(cue, position, Obstacles(table, id), _r))
                    {
                        return false;
                    }
                    any = true;
                }
            }
            return any;
        }

        // Every ball but the cue ball and the target, in one list reused for each sightline: a
        // caller reads it before it asks for the next.
        private List<Vec3> Obstacles(BallLayout table, BallId target)
        {
            _obstacles.Clear();
            foreach (var (id, position) in table)
            {
                if (id != Cue && id != target)
                {
                    _obstacles.Add(position);
                }
            }
            return _obstacles;
        }

        // The cue ball left the bed before its first contact and passed over a ball lying on its
        // straight line of flight short of the ball it struck.
        private bool JumpedOver(BallLayout positions, BallId struck)
        {
            var events = shot.Events;
            int contact = shot.FirstContactIndex;
            bool airborne = false;
            for (int i = 0; i < events.Length && i < contact; i++)
            {
                airborne |= events[i].Kind == EventKind.BallAirborne && events[i].A == Cue;
            }
            if (!airborne || shot.Shot is not { } strike || positions.PositionOf(Cue) is not { } cue || positions.PositionOf(struck) is not { } target)
            {
                return false;
            }
            double a = strike.AimDeg * Math.PI / 180;
            var u = new Vec3(DeterministicMath.Cos(a), DeterministicMath.Sin(a), 0);
            double reach = Vec3.Dot(target - cue, u);
            foreach (var (id, p) in positions)
            {
                if (id == Cue || id == struck)
                {
                    continue;
                }
                var d = p - cue;
                double along = Vec3.Dot(d, u);
                double across = Math.Abs((d.X * u.Y) - (d.Y * u.X));
                if (along > 0 && along < reach && across < 2 * _r)
                {
                    return true;
                }
            }
            return false;
        }
    }
}

/// <summary>
/// Straight lines from the cue ball to a ball (rules.md "Snooker"): whether the cue ball, moving in
/// a straight line, can strike some part of a target, or both its extremities (the thinnest
/// contacts on either side), with no other ball in the way. Only balls obstruct (ours: the
/// cushions' noses at the pockets are left out).
/// </summary>
public static class Sightlines
{
    // Offsets across the line of centres, as fractions of 2R, tried for "some part".
    private const int PartSamples = 33;

    // The thinnest contact tried as an extremity, a fraction of 2R.
    private const double Extremity = 1 - 1e-6;

    /// <summary>True when a straight line of the cue ball from <paramref name="cue"/> strikes both extremities of <paramref name="target"/> past <paramref name="obstacles"/>.</summary>
    public static bool BothSides(Vec3 cue, Vec3 target, IReadOnlyList<Vec3> obstacles, double radius) =>
        Clear(cue, target, +Extremity, obstacles, radius) && Clear(cue, target, -Extremity, obstacles, radius);

    /// <summary>True when some straight line of the cue ball from <paramref name="cue"/> strikes <paramref name="target"/> past <paramref name="obstacles"/>.</summary>
    public static bool AnyPart(Vec3 cue, Vec3 target, IReadOnlyList<Vec3> obstacles, double radius)
    {
        // The full-ball line first, then outwards on alternate sides: the answer is the same in any
        // order, and an open ball is seen at the first line.
        const int Middle = (PartSamples - 1) / 2;
        for (int j = 0; j < PartSamples; j++)
        {
            int k = Middle + ((j & 1) == 0 ? j / 2 : -((j + 1) / 2));
            double f = Extremity * ((2.0 * k / (PartSamples - 1)) - 1);
            if (Clear(cue, target, f, obstacles, radius))
            {
                return true;
            }
        }
        return false;
    }

    // The cue ball's centre runs from the cue to where it touches the target with the target's
    // centre f * 2R to the side of its line; clear when no obstacle comes within 2R of that segment.
    private static bool Clear(Vec3 cue, Vec3 target, double f, IReadOnlyList<Vec3> obstacles, double radius)
    {
        var d = (target - cue) with { Z = 0 };
        double length = d.LengthXY;
        double contact = 2 * radius;
        double s = f * contact;
        if (length <= contact)
        {
            return true;
        }
        var along = d / length;
        var side = new Vec3(-along.Y, along.X, 0);
        // The direction whose line passes s to the side of the target's centre.
        double sin = s / length, cos = Math.Sqrt(1 - (sin * sin));
        var u = (along * cos) - (side * sin);
        double travel = (length * cos) - Math.Sqrt((contact * contact) - (s * s));
        var end = cue + (u * travel);
        for (int i = 0; i < obstacles.Count; i++)
        {
            if (DistanceToSegment(obstacles[i], cue, end) < contact - 1e-9)
            {
                return false;
            }
        }
        return true;
    }

    private static double DistanceToSegment(Vec3 p, Vec3 a, Vec3 b)
    {
        var ab = (b - a) with { Z = 0 };
        var ap = (p - a) with { Z = 0 };
        double t = Math.Clamp(Vec3.Dot(ap, ab) / Math.Max(Vec3.Dot(ab, ab), 1e-18), 0, 1);
        return (ap - (ab * t)).LengthXY;
    }
}
