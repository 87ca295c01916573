using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>14.1 continuous (rules.md): any ball, every shot after the break called, reracks of fourteen.</summary>
public sealed class StraightPoolRuleset : Ruleset
{
    /// <inheritdoc />
    public override GameRules Game => GameRules.StraightPool;

    /// <inheritdoc />
    public override string ShortName => "14.1";

    /// <inheritdoc />
    public override string Title => "14.1 straight pool";

    /// <inheritdoc />
    public override IReadOnlyList<BallId> Balls => BallSet.Ids;

    /// <inheritdoc />
    protected override RackGame RackShape => RackGame.StraightPool;

    /// <inheritdoc />
    public override bool HasScore => true;

    /// <inheritdoc />
    public override IReferee Referee(TableSpec table, double ballRadius) => new StraightPoolReferee(table, ballRadius);

    /// <summary>Any object ball.</summary>
    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls) => Ordered(objectBalls);

    /// <summary>Ten shots per point of the target, at least 400.</summary>
    public override int MaxShots(GameState start)
    {
        ArgumentNullException.ThrowIfNull(start);
        return Math.Max(base.MaxShots(start), 10 * start.Target);
    }

    /// <summary>After a foul on the opening break: accept or rerack.</summary>
    public override IReadOnlyList<(RefereeOption Option, string Word)> OptionWords { get; } =
        [(RefereeOption.Accept, "accept"), (RefereeOption.Rerack, "rerack")];

    /// <summary>A rerack after a foul is broken by the offender: the player who is not choosing.</summary>
    protected override GameState Rerack(GameState next) => next with { Shooter = next.Incoming, Shot = 0, BallInHand = BallInHand.None };

    /// <summary>
    /// Racks the pocketed balls with the apex empty. The WPA's placement rules, simplified (ours): a
    /// fifteenth ball in the rack's way goes to the head spot (the centre spot if the cue ball is
    /// there); a cue ball in the way is taken up, and the shooter has ball in hand behind the head string.
    /// </summary>
    public override (BallLayout Balls, BallInHand? BallInHand) RerackDuringPlay(BallLayout table, IReadOnlyList<BallId> balls, TableSpec tableSpec, double ballRadius, int seed)
    {
        ArgumentNullException.ThrowIfNull(table);
        double r = ballRadius;
        var rack = Initializer.Rerack(balls, tableSpec, r, seed);
        bool InTheWay(Vec3 p) => rack.Any(b => (b.Position - p).Length < 2 * r) || (Initializer.FootSpot(tableSpec, r) - p).Length < 2 * r;
        BallInHand? hand = null;
        var cueBall = BallSet.CueBalls[0]; // 14.1's one cue ball
        if (table.PositionOf(cueBall) is { } cue && InTheWay(cue))
        {
            table = table.Without(cueBall);
            hand = BallInHand.Kitchen;
        }
        foreach (var (id, _) in table.Where(b => b.Id != cueBall && InTheWay(b.Position)).OrderBy(b => b.Id.Value).ToList())
        {
            var head = Initializer.HeadSpot(tableSpec, r);
            bool headTaken = table.PositionOf(cueBall) is { } c && (c - head).Length < 2 * r;
            table = table.With(id, headTaken ? new Vec3(0, 0, r) : head);
        }
        foreach (var (id, p) in rack)
        {
            table = table.With(id, p);
        }
        return (table, hand);
    }

    /// <inheritdoc />
    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(objectBalls);
        return new HudTarget($"{objectBalls.Count} balls on the table", []);
    }
}
