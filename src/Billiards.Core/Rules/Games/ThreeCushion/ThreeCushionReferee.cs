using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// Three-cushion's referee and score sheet (rules.md "Three-cushion carom"): reads the struck
/// ball's contacts from the shot's events and keeps the score, the innings and the run in the
/// game state. Pure: the same state and record give the same ruling.
/// </summary>
/// <remarks>
/// An inning is one visit: the state's <see cref="ThreeCushionPart.Innings"/> counts each player's visits
/// begun, the one at the table included (a state before the break that counts none has begun the
/// breaker's first). A point keeps the shooter at the table; no point, or a foul, hands it over
/// and begins the other player's next inning.
/// </remarks>
public sealed class ThreeCushionReferee(TableSpec table, double ballRadius) : IReferee
{
    /// <summary>How near two balls' surfaces may be and still count as frozen (m).</summary>
    public const double FrozenGap = 1e-4;

    /// <inheritdoc />
    public GameRules Rules => ThreeCushionRuleset.ThreeCushion;

    /// <inheritdoc />
    public TableSpec Table { get; } = table;

    /// <inheritdoc />
    public double BallRadius { get; } = ballRadius;

    /// <summary>What the shooter's cue ball did on a shot, read from its events.</summary>
    /// <param name="FirstBall">The first ball it met, or null.</param>
    /// <param name="BothBalls">It met both object balls.</param>
    /// <param name="Cushions">Its cushion contacts before it met the second object ball, or in all when it met fewer than two.</param>
    public readonly record struct Contacts(BallId? FirstBall, bool BothBalls, int Cushions)
    {
        /// <summary>A point's contacts: both balls, three cushions or more before the second.</summary>
        public bool IsPoint => BothBalls && Cushions >= 3;
    }

    /// <summary>
    /// The cue ball's contacts in <paramref name="events"/>: every cushion event of
    /// <paramref name="cue"/> counts until it meets a second, different ball; an object ball's
    /// cushions and a second contact with the same ball (a kiss) do not.
    /// </summary>
    public static Contacts Read(ReadOnlySpan<SimEvent> events, BallId cue)
    {
        BallId? first = null;
        int cushions = 0;
        foreach (ref readonly var e in events)
        {
            if (e.Kind == EventKind.BallCushion && e.A == cue)
            {
                cushions++;
            }
            else if (e.Kind == EventKind.BallBall && (e.A == cue || e.B == cue))
            {
                var other = e.A == cue ? e.B : e.A;
                if (first is null)
                {
                    first = other;
                }
                else if (other != first)
                {
                    return new Contacts(first, true, cushions);
                }
            }
        }
        return new Contacts(first, false, cushions);
    }

