using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// 9-ball and 10-ball (rules.md): the lowest ball on the table is the legal target, the push-out
/// after the break, three fouls in a row lose. 9-ball has no calls and the 9 wins on any legal
/// shot, the break included; 10-ball calls every shot but the break, and only the 10 legally
/// pocketed in its called pocket wins.
/// </summary>
internal sealed class RotationReferee(RotationRuleset ruleset, TableSpec table, double ballRadius) : RefereeBase(ruleset.Game, table, ballRadius)
{
    private bool Called => ruleset.CallsShots;

    private BallId Money => ruleset.Money;

    protected override Ruling Rule(GameState before, ShotRecord shot, ShotFacts facts, RulingBuilder ruling)
    {
        if (facts.BadPlacement)
        {
            ruling.Foul(Foul.BadPlacement);
        }
        bool moneyDown = facts.PocketOf.ContainsKey(Money);
        bool moneyWins;
        if (before.Shot == 0)
        {
            if (facts.Scratch)
            {
                ruling.Foul(Foul.CueBallPocketed);
            }
            OffTableFoul(facts, ruling);
            // Which of the two the break failed: the first ball it hit, or what it drove.
            if (facts.FirstContact != facts.Lowest)
            {
                ruling.Foul(Foul.BadBreak, facts.FirstContact is { } first ? $"the break hit the {first} first, not the {facts.Lowest}" : $"the break missed the {facts.Lowest}");
            }
            else if (facts.Pocketed.Count == 0 && facts.ObjectBallsToCushion < 4)
            {
                ruling.Foul(Foul.BadBreak, string.Create(System.Globalization.CultureInfo.InvariantCulture, $"the break pocketed no ball and sent {facts.ObjectBallsToCushion} object {(facts.ObjectBallsToCushion == 1 ? "ball" : "balls")} to a cushion, not four"));
            }
            ruling.Continue = facts.Pocketed.Count > 0;
            moneyWins = !Called;
        }
        else if (before.PushOut && before.Shot == 1)
        {
            // First contact and rail do not apply; a scratch is still a foul.
            if (facts.Scratch)
            {
                ruling.Foul(Foul.CueBallPocketed);
            }
            OffTableFoul(facts, ruling);
            if (ruling.Legal)
            {
                ruling.Options.AddRange([RefereeOption.Shoot, RefereeOption.PassBack]);
                ruling.Outcome = $"{before.ShooterName} pushed out.";
            }
            moneyWins = false;
        }
        else
        {
            var lowest = facts.Lowest;
            CommonFouls(facts, ruling, ball => ball == lowest);
            bool made = facts.Made(before.Call);
            ruling.Continue = Called ? made : facts.Pocketed.Count > 0;
            moneyWins = !Called || (made && before.Call!.Ball == Money);
        }

        ruling.CountFouls();
        if (!ruling.Legal)
        {
            ruling.BallInHand = BallInHand.Table;
            int fouls = ruling.FoulsInRow[before.Shooter];
            if (fouls >= 3)
            {
                ruling.Foul(Foul.ThreeFouls);
                ruling.Win(before.Incoming, $"{before.IncomingName} wins.");
                return ruling.Build();
            }
            if (fouls == 2)
            {
                ruling.Note = $"Warning: {before.ShooterName} has two fouls in a row; a third loses the game.";
            }
        }
        // Jumped balls stay off the table, except the game ball, which is spotted (rules.md).
        if (facts.OffTable.Contains(Money))
        {
            ruling.SpotBall(Money);
        }
        if (moneyDown)
        {
            if (ruling.Legal && moneyWins)
            {
                ruling.Win(before.Shooter, $"{before.ShooterName} pocketed the {Money} and wins.");
            }
            else
            {
                ruling.SpotBall(Money);
            }
        }
        return ruling.Build();
    }
}
