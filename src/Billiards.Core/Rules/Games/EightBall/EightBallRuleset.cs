using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>8-ball (rules.md): solids and stripes, the 8 last, every shot after the break called.</summary>
public sealed class EightBallRuleset : Ruleset
{
    /// <summary>The 8 ball.</summary>
    public static BallId Eight { get; } = new(8);

    /// <inheritdoc />
    public override GameRules Game => GameRules.EightBall;

    /// <inheritdoc />
    public override string ShortName => "8-ball";

    /// <inheritdoc />
    public override IReadOnlyList<BallId> Balls => BallSet.Ids;

    /// <inheritdoc />
    protected override RackGame RackShape => RackGame.EightBall;

    /// <inheritdoc />
    public override bool HasGroups => true;

    /// <summary>No: 8-ball has no three-foul rule.</summary>
    public override bool HasThreeFouls => false;

    /// <summary>The groups, open at the start.</summary>
    public override GameStatePart? StartPart { get; } = new EightBallPart();

    /// <inheritdoc />
    public override IReadOnlyList<string> PartFields => EightBallPart.Fields;

    /// <inheritdoc />
    public override GameStatePart? ReadPart(GameBlockFields block) => EightBallPart.Read(block);

    /// <inheritdoc />
    public override void WritePart(Utf8JsonWriter writer, GameState state, GameBlockSlot slot) => EightBallPart.Of(state).Write(writer, slot);

    /// <summary>The chooser breaks a new rack on an open table.</summary>
    protected override GameState Rerack(GameState next) => base.Rerack(next) with { Part = StartPart };

    /// <summary>After a foul on the break: accept, rerack; after the 8 on the break: rerack, spot-eight.</summary>
    public override IReadOnlyList<(RefereeOption Option, string Word)> OptionWords { get; } =
        [(RefereeOption.Accept, "accept"), (RefereeOption.Rerack, "rerack"), (RefereeOption.SpotEight, "spot-eight")];

    /// <inheritdoc />
    public override IReferee Referee(TableSpec table, double ballRadius) => new EightBallReferee(table, ballRadius);

    /// <summary>The shooter's group; any ball but the 8 on an open table; the 8 once the group is cleared.</summary>
    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        var balls = Ordered(objectBalls);
        if (EightBallPart.Of(state).Groups is not { } groups)
        {
            var open = balls.Where(b => b != Eight).ToList();
            return open.Count > 0 ? open : balls;
        }
        var own = balls.Where(b => groups[state.Shooter].Contains(b)).ToList();
        return own.Count > 0 ? own : balls.Where(b => b == Eight).ToList();
    }

    /// <summary>The legal targets and the 8.</summary>
    public override IReadOnlyList<BallId> StillToPot(GameState state, IEnumerable<BallId> objectBalls)
    {
        var list = objectBalls.ToList();
        var targets = LegalTargets(state, list);
        return !targets.Contains(Eight) && list.Contains(Eight) ? [.. targets, Eight] : targets;
    }

    /// <summary>Only the shooter's own balls (any but the 8 while the table is open); never the 8 by itself.</summary>
    public override bool MayCall(GameState state, BallId ball)
    {
        ArgumentNullException.ThrowIfNull(state);
        if (ball == Eight)
        {
            return false;
        }
        return EightBallPart.Of(state).Groups is not { } groups || groups[state.Shooter].Contains(ball);
    }

    /// <inheritdoc />
    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls)
    {
        ArgumentNullException.ThrowIfNull(state);
        if (EightBallPart.Of(state).Groups is not { } groups)
        {
            return new HudTarget("open table", []);
        }
        var group = groups[player];
        var need = Ordered(objectBalls.Where(b => group.Contains(b)));
        return need.Count == 0
            ? new HudTarget($"{group.ToName()}, on the 8", [Eight])
            : new HudTarget($"{group.ToName()}: {string.Join(" ", need)}", need);
    }
}
