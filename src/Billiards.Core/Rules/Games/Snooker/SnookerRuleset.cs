using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Scenes;
using Billiards.Core.Mathematics;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// Snooker (rules.md "Snooker", the WPBSA's rules): 15 reds and six colours on the 12 ft table, the
/// ball on red and colour in turn while reds remain and then the colours in order, nominated
/// colours and free balls, points for pots and for the opponent's fouls, re-spotted colours,
/// <c>play</c> / <c>put-back</c> after a foul and <c>replace</c> after a miss.
/// </summary>
public sealed class SnookerRuleset : Ruleset
{
    /// <summary>The ball on while reds remain: a red.</summary>
    public const string Red = "red";

    /// <summary>The ball on after a potted red: a colour, which the striker nominates.</summary>
    public const string Colour = "colour";

    /// <summary>The smallest penalty of a foul (points).</summary>
    public const int MinimumPenalty = 4;

    /// <inheritdoc />
    public override GameRules Game => GameRules.Snooker;

    /// <inheritdoc />
    public override string ShortName => "snooker";

    /// <inheritdoc />
    public override bool HasBallOn => true;

    /// <inheritdoc />
    public override BallSet BallSet => BallSet.Snooker;

    /// <inheritdoc />
    public override IReadOnlyList<BallId> Balls => BallSet.Ids;

    /// <inheritdoc />
    protected override RackGame RackShape => RackGame.Snooker;

    /// <inheritdoc />
    public override string TablePreset => SnookerTable.Preset;

    /// <summary>The break-off is played from in hand in the D.</summary>
    public override BallInHand BreakBallInHand => BallInHand.D;

    /// <summary>No pocket is ever called; a colour or a free ball is nominated (<see cref="MayCall"/>).</summary>
    public override bool CallsShots => false;

    /// <summary>No three-foul rule (snooker's is the three-miss rule).</summary>
    public override bool HasThreeFouls => false;

    /// <inheritdoc />
    public override bool HasScore => true;


    /// <inheritdoc />
    public override IReferee Referee(TableSpec table, double ballRadius) => new SnookerReferee(table, ballRadius);

    /// <summary>True for a red.</summary>
    public static bool IsRed(BallId ball) => ball.Value >= BallSet.FirstRed && ball.Value < BallSet.FirstRed + BallSet.Reds;

    /// <summary>True for one of the six colours.</summary>
    public static bool IsColour(BallId ball) => ball.Value >= BallSet.FirstRed + BallSet.Reds && ball.Value < BallSet.FirstRed + BallSet.Reds + 6;

    /// <summary>A ball's points: red 1, yellow 2 .. black 7 (0 for the cue ball).</summary>
    public static int ValueOf(BallId ball) => IsRed(ball) ? 1 : IsColour(ball) ? ball.Value - (BallSet.FirstRed + BallSet.Reds) + 2 : 0;

    /// <summary>The ball on of <paramref name="state"/>: its <see cref="SnookerPart.BallOn"/>, "red" at the start of a frame.</summary>
    public static string BallOnOf(GameState state) => SnookerPart.Of(state).BallOn ?? Red;

    /// <summary>The ball on, a free ball and the misses in a row, at the start of a frame.</summary>
    public override GameStatePart? StartPart { get; } = new SnookerPart();

    /// <inheritdoc />
    public override IReadOnlyList<string> PartFields => SnookerPart.Fields;

    /// <inheritdoc />
    public override GameStatePart? ReadPart(GameBlockFields block) => SnookerPart.Read(block);

    /// <summary>A nomination of a ball, <c>{"ball": "blue"}</c>, with no pocket.</summary>
    public override Call ReadCall(JsonElement call, GameBlockFields block) => SnookerPart.ReadNomination(call, block);

    /// <inheritdoc />
    public override void WritePart(Utf8JsonWriter writer, GameState state, GameBlockSlot slot) => SnookerPart.Of(state).Write(writer, slot);

    /// <summary>The ruling's points, penalty, foul_and_miss and free_ball.</summary>
    public override void WriteRulingFields(Utf8JsonWriter writer, Ruling ruling)
    {
        ArgumentNullException.ThrowIfNull(writer);
        ArgumentNullException.ThrowIfNull(ruling);
        writer.WriteNumber("points", ruling.Points);
        writer.WriteNumber("penalty", ruling.Penalty);
        var part = ruling.PartOf<SnookerRulingPart>();
        writer.WriteBoolean("foul_and_miss", part?.FoulAndMiss ?? false);
        writer.WriteBoolean("free_ball", part?.FreeBall ?? false);
    }

