using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// 14.1 continuous (rules.md): every shot is called; a called ball legally pocketed scores a point
/// and, as the WPA counts them, so does every other ball pocketed on that shot; balls pocketed
/// otherwise are spotted. A foul costs a point, the third in a row 15 more; the opening break
/// has its own requirement (-2 when missed). When one object ball is left the other 14 are
/// racked again and the shooter goes on.
/// </summary>
internal sealed class StraightPoolReferee(TableSpec table, double ballRadius) : RefereeBase(GameRules.StraightPool, table, ballRadius)
{
    /// <summary>Points lost for a missed opening break.</summary>
    public const int BadBreakPenalty = 2;

    /// <summary>Points lost for a foul.</summary>
    public const int FoulPenalty = 1;

    /// <summary>Points lost, besides the foul's, for the third foul in a row.</summary>
    public const int ThreeFoulPenalty = 15;

    protected override Ruling Rule(GameState before, ShotRecord shot, ShotFacts facts, RulingBuilder ruling)
    {
        int shooter = before.Shooter;
        if (facts.BadPlacement)
        {
            ruling.Foul(Foul.BadPlacement);
        }
        bool made = facts.Made(before.Call);
        int points;
        if (before.Shot == 0)
        {
            if (facts.Scratch)
            {
                ruling.Foul(Foul.CueBallPocketed);
            }
            OffTableFoul(facts, ruling);
            if (!made && !(facts.ObjectBallsToCushion >= 2 && facts.CueToCushion))
            {
                // A breaking violation, not a foul of the three-foul count (ours: the WPA's reading).
                ruling.Foul(Foul.BadBreak, "the break pocketed no called ball and did not send two object balls and the cue ball to a cushion");
                ruling.Options.AddRange([RefereeOption.Accept, RefereeOption.Rerack]);
                points = -BadBreakPenalty;
            }
            else
            {
                ruling.CountFouls();
                points = ruling.Legal ? 0 : -FoulPenalty;
            }
        }
        else
        {
            CommonFouls(facts, ruling, null);
            points = ruling.Legal ? 0 : -FoulPenalty;
            ruling.CountFouls();
        }

        if (!ruling.Has(Foul.BadBreak) && !ruling.Legal && ruling.FoulsInRow[shooter] >= 3)
        {
            ruling.Foul(Foul.ThreeFouls);
            points -= ThreeFoulPenalty;
            ruling.FoulsInRow = ruling.FoulsInRow.With(shooter, 0);
            ruling.Note = $"{before.ShooterName} loses {ThreeFoulPenalty} more points for three fouls in a row.";
        }
        else if (!ruling.Has(Foul.BadBreak) && !ruling.Legal && ruling.FoulsInRow[shooter] == 2)
        {
            ruling.Note = $"Warning: {before.ShooterName} has two fouls in a row; a third costs {ThreeFoulPenalty} more points.";
        }

        bool scores = ruling.Legal && made;
        if (scores)
        {
            points += facts.Pocketed.Count;
        }
        else
        {
            foreach (var ball in facts.Pocketed)
            {
                ruling.SpotBall(ball);
            }
        }
        // Jumped object balls are spotted (rules.md).
        foreach (var ball in facts.OffTable)
        {
            ruling.SpotBall(ball);
        }
        ruling.Score = ruling.Score.With(shooter, ruling.Score[shooter] + points);
        ruling.Continue = scores;
        // A cue ball off the table is a scratch's foul, with ball in hand in the kitchen.
        ruling.BallInHand = facts.Scratch || facts.CueOffTable ? BallInHand.Kitchen
            : !ruling.Legal && !(ruling.Has(Foul.BadBreak) && !ruling.Has(Foul.BadPlacement)) ? BallInHand.Table
            : BallInHand.None;

        if (ruling.Score[shooter] >= before.Target)
        {
            ruling.Win(shooter, $"{before.ShooterName} reaches {ruling.Score[shooter]} points and wins.");
            return ruling.Build();
        }
        if (scores && facts.OnTableAfter.Count <= 1)
        {
            var set = Ruleset.BallSet;
            foreach (var ball in Ruleset.Balls.Where(b => !set.IsCueBall(b) && !facts.OnTableAfter.Contains(b.Value)))
            {
                ruling.Rerack.Add(ball);
            }
            ruling.Outcome = $"{before.ShooterName} scores and goes on after a rerack of {ruling.Rerack.Count}.";
        }
        return ruling.Build();
    }
}
