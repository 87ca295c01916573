using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// 8-ball (rules.md): solids 1-7 and stripes 9-15, an open table until a called ball is legally
/// pocketed after the break, the 8 last into a called pocket. Losing the game on the 8 is reported
/// with the loss codes alongside the shot's fouls.
/// </summary>
internal sealed class EightBallReferee(TableSpec table, double ballRadius) : RefereeBase(GameRules.EightBall, table, ballRadius)
{
    private static readonly BallId Eight = new(8);

    protected override Ruling Rule(GameState before, ShotRecord shot, ShotFacts facts, RulingBuilder ruling)
    {
        if (facts.BadPlacement)
        {
            ruling.Foul(Foul.BadPlacement);
        }
        if (before.Shot == 0)
        {
            Break(before, facts, ruling);
        }
        else
        {
            Shot(before, facts, ruling);
        }
        JumpedBalls(before, facts, ruling);
        ruling.CountFouls();
        // A bad break alone is no ball in hand: the incoming player accepts the table as it lies or reracks.
        if (!ruling.Legal && !ruling.GameOver && !(ruling.Has(Foul.BadBreak) && ruling.FoulCount == 1))
        {
            ruling.BallInHand = BallInHand.Table;
        }
        return ruling.Build();
    }

    // Jumped object balls are spotted; the 8 off the table loses the game (rules.md).
    private static void JumpedBalls(GameState before, ShotFacts facts, RulingBuilder ruling)
    {
        foreach (var ball in facts.OffTable)
        {
            if (ball == Eight)
            {
                ruling.Foul(Foul.EightBallOffTable);
                ruling.Win(before.Incoming, $"{before.IncomingName} wins.");
            }
            else
            {
                ruling.SpotBall(ball);
            }
        }
    }

    private static void Break(GameState before, ShotFacts facts, RulingBuilder ruling)
    {
        if (facts.Scratch)
        {
            ruling.Foul(Foul.CueBallPocketed);
        }
        OffTableFoul(facts, ruling);
        if (facts.Pocketed.Count == 0 && facts.ObjectBallsToCushion < 4)
        {
            ruling.Foul(Foul.BadBreak, "the break pocketed no ball and sent fewer than four object balls to a cushion");
            ruling.Options.AddRange([RefereeOption.Accept, RefereeOption.Rerack]);
        }
        if (facts.PocketOf.ContainsKey(Eight))
        {
            // Neither win nor loss: spot it (the default) or rerack, chosen by whoever shoots next.
            ruling.SpotBall(Eight);
            ruling.Options.AddRange([RefereeOption.SpotEight, RefereeOption.Rerack]);
        }
        ruling.Continue = facts.Pocketed.Count > 0;
        _ = before;
    }

    private static void Shot(GameState before, ShotFacts facts, RulingBuilder ruling)
    {
        var groups = EightBallPart.Of(before).Groups;
        bool open = groups is null;
        BallGroup? own = groups?[before.Shooter];
        bool cleared = own is { } g && !facts.OnTableBefore.Any(n => g.Contains(new BallId(n)));
        CommonFouls(facts, ruling, ball => open
            ? ball != Eight
            : cleared ? ball == Eight : own!.Value.Contains(ball));

        var call = before.Call;
        if (facts.PocketOf.TryGetValue(Eight, out var eightPocket))
        {
            bool shotFoul = !ruling.Legal;
            if (!cleared)
            {
                ruling.Foul(Foul.EightBallEarly);
            }
            if (shotFoul)
            {
                ruling.Foul(Foul.EightBallFoul);
            }
            if (call is not { IsSafety: false } || call.Ball != Eight || call.Pocket != eightPocket)
            {
                ruling.Foul(Foul.EightBallUncalled);
            }
            if (ruling.Legal)
            {
                ruling.Win(before.Shooter, $"{before.ShooterName} pocketed the 8 in the called pocket and wins.");
            }
            else
            {
                ruling.Win(before.Incoming, $"{before.IncomingName} wins.");
            }
            return;
        }
        if (!ruling.Legal || !facts.Made(call))
        {
            return;
        }
        var called = call!.Ball;
        if (open)
        {
            var group = BallGroup.Stripes.Contains(called) ? BallGroup.Stripes : BallGroup.Solids;
            var other = group == BallGroup.Solids ? BallGroup.Stripes : BallGroup.Solids;
            ruling.Part = new EightBallPart { Groups = before.Shooter == 0 ? new PerPlayer<BallGroup>(group, other) : new PerPlayer<BallGroup>(other, group) };
            ruling.Note = $"{before.ShooterName} has the {group.ToName()}.";
            ruling.Continue = true;
        }
        else
        {
            ruling.Continue = own!.Value.Contains(called);
        }
    }
}
