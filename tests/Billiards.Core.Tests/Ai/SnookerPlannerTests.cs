using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Ai;

/// <summary>The planner at snooker, on positions whose right answer is known.</summary>
public class SnookerPlannerTests
{
    private static readonly TableSpec Table = SnookerTable.Spec;
    private static readonly PhysicsParams Params = BallSet.Snooker.DefaultParams;
    private static readonly ShotPlanner Planner = new(Table, Params);
    private static readonly double R = Params.R;
    private static readonly BallId Blue = BallSet.Colour("blue");
    private static readonly BallId Black = BallSet.Colour("black");
    private static readonly BallId Red = BallSet.Snooker.Ids.First(SnookerRuleset.IsRed);
    private static readonly BallId Cue = BallSet.Snooker.CueBalls[0];
    private static readonly PocketId FootLeft = Pocket("foot-left");

    private static PocketId Pocket(string name) => Table.Pockets.TryParse(name, out var p) ? p : throw new ArgumentException(name);

    private static ShotRecord Simulate(TablePosition position, ShotSpec shot)
    {
        var sim = position.CreateSimulation(Table, Params);
        sim.Strike(shot);
        sim.AdvanceTo(120);
        return ShotRecord.LastShot(sim, shot);
    }

    // The blue straight in to the top-left corner from 0.4 m with the cue ball 0.5 m behind it, the black on its spot.
    private static TablePosition BlueStraightIn()
    {
        var aim = Planner.Table.AimPoint(FootLeft);
        var dir = (aim - new Vec3(0, 0, aim.Z)).XY.Normalized();
        var blue = (aim - (dir * 0.4)) with { Z = R };
        var cue = (blue - (dir * 0.5)) with { Z = R };
        return new TablePosition([(Cue, cue), (Blue, blue), (Black, SnookerTable.Spot(Table, "black", R)), (BallSet.Colour("yellow"), SnookerTable.Spot(Table, "yellow", R))], Cue);
    }

    [Fact]
    public void AheadByMoreThanSevenOnTheLastBlackTheComputerPotsItRatherThanFoulIt()
    {
        // A foul on the last black ends the frame with 7 to the opponent: 20 ahead, a foul would
        // still win. The computer plays the game, not the rule's gap: it pots the black.
        // A long, cut black: a pot is far from sure, a foul is a sure end.
        var position = new TablePosition([(Cue, new Vec3(-0.9, 0.45, R)), (Black, SnookerTable.Spot(Table, "black", R))], Cue);
        var state = new GameState(GameRules.Snooker) { Players = new("Anna", "Ben"), Shot = 60, Score = new PerPlayer<int>(60, 40), Part = new SnookerPart { BallOn = "black" } };
        var decision = Planner.Decide(state, position, SkillLevel.Of(5), new PlannerBudget(60_000, 2), 7);
        var record = Simulate(position, decision.Shot);
        var ruling = Referee.For(GameRules.Snooker, Table, R).Judge(state with { Call = decision.Call }, record);
        Assert.True(ruling.Legal, ruling.Message);
        Assert.True(ShotKinds.IsPot(decision.Kind, decision.Pocket), $"a {decision.Kind}: {ruling.Message}");
    }

    [Fact]
    public void AfterARedTheComputerNominatesTheColourItPotsAndPotsIt()
    {
        var position = BlueStraightIn();
        var state = new GameState(GameRules.Snooker) { Shot = 8, Score = new PerPlayer<int>(1, 0), Part = new SnookerPart { BallOn = SnookerRuleset.Colour } };
        var decision = Planner.Decide(state, position, SkillLevel.Of(4), new PlannerBudget(60_000, 2), 5);

        Assert.Equal(Call.Nominate(decision.Target), decision.Call);
        Assert.True(ShotKinds.IsPot(decision.Kind, decision.Pocket), $"a {decision.Kind}");
        var record = Simulate(position, decision.Shot);
        Assert.Equal(decision.Target, record.FirstContact);
        Assert.NotEqual(PocketId.None, record.PocketedOnShot(decision.Target));
        var ruling = Referee.For(GameRules.Snooker, Table, R).Judge(state with { Call = decision.Call }, record);
        Assert.True(ruling.Legal, ruling.Message);
        Assert.Equal(SnookerRuleset.ValueOf(decision.Target), ruling.Points);
    }

    // Two reds at the far end, the cue ball in the baulk half near the side cushion: the best pot is
    // long (about 2 m to the red, then 0.7 m) and level 5 makes it a fifth of the time.
    private static TablePosition LongRedsFromBaulk() => new(
        [(Cue, new Vec3(-0.9, 0.6, R)), (Red, new Vec3(0.9, -0.5, R)), (BallSet.Snooker.Ids.Where(SnookerRuleset.IsRed).ElementAt(1), new Vec3(1.2, 0.1, R)),
         (BallSet.Colour("yellow"), SnookerTable.Spot(Table, "yellow", R)), (BallSet.Colour("green"), SnookerTable.Spot(Table, "green", R)),
         (BallSet.Colour("brown"), SnookerTable.Spot(Table, "brown", R)), (Blue, SnookerTable.Spot(Table, "blue", R)),
         (BallSet.Colour("pink"), SnookerTable.Spot(Table, "pink", R)), (Black, SnookerTable.Spot(Table, "black", R))], Cue);

