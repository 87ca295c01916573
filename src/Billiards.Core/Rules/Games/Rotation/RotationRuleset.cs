using Billiards.Core.Balls;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>The rotation games (9-ball, 10-ball): the lowest ball first, a push-out after the break.</summary>
public abstract class RotationRuleset : Ruleset
{
    /// <summary>The ball that wins the game (the highest of the rack).</summary>
    public abstract BallId Money { get; }

    /// <inheritdoc />
    public override IReadOnlyList<BallId> Balls => [.. BallSet.Ids.Take(Money.Value + 1)];

    /// <inheritdoc />
    public override bool HasPushOut => true;

    /// <summary>After a push-out: shoot, or pass-back.</summary>
    public override IReadOnlyList<(RefereeOption Option, string Word)> OptionWords { get; } =
        [(RefereeOption.Shoot, "shoot"), (RefereeOption.PassBack, "pass-back")];

    /// <inheritdoc />
    public override IReferee Referee(TableSpec table, double ballRadius) => new RotationReferee(this, table, ballRadius);

    /// <summary>The lowest-numbered ball on the table.</summary>
    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls)
    {
        var balls = Ordered(objectBalls);
        return balls.Count > 0 ? [balls[0]] : [];
    }

    /// <inheritdoc />
    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls)
    {
        var lowest = LegalTargets(state, objectBalls);
        return lowest.Count == 0 ? new HudTarget("-", []) : new HudTarget($"on the {lowest[0]}", lowest);
    }
}

/// <summary>9-ball (rules.md): the 9 wins whenever it drops on a legal shot; no call.</summary>
public sealed class NineBallRuleset : RotationRuleset
{
    /// <inheritdoc />
    public override GameRules Game => GameRules.NineBall;

    /// <inheritdoc />
    public override string ShortName => "9-ball";

    /// <inheritdoc />
    public override BallId Money => new(9);

    /// <inheritdoc />
    protected override RackGame RackShape => RackGame.NineBall;

    /// <summary>No: 9-ball is not a called game.</summary>
    public override bool CallsShots => false;
}

/// <summary>10-ball (rules.md): 9-ball's rules with called shots and the 10.</summary>
public sealed class TenBallRuleset : RotationRuleset
{
    /// <inheritdoc />
    public override GameRules Game => GameRules.TenBall;

    /// <inheritdoc />
    public override string ShortName => "10-ball";

    /// <inheritdoc />
    public override BallId Money => new(10);

    /// <inheritdoc />
    protected override RackGame RackShape => RackGame.TenBall;
}
