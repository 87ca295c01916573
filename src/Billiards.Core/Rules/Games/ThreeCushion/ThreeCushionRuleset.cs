using System.Globalization;
using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// Three-cushion carom (rules.md "Three-cushion carom", the UMB's rules): the white, the yellow
/// and the red on the pocketless match table, each player striking their own cue ball; a point
/// when the cue ball meets both object balls with three cushion contacts before the second; a
/// race to a target with the equalizing inning; innings, the average and the highest run on the
/// score sheet.
/// </summary>
public sealed class ThreeCushionRuleset : Ruleset
{
    /// <summary>The default target of a game (points).</summary>
    public const int Target40 = 40;

    /// <summary>The game's name in files.</summary>
    public static GameRules ThreeCushion { get; } = new("three-cushion");

    /// <summary>The default cue balls: the white for player 0, the yellow for player 1.</summary>
    public static PerPlayer<BallId> DefaultCueBalls { get; } = new(BallSet.White, BallSet.Yellow);

    /// <inheritdoc />
    public override GameRules Game => ThreeCushion;

    /// <inheritdoc />
    public override string ShortName => "3-cushion";

    /// <inheritdoc />
    public override string Title => "three-cushion carom";

    /// <inheritdoc />
    public override BallSet BallSet => BallSet.Carom;

    /// <inheritdoc />
    public override IReadOnlyList<BallId> Balls => BallSet.Ids;

    /// <inheritdoc />
    public override string TablePreset => CaromTable.Preset;

    /// <summary>No ball in hand ever: the balls are spotted.</summary>
    public override BallInHand BreakBallInHand => BallInHand.None;

    /// <inheritdoc />
    public override bool CallsShots => false;

    /// <inheritdoc />
    public override bool HasThreeFouls => false;

    /// <inheritdoc />
    public override bool PowerBreak => false;

    /// <inheritdoc />
    public override bool HasScore => true;

    /// <inheritdoc />
    public override bool HasInnings => true;

    /// <inheritdoc />
    public override int DefaultTarget => Target40;

    /// <summary>The cue balls, innings, equalizing, breaker and run of a game's start.</summary>
    public override GameStatePart? StartPart { get; } = new ThreeCushionPart();

    /// <inheritdoc />
    public override IReadOnlyList<string> PartFields => ThreeCushionPart.Fields;

    /// <inheritdoc />
    public override GameStatePart? ReadPart(GameBlockFields block) => ThreeCushionPart.Read(block, BallSet);

    /// <inheritdoc />
    public override void WritePart(Utf8JsonWriter writer, GameState state, GameBlockSlot slot) => ThreeCushionPart.Of(state).Write(writer, slot, BallSet);

    /// <summary>The incoming ball frozen to a ball: accept, or spot-break.</summary>
    public override IReadOnlyList<(RefereeOption Option, string Word)> OptionWords { get; } =
        [(RefereeOption.Accept, "accept"), (RefereeOption.SpotBreak, "spot-break")];

    /// <summary>The breaker shoots first and is the breaker of the equalizing inning.</summary>
    public override GameState BrokenBy(GameState start, int breaker) =>
        base.BrokenBy(start, breaker) with { Part = ThreeCushionPart.Of(start) with { Breaker = breaker } };

    /// <summary>The ruling's point, cushions, score, innings, average and run.</summary>
    public override void WriteRulingFields(Utf8JsonWriter writer, Ruling ruling)
    {
        ArgumentNullException.ThrowIfNull(writer);
        ArgumentNullException.ThrowIfNull(ruling);
        var part = ruling.PartOf<ThreeCushionRulingPart>() ?? new ThreeCushionRulingPart();
        writer.WriteBoolean("point", part.Point);
        writer.WriteNumber("cushions", part.Cushions);
        GameBlockWriter.WritePair(writer, "score", ruling.Score);
        GameBlockWriter.WritePair(writer, "innings", part.Innings);
        writer.WriteStartArray("average");
        writer.WriteNumberValue(AverageValue(ruling.Score.First, part.Innings.First));
        writer.WriteNumberValue(AverageValue(ruling.Score.Second, part.Innings.Second));
        writer.WriteEndArray();
        writer.WriteNumber("run", part.Run);
    }

    /// <inheritdoc />
    public override string BreakUnit => "points";

    /// <summary>The player's cue ball: the game block's <c>cue_balls</c>, white and yellow by default.</summary>
    public override BallId CueBall(GameState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        return CueBallOf(state, state.Shooter);
    }

    /// <summary>Player <paramref name="player"/>'s cue ball in <paramref name="state"/>.</summary>
    public static BallId CueBallOf(GameState state, int player)
    {
        ArgumentNullException.ThrowIfNull(state);
        return (ThreeCushionPart.Of(state).CueBalls ?? DefaultCueBalls)[player];
    }