    /// <summary>After a foul: play, put-back, and after a foul and a miss replace.</summary>
    public override IReadOnlyList<(RefereeOption Option, string Word)> OptionWords { get; } =
        [(RefereeOption.Play, "play"), (RefereeOption.PutBack, "put-back"), (RefereeOption.Replace, "replace")];

    /// <summary>Playing the balls as they lie says so when it is with a free ball.</summary>
    public override string ChoiceMessage(RefereeOption option, GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return option == RefereeOption.Play && SnookerPart.Of(state).FreeBall
            ? $"{state.ShooterName} plays the balls as they lie, with a free ball."
            : base.ChoiceMessage(option, state);
    }

    /// <summary>After a foul and a miss, <see cref="RefereeOption.Replace"/>: every ball back where it stood before the shot, the offender to play again.</summary>
    protected override OptionOutcome ChooseOther(Ruling ruling, RefereeOption option, GameState next)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        return option == RefereeOption.Replace
            ? new OptionOutcome(ruling.PartOf<SnookerRulingPart>()?.Replaced ?? throw new ArgumentException("the ruling has no replaced state", nameof(ruling)), false, []) { Replace = true }
            : base.ChooseOther(ruling, option, next);
    }

    /// <summary>The offender plays again from where the balls lie; a free ball was the incoming player's only.</summary>
    protected override GameState PutBack(GameState next) => base.PutBack(next) with { Part = SnookerPart.Of(next) with { FreeBall = false } };

    /// <summary>The ball on at the start of a turn with <paramref name="objectBalls"/> on the table: a red while any remains, else the lowest colour.</summary>
    public static string TurnBallOn(IEnumerable<BallId> objectBalls)
    {
        var balls = objectBalls.ToList();
        if (balls.Exists(IsRed))
        {
            return Red;
        }
        var colours = balls.Where(IsColour).OrderBy(b => b.Value).ToList();
        return colours.Count > 0 ? colours[0].ToString() : BallSet.Colours[^1];
    }

    /// <summary>
    /// The balls the striker may legally strike first: the nominated free ball; the reds; the
    /// nominated colour (any colour before one is nominated); the colour in turn.
    /// </summary>
    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        var on = objectBalls.ToList();
        if (SnookerPart.Of(state).FreeBall && state.Call is { IsNomination: true } free)
        {
            return on.Contains(free.Ball) ? [free.Ball] : [];
        }
        return BallOnOf(state) switch
        {
            Red => Ordered(on.Where(IsRed)),
            Colour when state.Call is { IsNomination: true } c => on.Contains(c.Ball) ? [c.Ball] : [],
            Colour => Ordered(on.Where(IsColour)),
            var name => Ordered(on.Where(b => b.ToString() == name)),
        };
    }

    /// <summary>A colour after a red; with a free ball any object ball; nothing else is nominated.</summary>
    public override bool MayCall(GameState state, BallId ball)
    {
        ArgumentNullException.ThrowIfNull(state);
        return SnookerPart.Of(state).FreeBall ? !BallSet.IsCueBall(ball) : BallOnOf(state) == Colour && IsColour(ball);
    }

    /// <summary>A colour is nominated after a potted red, and any ball with a free ball.</summary>
    public override bool Nominates(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return SnookerPart.Of(state).FreeBall || BallOnOf(state) == Colour;
    }

    /// <summary>The break-off is a safety off the side of the pack, not a power break.</summary>
    public override bool PowerBreak => false;

    /// <summary>Snooker's miss and free ball turn on whether a player is snookered.</summary>
    public override bool HasSnookers => true;

    /// <summary>Snooker's: an open table gives a break; more safeties, sure pots and snookers (<see cref="Ai.PlannerPolicy.Snooker"/>).</summary>
    public override Ai.PlannerPolicy Policy => Ai.PlannerPolicy.Snooker;

    /// <summary>A frame rarely lasts 300 shots; 600 leaves room for long safety exchanges.</summary>
    public override int MaxShots(GameState start) => 600;

    /// <summary>Snooker's break: the points the shot scored for the shooter (<see cref="Ruling.Points"/>; a penalty goes to the opponent and is no part of it).</summary>
    public override int BreakValue(Ruling ruling)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        return ruling.Points;
    }

    /// <inheritdoc />
    public override string BreakUnit => "points";

    /// <inheritdoc />
    public override string BreakWord => "break";

    /// <inheritdoc />
    public override string GameWord => "frame";

    /// <inheritdoc />
    public override string TheGame => "the frame";

    /// <inheritdoc />
    public override int? PointsRemaining(GameState state, IReadOnlyCollection<BallId> objectBalls) =>
        PointsRemaining(BallOnOf(state), objectBalls);

    /// <inheritdoc />
    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        ArgumentNullException.ThrowIfNull(objectBalls);
        if (player != state.Shooter)
        {
            return new HudTarget($"{state.Score[player]}", []);
        }
        string on = BallOnOf(state);
        var balls = LegalTargets(state, objectBalls);
        string text = SnookerPart.Of(state).FreeBall ? "free ball" : on switch
        {
            Red => "on a red",
            Colour => state.Call is { IsNomination: true } c ? $"on the {c.Ball}" : "on a colour",
            var name => $"on the {name}",
        };
        return new HudTarget($"{state.Score[player]}, {text}", balls);
    }

    /// <summary>
    /// The points still on the table for a player whose ball on is <paramref name="ballOn"/>: eight
    /// a red and 27 for the colours while reds remain (7 more when a colour is on after a red); in
    /// the colours phase the values of the colours still on the table.
    /// </summary>
    public static int PointsRemaining(string ballOn, IEnumerable<BallId> objectBalls)
    {
        var balls = objectBalls.ToList();
        int reds = balls.Count(IsRed);
        int colours = balls.Where(IsColour).Sum(ValueOf);
        int extra = ballOn == Colour ? 7 : 0;
        return reds > 0 ? (8 * reds) + 27 + extra : colours + extra;
    }

    /// <summary>True when either player is behind by more than the points remaining (needs snookers).</summary>
    public static bool NeedsSnookers(PerPlayer<int> score, string ballOn, IEnumerable<BallId> objectBalls)
    {
        int remaining = PointsRemaining(ballOn, objectBalls);
        return Math.Abs(score.First - score.Second) > remaining;
    }

    /// <summary>
    /// Re-spots the colours of <paramref name="balls"/> on <paramref name="table"/>, the highest
    /// value first (rules.md): each on its own spot; if that is taken, on the highest-value spot
    /// that is free; if none is, as near its own spot as it fits on the long axis towards the top
    /// cushion, else towards baulk. Reds are never re-spotted. Returns the balls after the spotting.
    /// </summary>
    public static BallLayout Respot(BallLayout table, IEnumerable<BallId> balls, TableSpec tableSpec, double radius)
    {
        ArgumentNullException.ThrowIfNull(table);
        ArgumentNullException.ThrowIfNull(balls);
        foreach (var ball in balls.Where(IsColour).OrderByDescending(b => b.Value))
        {
            table = table.With(ball, RespotPosition(ball, table.Without(ball).Positions, tableSpec, radius));
        }
        return table;
    }

    /// <summary>Where a colour goes when re-spotted among <paramref name="others"/> (m, z = R).</summary>
    public static Vec3 RespotPosition(BallId colour, IReadOnlyList<Vec3> others, TableSpec table, double radius)
    {
        ArgumentNullException.ThrowIfNull(others);
        bool Free(Vec3 p) => others.All(o => !Placement.Overlaps(radius, o, p));
        var own = SnookerTable.Spot(table, colour.ToString(), radius);
        if (Free(own))
        {
            return own;
        }
        foreach (string name in BallSet.Colours.Reverse())
        {
            var spot = SnookerTable.Spot(table, name, radius);
            if (Free(spot))
            {
                return spot;
            }
        }
        var onAxis = others.Where(o => Math.Abs(o.Y) < 2 * radius).ToList();
        double limit = table.HalfLength - radius;
        double x = Placement.FreeOnLongAxis(radius, onAxis, own.X, +1);
        if (x > limit)
        {
            x = Placement.FreeOnLongAxis(radius, onAxis, own.X, -1);
        }
        return new Vec3(x, 0, radius);
    }

    /// <summary>Re-spots the colours among <paramref name="balls"/> on their spots (<see cref="Respot"/>).</summary>
    public override void SpotBalls(Physics.Simulation simulation, IReadOnlyList<BallId> balls)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        ArgumentNullException.ThrowIfNull(balls);
        var before = simulation.InPlay();
        var table = Respot(before, balls, simulation.Table, simulation.BallRadius);
        foreach (var ball in balls.Where(IsColour).OrderByDescending(b => b.Value))
        {
            if (table.PositionOf(ball) is { } spot && before.PositionOf(ball) != spot)
            {
                simulation.PlaceBall(ball, spot);
            }
        }
    }
}