    [Fact]
    public void ALongPotOfLowChanceIsNotAttemptedAtLevelFiveButASafetyIsPlayed()
    {
        var state = new GameState(GameRules.Snooker) { Shot = 10, Part = new SnookerPart { BallOn = SnookerRuleset.Red } };
        var level = SkillLevel.Of(5);
        var decision = Planner.Decide(state, LongRedsFromBaulk(), level, new PlannerBudget(60_000, 2), 1);

        // Without the pot-or-safety choice the search's best mean was a pot of the far red with
        // about a fifth of its samples potting: an open table for the opponent four times in five.
        Assert.False(ShotKinds.IsPot(decision.Kind, decision.Pocket), $"a {decision.Kind} of {decision.Target} expected to pot {decision.ExpectedPot:P0}");
        Assert.True(SnookerRuleset.IsRed(decision.Target));
        Assert.True(decision.ExpectedPot < level.SurePotChance);
    }

    [Fact]
    public void ASurePotIsStillAttemptedAtLevelFive()
    {
        var state = new GameState(GameRules.Snooker) { Shot = 8, Score = new PerPlayer<int>(1, 0), Part = new SnookerPart { BallOn = SnookerRuleset.Colour } };
        var level = SkillLevel.Of(5);
        var decision = Planner.Decide(state, BlueStraightIn(), level, new PlannerBudget(60_000, 2), 5);

        // The blue straight in, or the black off its spot (worth more): a pot either way.
        Assert.True(ShotKinds.IsPot(decision.Kind, decision.Pocket), $"a {decision.Kind}");
        Assert.True(decision.ExpectedPot >= level.SurePotChance, $"expected to pot {decision.ExpectedPot:P0}");
    }

    [Fact]
    public void TheBreakOffIsPlayedFromTheDOffTheSideOfThePack()
    {
        var position = TablePosition.Rack(new RackSpec(RackGame.Snooker, 3), Table, R, Cue).Without(Cue);
        var state = new GameState(GameRules.Snooker);
        var decision = Planner.Decide(state, position, SkillLevel.Of(3), new PlannerBudget(60_000, 2), 9);

        Assert.NotNull(decision.Place);
        Assert.True(SnookerTable.InD(Table, decision.Place!.Value), $"placed at {decision.Place}");
        Assert.True(SnookerRuleset.IsRed(decision.Target));
        Assert.Null(decision.Call);
        // Played as planned it strikes a red first and leaves the cue ball on the table: no foul.
        var record = Simulate(position.With(Cue, decision.Place.Value), decision.Shot);
        var ruling = Referee.For(GameRules.Snooker, Table, R).Judge(state with { Placement = decision.Place }, record);
        Assert.True(ruling.Legal, ruling.Message);
    }

    // A miss: the cue ball, with a full view of the only red, rolled gently away from it.
    private static (Ruling Ruling, TablePosition After) Miss(Vec3 red, Vec3 cue)
    {
        var position = new TablePosition([(Cue, cue), (Red, red), (Black, SnookerTable.Spot(Table, "black", R))], Cue);
        var state = new GameState(GameRules.Snooker) { Shot = 4, Part = new SnookerPart { BallOn = SnookerRuleset.Red } };
        var away = Math.Atan2(cue.Y - red.Y, cue.X - red.X) * 180 / Math.PI;
        var record = Simulate(position, new ShotSpec(0.3, away, 0, 0));
        var ruling = Referee.For(GameRules.Snooker, Table, R).Judge(state, record);
        Assert.Contains(RefereeOption.Replace, ruling.Options);
        return (ruling, TablePosition.After(record));
    }

    [Fact]
    public void AfterAMissThatLeavesAnEasyPotTheComputerPlaysOn()
    {
        // The red 0.3 m from the top-left corner's mouth, the cue ball straight behind it.
        var aim = Planner.Table.AimPoint(FootLeft);
        var dir = (aim - new Vec3(0, 0, aim.Z)).XY.Normalized();
        var red = (aim - (dir * 0.3)) with { Z = R };
        var (ruling, after) = Miss(red, (red - (dir * 0.45)) with { Z = R });
        Assert.Equal(RefereeOption.Play, Planner.ChooseOption(ruling, after));
    }

    [Fact]
    public void AfterAMissFromAHardPositionTheComputerHasTheBallsReplaced()
    {
        // The red frozen to the middle of the top cushion, the cue ball in baulk: no pot to speak of.
        var red = new Vec3(Table.HalfLength - R, 0.05, R);
        var (ruling, after) = Miss(red, new Vec3(-1.2, 0.1, R));
        Assert.Equal(RefereeOption.Replace, Planner.ChooseOption(ruling, after));
    }

    [Fact]
    public void ABallBehindAColourSnookersThePlayerAndAClearLineDoesNot()
    {
        // The red behind the blue on the cue ball's line, the balls touching nearly: no part of the red is seen.
        var cue = new Vec3(-0.6, 0, R);
        var blue = new Vec3(0, 0, R);
        var hidden = new TablePosition([(Cue, cue), (Blue, blue), (Red, new Vec3(2.05 * R, 0, R))], Cue);
        var open = new TablePosition([(Cue, cue), (Blue, blue), (Red, new Vec3(2.05 * R, 0.4, R))], Cue);
        var state = new GameState(GameRules.Snooker) { Shot = 3, Part = new SnookerPart { BallOn = SnookerRuleset.Red } };

        Assert.True(Planner.Table.Snookered(hidden, state));
        Assert.False(Planner.Table.Snookered(open, state));
        // Pool has no snookers: the same balls never count as one.
        Assert.False(Planner.Table.Snookered(hidden, new GameState(GameRules.NineBall) { Shot = 3 }));
    }
}