    /// <summary>The break with the white as the breaker's ball.</summary>
    public override IReadOnlyList<(BallId Id, Vec3 Position)> Rack(TableSpec table, double ballRadius, int seed) =>
        Initializer.CaromBreak(table, ballRadius, BallSet.White);

    /// <summary>The break with the shooter's ball beside the head spot.</summary>
    public override IReadOnlyList<(BallId Id, Vec3 Position)> Rack(GameState start, TableSpec table, double ballRadius, int seed) =>
        Initializer.CaromBreak(table, ballRadius, CueBall(start));

    /// <inheritdoc />
    public override Vec3 CueStart(TableSpec table, double ballRadius) => CaromTable.HeadSpot(table, ballRadius);

    /// <inheritdoc />
    public override IReferee Referee(TableSpec table, double ballRadius) => new ThreeCushionReferee(table, ballRadius);

    /// <summary>Both object balls (on the break the red, which must be met first).</summary>
    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        var on = objectBalls.ToList();
        return state.Shot == 0 ? [.. on.Where(b => b == BallSet.Red)] : Ordered(on);
    }

    /// <summary>A point is one; anything else adds nothing to the run.</summary>
    public override int BreakValue(Ruling ruling)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        return ruling.PartOf<ThreeCushionRulingPart>() is { Point: true } ? 1 : 0;
    }

    /// <summary>20 shots a point of the target and 200 more: a race to 40 at a general average of 0.3 takes some 270 shots.</summary>
    public override int MaxShots(GameState start)
    {
        ArgumentNullException.ThrowIfNull(start);
        return 20 * start.Target + 200;
    }

    /// <summary>The innings and the average, "inn 9  avg 1.333" (the card's score row shows the score, the target and the run).</summary>
    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        int innings = ThreeCushionPart.Of(state).Innings[player];
        return new(string.Create(CultureInfo.InvariantCulture,
            $"inn {innings}  avg {Average(state.Score[player], innings)}"), []);
    }

    /// <summary>The average as the score sheet writes it: points / innings to three decimals ("0.000" before an inning).</summary>
    public static string Average(int points, int innings) =>
        (innings == 0 ? 0.0 : Math.Round((double)points / innings, 3, MidpointRounding.AwayFromZero)).ToString("0.000", CultureInfo.InvariantCulture);

    /// <summary>The average as a number, rounded to three decimals (0 before an inning).</summary>
    public static double AverageValue(int points, int innings) =>
        innings == 0 ? 0 : Math.Round((double)points / innings, 3, MidpointRounding.AwayFromZero);

    /// <summary>
    /// Spots carom's balls between shots: the whole set (a frozen ball's spotting) as for the
    /// break, the first named ball the breaker's; a single ball as after it left the table, the
    /// red on the foot spot and a cue ball on the head spot, each on the other's spot when its own
    /// is taken and on the centre spot when both are (ours: USBA's).
    /// </summary>
    public override void SpotBalls(Physics.Simulation simulation, IReadOnlyList<BallId> balls)
    {
        ArgumentNullException.ThrowIfNull(simulation);
        ArgumentNullException.ThrowIfNull(balls);
        var table = simulation.Table;
        double r = simulation.BallRadius;
        if (balls.Count == BallSet.Count)
        {
            foreach (var (id, position) in Initializer.CaromBreak(table, r, balls[0]))
            {
                simulation.PlaceBall(id, position);
            }
            return;
        }
        foreach (var ball in balls)
        {
            var foot = CaromTable.FootSpot(table, r);
            var head = CaromTable.HeadSpot(table, r);
            Vec3[] spots = ball == BallSet.Red ? [foot, head, CaromTable.CentreSpot(r)] : [head, foot, CaromTable.CentreSpot(r)];
            simulation.PlaceBall(ball, spots.FirstOrDefault(s => IsFree(simulation, ball, s), spots[^1]));
        }
    }

    private static bool IsFree(Physics.Simulation simulation, BallId ball, Vec3 spot)
    {
        var balls = simulation.Balls;
        double d = 2 * simulation.BallRadius;
        for (int j = 0; j < balls.Length; j++)
        {
            if (simulation.Ids[j] != ball && !balls[j].IsOutOfPlay && (balls[j].Position - spot).LengthSquared < d * d)
            {
                return false;
            }
        }
        return true;
    }

    /// <summary>A frozen ball's spotting: the whole set as for the break, the incoming shooter's ball first.</summary>
    protected override OptionOutcome ChooseOther(Ruling ruling, RefereeOption option, GameState next)
    {
        ArgumentNullException.ThrowIfNull(ruling);
        ArgumentNullException.ThrowIfNull(next);
        if (option != RefereeOption.SpotBreak)
        {
            return base.ChooseOther(ruling, option, next);
        }
        var own = CueBall(next);
        return new OptionOutcome(next, false, [own, .. Balls.Where(b => b != own && b != BallSet.Red), BallSet.Red]);
    }
}