    /// <inheritdoc />
    public Ruling Judge(GameState before, ShotRecord shot)
    {
        ArgumentNullException.ThrowIfNull(before);
        ArgumentNullException.ThrowIfNull(shot);
        if (before.Rules != Rules)
        {
            throw new ArgumentException($"a three-cushion referee cannot judge {before.Rules.ToName()}", nameof(before));
        }
        int shooter = before.Shooter, other = before.Incoming;
        var cue = ThreeCushionRuleset.CueBallOf(before, shooter);
        var struck = shot.Events.Length > 0 && shot.Events[0].Kind == EventKind.CueStrike ? shot.Events[0].A : cue;
        var contacts = Read(shot.Events, struck);
        var fouls = new List<Foul>();
        var offTable = new List<BallId>();
        foreach (ref readonly var e in shot.Events)
        {
            if (e.Kind == EventKind.BallOffTable && !offTable.Contains(e.A))
            {
                offTable.Add(e.A);
            }
        }
        if (struck != cue)
        {
            fouls.Add(Foul.WrongCueBall);
        }
        if (before.Shot == 0 && contacts.FirstBall != BallSet.Red)
        {
            fouls.Add(Foul.RedNotFirstOnBreak);
        }
        if (offTable.Count > 0)
        {
            fouls.Add(Foul.BallOffTable);
        }
        bool point = fouls.Count == 0 && contacts.IsPoint;
        var part = ThreeCushionPart.Of(before);
        var innings = part.Innings.With(shooter, Math.Max(1, part.Innings[shooter]));
        var score = point ? before.Score.With(shooter, before.Score[shooter] + 1) : before.Score;
        int run = part.Run + (point ? 1 : 0);
        string name = before.ShooterName;
        var spot = BallSet.Carom.Ids.Where(offTable.Contains).ToList();
        string what = Describe(fouls, contacts, point, struck, cue);

        bool breakerDone = score[part.Breaker] >= before.Target;
        bool equalizing = part.Equalizing && shooter == part.Breaker && innings[other] < innings[shooter];
        GameState Over() => new GameState(Rules)
        {
            Players = before.Players, Target = before.Target, Shooter = part.Breaker,
            Part = new ThreeCushionPart { Equalizing = part.Equalizing, CueBalls = part.CueBalls, Breaker = part.Breaker },
        };
        Ruling Make(bool keep, bool over, int? winner, string message, GameState next) =>
            new(fouls.Count == 0, fouls, [], keep, BallInHand.None, spot, keep || over ? [] : FrozenOptions(shot, next), over, winner, message, next)
            {
                Score = score,
                Part = new ThreeCushionRulingPart { Point = point, Cushions = contacts.Cushions, Innings = innings, Run = run },
            };

        if (point && score[shooter] >= before.Target)
        {
            if (equalizing)
            {
                var handed = Handed();
                return Make(false, false, null, Invariant($"{name} {what}: {score[shooter]} in {innings[shooter]} innings. {before.IncomingName} has the equalizing inning."), handed);
            }
            bool draw = shooter != part.Breaker && score[part.Breaker] >= before.Target;
            return Make(false, true, draw ? null : shooter, draw
                ? Invariant($"{name} {what} and equalizes: a draw, {score[0]}-{score[1]}.")
                : Invariant($"{name} {what} and wins {score[shooter]}-{score[other]} in {innings[shooter]} innings (average {ThreeCushionRuleset.Average(score[shooter], innings[shooter])})."), Over());
        }
        if (point)
        {
            var next = before with { Shot = before.Shot + 1, Score = score, Part = part with { Innings = innings, Run = run }, Call = null, Placement = null, BallInHand = BallInHand.None };
            return Make(true, false, null, Invariant($"{name} {what}: run {run}, {score[shooter]} of {before.Target}."), next);
        }
        if (shooter != part.Breaker && breakerDone)
        {
            return Make(false, true, part.Breaker, Invariant($"{name} {what}: {before.IncomingName} wins {score[part.Breaker]}-{score[shooter]}."), Over());
        }
        return Make(false, false, null, Invariant($"{name} {what}. {before.IncomingName} to play."), Handed());

        GameState Handed() => before with
        {
            Shooter = other, Shot = before.Shot + 1, Score = score, Part = part with { Innings = innings.With(other, innings[other] + 1), Run = 0 },
            Call = null, Placement = null, BallInHand = BallInHand.None,
        };
    }

    // The incoming shooter's ball frozen to a ball: they may play away (accept) or have the balls spotted as for the break.
    private IReadOnlyList<RefereeOption> FrozenOptions(ShotRecord shot, GameState next)
    {
        var own = ThreeCushionRuleset.CueBallOf(next, next.Shooter);
        int i = shot.IndexOf(own);
        if (i < 0 || shot.BallsAfter[i].IsOutOfPlay)
        {
            return [];
        }
        var p = shot.BallsAfter[i].Position;
        double touch = 2 * BallRadius + FrozenGap;
        for (int j = 0; j < shot.BallsAfter.Length; j++)
        {
            if (j != i && !shot.BallsAfter[j].IsOutOfPlay && (shot.BallsAfter[j].Position - p).LengthSquared <= touch * touch)
            {
                return [RefereeOption.Accept, RefereeOption.SpotBreak];
            }
        }
        return [];
    }

    private static string Describe(List<Foul> fouls, Contacts contacts, bool point, BallId struck, BallId cue)
    {
        if (fouls.Count > 0)
        {
            return fouls[0] switch
            {
                Foul.WrongCueBall => $"fouls: struck the {struck}, not the {cue}",
                Foul.RedNotFirstOnBreak => "fouls: the break did not meet the red first",
                _ => "fouls: a ball left the table",
            };
        }
        if (point)
        {
            return Invariant($"scores with {contacts.Cushions} cushions");
        }
        return contacts.FirstBall is null ? "misses both balls"
            : !contacts.BothBalls ? "meets only one ball"
            : Invariant($"meets both balls with {contacts.Cushions} cushion{(contacts.Cushions == 1 ? "" : "s")} before the second: no point");
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
