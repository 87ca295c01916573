using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Rules.Games.SnookerShot;

namespace Billiards.Core.Tests.Rules.Games;

/// <summary>One test for each rule of rules.md's "Snooker", named after the rule.</summary>
public class SnookerRefereeTests
{
    private static readonly GameState OnRed = Frame;

    // One red left on the rack's apex, the blue and black on their spots, the cue ball with a full view of the red.
    private static SnookerShot Clear() => new SnookerShot().Only("red-1", "blue", "black").At("cue", -1.0, 0.3);

    private static GameState OnColour(string nominated) => Frame with { Call = Call.Nominate(Id(nominated)), Part = SnookerPart.Of(Frame) with { BallOn = "colour" } };

    [Fact]
    public void ValuesRed1Yellow2Green3Brown4Blue5Pink6Black7()
    {
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], new[] { "red-9", "yellow", "green", "brown", "blue", "pink", "black" }.Select(n => SnookerRuleset.ValueOf(Id(n))));
        // The value is what a potted ball on scores.
        foreach (string colour in BallSet.Colours)
        {
            var ruling = new SnookerShot().Hit(colour).Pot(colour).Judge(OnColour(colour));
            Assert.Equal(SnookerRuleset.ValueOf(Id(colour)), ruling.Points);
            Assert.Equal(ruling.Points, ruling.Next.Score.First);
        }
    }

    [Fact]
    public void BallOnRedWhileRedsRemainEachRedPottedScores1AndAColourIsOnNext()
    {
        var ruling = new SnookerShot().Hit("red-3").Pot("red-3").Pot("red-7").Judge(OnRed);
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(2, ruling.Points);
        Assert.Equal(new PerPlayer<int>(2, 0), ruling.Next.Score);
        Assert.Equal("colour", SnookerPart.Of(ruling.Next).BallOn);
        Assert.Empty(ruling.Spot);
    }

    [Fact]
    public void BallOnColourTheNominatedColourPottedWhileRedsRemainScoresAndIsRespottedAndARedIsOnNext()
    {
        var ruling = new SnookerShot().Gone("red-1").Hit("blue").Pot("blue").Judge(OnColour("blue"));
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(5, ruling.Points);
        Assert.Equal([Id("blue")], ruling.Spot);
        Assert.Equal("red", SnookerPart.Of(ruling.Next).BallOn);
    }

    [Fact]
    public void BallOnColourAColourOtherThanTheNominatedOneStruckFirstIsAFoul()
    {
        var ruling = new SnookerShot().Hit("pink").Judge(OnColour("blue"));
        Assert.Equal([Foul.WrongBallFirst], ruling.Fouls);
        Assert.Equal(6, ruling.Penalty);
    }

    [Fact]
    public void ColoursPhaseTheColoursInAscendingOrderStayDownOncePotted()
    {
        var ruling = new SnookerShot().Only("yellow", "green", "black").Hit("yellow").Pot("yellow").Judge(Frame with { Part = SnookerPart.Of(Frame) with { BallOn = "yellow" } });
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(2, ruling.Points);
        Assert.Empty(ruling.Spot);
        Assert.Equal("green", SnookerPart.Of(ruling.Next).BallOn);
        // The green is not on while the yellow is.
        var wrong = new SnookerShot().Only("yellow", "green", "black").Hit("green").Judge(Frame with { Part = SnookerPart.Of(Frame) with { BallOn = "yellow" } });
        Assert.Equal([Foul.WrongBallFirst], wrong.Fouls);
    }

    [Fact]
    public void ColoursPhaseBeginsAfterTheColourThatFollowsTheLastRedWhichIsRespotted()
    {
        var ruling = new SnookerShot().Only("yellow", "green", "brown", "blue", "pink", "black").Hit("black").Pot("black").Judge(OnColour("black"));
        Assert.Equal([Id("black")], ruling.Spot);
        Assert.Equal("yellow", SnookerPart.Of(ruling.Next).BallOn);
    }

    [Fact]
    public void RespottingAColourGoesToItsOwnSpot()
    {
        var table = SnookerRuleset.Respot(BallLayout.Empty, [Id("green")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "green", R), table[Id("green")]);
    }

    [Fact]
    public void RespottingWhenTheOwnSpotIsTakenUsesTheHighestValueFreeSpot()
    {
        var table = SnookerRuleset.Respot([(Id("red-1"), SnookerTable.Spot(SnookerShot.Table, "pink", R))], [Id("pink")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "black", R), table[Id("pink")]);
        table = SnookerRuleset.Respot([(Id("red-1"), SnookerTable.Spot(SnookerShot.Table, "pink", R)), (Id("red-2"), SnookerTable.Spot(SnookerShot.Table, "black", R))], [Id("pink")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "blue", R), table[Id("pink")]);
    }

    [Fact]
    public void RespottingWithEverySpotTakenGoesAsNearItsOwnSpotAsItFitsTowardsTheTopCushion()
    {
        var table = SnookerRuleset.Respot(new BallLayout(BallSet.Colours.Select((c, i) => (Id($"red-{i + 1}"), SnookerTable.Spot(SnookerShot.Table, c, R)))), [Id("brown")], SnookerShot.Table, R);
        var brown = SnookerTable.Spot(SnookerShot.Table, "brown", R);
        Assert.Equal(new Vec3(brown.X + 2 * R, 0, R).X, table[Id("brown")].X, 9);
        Assert.Equal(0, table[Id("brown")].Y);
        // Several at once: the higher value first, so the black takes its spot before the pink looks for one.
        var two = SnookerRuleset.Respot([(Id("red-1"), SnookerTable.Spot(SnookerShot.Table, "pink", R))], [Id("pink"), Id("black")], SnookerShot.Table, R);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "black", R), two[Id("black")]);
        Assert.Equal(SnookerTable.Spot(SnookerShot.Table, "blue", R), two[Id("pink")]);
    }

    [Fact]
    public void BreakOffIsPlayedFromInHandInTheDWithARedOn()
    {
        var inD = new SnookerShot().Hit("red-5").Judge(Frame with { Shot = 0, Placement = new Vec3(-1.2, 0.1, R) });
        Assert.True(inD.Legal);
        var outside = new SnookerShot().Hit("red-5").Judge(Frame with { Shot = 0, Placement = new Vec3(-0.9, 0.1, R) });
        Assert.Contains(Foul.BadPlacement, outside.Fouls);
        Assert.Equal(BallInHand.D, Ruleset.For(GameRules.Snooker).BreakBallInHand);
        var onColour = new SnookerShot().Hit("brown").Judge(Frame with { Shot = 0 });
        Assert.Contains(Foul.WrongBallFirst, onColour.Fouls);
    }

    [Fact]
    public void FoulPenaltyIsAtLeast4AwardedToTheOpponent()
    {
        var ruling = new SnookerShot().Judge(OnRed);
        Assert.Equal([Foul.NoContact], ruling.Fouls);
        Assert.Equal(4, ruling.Penalty);
        Assert.Equal(new PerPlayer<int>(0, 4), ruling.Next.Score);
        Assert.False(ruling.Continue);
        Assert.Equal(1, ruling.Next.Shooter);
    }

    [Fact]
    public void FoulPenaltyIsTheValueOfTheBallOn()
    {
        var ruling = new SnookerShot().Hit("red-2").Judge(OnColour("black"));
        Assert.Equal(7, ruling.Penalty);
    }

    [Fact]
    public void FoulPenaltyIsTheValueOfTheBallWronglyStruckFirst()
    {
        var ruling = new SnookerShot().Hit("pink").Judge(OnRed);
        Assert.Equal([Foul.WrongBallFirst], ruling.Fouls);
        Assert.Equal(6, ruling.Penalty);
    }

    [Fact]
    public void FoulPenaltyIsTheValueOfABallWronglyPotted()
    {
        var ruling = new SnookerShot().Hit("red-4").Collide("red-4", "blue").Pot("blue").Judge(OnRed);
        Assert.Equal([Foul.WrongBallPotted], ruling.Fouls);
        Assert.Equal(5, ruling.Penalty);
        Assert.Equal(0, ruling.Points);
    }

    [Fact]
    public void InOffIsAFoulWithBallInHandInTheDForTheIncomingPlayer()
    {
        var ruling = new SnookerShot().Hit("red-4").Pot("cue").Judge(OnRed);
        Assert.Equal([Foul.CueBallPocketed], ruling.Fouls);
        Assert.Equal(BallInHand.D, ruling.BallInHand);
        Assert.Equal(BallInHand.D, ruling.Next.BallInHand);
        Assert.Equal(4, ruling.Penalty);
    }

    [Fact]
    public void BallOffTableIsAFoul()
    {
        var ruling = new SnookerShot().Hit("red-4").Collide("red-4", "black").OffTable("black").Judge(OnRed);
        Assert.Equal([Foul.BallOffTable], ruling.Fouls);
        Assert.Equal(7, ruling.Penalty);
        Assert.Equal([Id("black")], ruling.Spot);
    }

    [Fact]
    public void JumpShotOverABallBeforeTheFirstContactIsAFoul()
    {
        // The cue ball, in the air, passes over the pink to strike a red behind it; on the bed it would have hit the pink.
        var shot = new SnookerShot().At("cue", 0.5, 0).Aim(0).Airborne().Hit("red-1");
        var ruling = shot.Judge(OnRed);
        Assert.Equal([Foul.JumpShot], ruling.Fouls);
        // The same contact without leaving the bed is legal.
        Assert.True(new SnookerShot().At("cue", 0.5, 0).Aim(0).Hit("red-1").Judge(OnRed).Legal);
    }

    [Fact]
    public void BadPlacementOutsideTheDIsAFoul()
    {
        var ruling = new SnookerShot().Hit("red-1").Judge(Frame with { BallInHand = BallInHand.D, Placement = new Vec3(-1.1, 0.35, R) });
        Assert.Contains(Foul.BadPlacement, ruling.Fouls);
    }

    [Fact]
    public void RedsPottedOnAFoulStayDownAndColoursAreRespotted()
    {
        var ruling = new SnookerShot().Hit("red-4").Pot("red-4").Pot("yellow").Pot("cue").Judge(OnRed);
        Assert.False(ruling.Legal);
        Assert.Equal([Id("yellow")], ruling.Spot);
        Assert.Equal(0, ruling.Points);
    }

    [Fact]
    public void ThereIsNoRailRule()
    {
        var ruling = new SnookerShot().Hit("red-4").Judge(OnRed);
        Assert.True(ruling.Legal);
        Assert.False(ruling.Continue);
        Assert.Empty(ruling.Options);
    }

    [Fact]
    public void AfterAFoulTheIncomingPlayerChoosesPlayOrPutBack()
    {
        var ruling = new SnookerShot().Hit("red-4").Pot("cue").Judge(OnRed);
        Assert.Equal([RefereeOption.Play, RefereeOption.PutBack], ruling.Options);
        var play = ruling.Choose(RefereeOption.Play);
        Assert.Equal(1, play.Next.Shooter);
        var putBack = ruling.Choose(RefereeOption.PutBack);
        Assert.Equal(0, putBack.Next.Shooter);
        Assert.Equal(BallInHand.D, putBack.Next.BallInHand);
        Assert.Equal(4, putBack.Next.Score.Second);
    }

    [Fact]
    public void FoulAndAMissIsCalledWhenTheBallOnIsNotStruckAndOffersReplace()
    {
        var ruling = new SnookerShot().Hit("blue").Judge(OnRed);
        Assert.True(ruling.FoulAndMiss);
        Assert.Equal([RefereeOption.Play, RefereeOption.PutBack, RefereeOption.Replace], ruling.Options);
        var replace = ruling.Choose(RefereeOption.Replace);
        Assert.True(replace.Replace);
        Assert.Equal(0, replace.Next.Shooter);
        Assert.Equal(new PerPlayer<int>(0, 5), replace.Next.Score);
        Assert.Equal(new PerPlayer<int>(1, 0), SnookerPart.Of(replace.Next).MissesInRow);
        // Striking the ball on and fouling otherwise is no miss.
        Assert.False(new SnookerShot().Hit("red-4").Pot("cue").Judge(OnRed).FoulAndMiss);
    }

    [Fact]
    public void FoulAndAMissIsNotCalledWhenOnlyTheBlackRemains()
    {
        var ruling = new SnookerShot().Only("black").Judge(Frame with { Score = new(30, 20), Part = SnookerPart.Of(Frame) with { BallOn = "black" } });
        Assert.False(ruling.FoulAndMiss);
    }

    [Fact]
    public void FoulAndAMissIsNotCalledWhenAPlayerNeedsSnookers()
    {
        // Only pink and black: 13 points remain; 40 behind needs snookers.
        var ruling = new SnookerShot().Only("pink", "black").Hit("black").Judge(Frame with { Score = new(10, 50), Part = SnookerPart.Of(Frame) with { BallOn = "pink" } });
        Assert.False(ruling.FoulAndMiss);
        // 40 behind 50 needs no snookers before, but after the 7 away it does: no miss either.
        Assert.False(new SnookerShot().Only("pink", "black").Hit("black").Judge(Frame with { Score = new(40, 50), Part = SnookerPart.Of(Frame) with { BallOn = "pink" } }).FoulAndMiss);
        var level = new SnookerShot().Only("pink", "black").Hit("black").Judge(Frame with { Score = new(45, 50), Part = SnookerPart.Of(Frame) with { BallOn = "pink" } });
        Assert.True(level.FoulAndMiss);
    }

    [Fact]
    public void FoulAndAMissIsNotCalledWhenTheStrikerWasSnookeredAndTheCueBallReachedTheBallOnsDistance()
    {
        // The pink stands between the cue ball and the last red: no part of the red can be struck.
        var snookered = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3);
        var reached = snookered.Hit("pink").Rests("cue", -0.7, 0.3).Judge(OnRed);
        Assert.False(reached.FoulAndMiss);
        var shortOf = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3)
            .Hit("pink").Rests("cue", 0.1, 0.3).Judge(OnRed);
        Assert.True(shortOf.FoulAndMiss);
    }

    [Fact]
    public void ThreeMissesWithAFullBallViewLoseTheFrameAndTheRefereeWarnsAfterTheSecond()
    {
        // A clear view of the last red (on the rack's apex) past the blue.
        var second = Clear().Hit("blue").Judge(OnRed with { Part = SnookerPart.Of(OnRed) with { MissesInRow = new(1, 0) } });
        Assert.True(second.FoulAndMiss);
        Assert.Contains("Warning", second.Message, StringComparison.Ordinal);
        Assert.False(second.GameOver);
        var third = Clear().Hit("blue").Judge(OnRed with { Part = SnookerPart.Of(OnRed) with { MissesInRow = new(2, 0) } });
        Assert.Contains(Foul.ThreeMisses, third.Fouls);
        Assert.True(third.GameOver);
        Assert.Equal(1, third.Winner);
        // Without a full ball view (snookered, the cue ball short of the red) the count goes on and loses nothing.
        var blind = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3)
            .Hit("pink").Judge(OnRed with { Part = SnookerPart.Of(OnRed) with { MissesInRow = new(2, 0) } });
        Assert.True(blind.FoulAndMiss);
        Assert.False(blind.GameOver);
    }

    [Fact]
    public void FreeBallIsOfferedAfterAFoulWhenTheIncomingPlayerIsSnookered()
    {
        var ruling = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.3, 0.3).At("red-1", 0.6, 0.3)
            .Hit("black").Judge(OnRed with { Shooter = 1 });
        Assert.True(ruling.FreeBall);
        Assert.True(SnookerPart.Of(ruling.Next).FreeBall);
        Assert.False(SnookerPart.Of(ruling.Choose(RefereeOption.PutBack).Next).FreeBall);
        // Not snookered, no free ball.
        Assert.False(Clear().Hit("black").Judge(OnRed with { Shooter = 1 }).FreeBall);
    }

    [Fact]
    public void FreeBallNominatedAndPottedScoresAsTheBallOnAndIsRespotted()
    {
        var state = OnRed with { Call = Call.Nominate(Id("pink")), Part = SnookerPart.Of(OnRed) with { FreeBall = true } };
        var ruling = new SnookerShot().Only("red-1", "pink", "black").Hit("pink").Pot("pink").Judge(state);
        Assert.True(ruling.Legal && ruling.Continue);
        Assert.Equal(1, ruling.Points);
        Assert.Equal([Id("pink")], ruling.Spot);
        Assert.Equal("colour", SnookerPart.Of(ruling.Next).BallOn);
        // In the colours phase it scores the colour on's value.
        var colours = new SnookerShot().Only("green", "pink", "black").Hit("pink").Pot("pink")
            .Judge(Frame with { Call = Call.Nominate(Id("pink")), Part = SnookerPart.Of(Frame) with { BallOn = "green", FreeBall = true } });
        Assert.Equal(3, colours.Points);
        Assert.Equal([Id("pink")], colours.Spot);
        Assert.Equal("green", SnookerPart.Of(colours.Next).BallOn);
        // Struck first, it is the ball on; the real ball on struck first is not.
        var wrong = new SnookerShot().Only("red-1", "pink", "black").Hit("red-1").Judge(state);
        Assert.Contains(Foul.WrongBallFirst, wrong.Fouls);
    }

    [Fact]
    public void SnookeringTheOpponentBehindTheFreeBallIsAFoul()
    {
        // The free ball (pink) ends between the cue ball and the last red.
        var state = OnRed with { Call = Call.Nominate(Id("pink")), Part = SnookerPart.Of(OnRed) with { FreeBall = true } };
        var ruling = new SnookerShot().Only("red-1", "pink", "black").At("cue", 0, 0.3).At("pink", 0.5, 0.6).At("red-1", 0.6, 0.3)
            .Hit("pink").Rests("pink", 0.3, 0.3).Judge(state);
        Assert.Contains(Foul.SnookeredByFreeBall, ruling.Fouls);
        Assert.Equal(4, ruling.Penalty);
        // Unless only the pink and black remain.
        var late = new SnookerShot().Only("pink", "black").At("cue", 0, 0.3).At("black", 0.6, 0.3).At("pink", 0.5, 0.6)
            .Hit("black").Rests("black", 0.3, 0.3).Judge(Frame with { Call = Call.Nominate(Id("black")), Part = SnookerPart.Of(Frame) with { BallOn = "pink", FreeBall = true } });
        Assert.DoesNotContain(Foul.SnookeredByFreeBall, late.Fouls);
    }

    [Fact]
    public void EndOfFrameTheLastBlackPottedGivesTheFrameToTheHigherScore()
    {
        var ruling = new SnookerShot().Only("black").Hit("black").Pot("black").Judge(Frame with { Score = new(40, 44), Part = SnookerPart.Of(Frame) with { BallOn = "black" } });
        Assert.True(ruling.GameOver);
        Assert.Equal(0, ruling.Winner);
        Assert.Equal(7, ruling.Points);
        // A foul on the last black ends it too.
        var foul = new SnookerShot().Only("black").Hit("black").Pot("cue").Judge(Frame with { Score = new(40, 44), Part = SnookerPart.Of(Frame) with { BallOn = "black" } });
        Assert.True(foul.GameOver);
        Assert.Equal(1, foul.Winner);
    }

    [Fact]
    public void EndOfFrameOnEqualScoresTheBlackIsRespottedAndPlayedFromInHandInTheD()
    {
        var ruling = new SnookerShot().Only("black").Hit("black").Pot("black").Judge(Frame with { Score = new(40, 47), Part = SnookerPart.Of(Frame) with { BallOn = "black" } });
        Assert.False(ruling.GameOver);
        Assert.Equal([Id("black")], ruling.Spot);
        Assert.Equal(BallInHand.D, ruling.Next.BallInHand);
        Assert.Equal("black", SnookerPart.Of(ruling.Next).BallOn);
        Assert.Equal(new PerPlayer<int>(47, 47), ruling.Next.Score);
        // The first to score then decides it.
        var decider = new SnookerShot().Only("black").Hit("black").Pot("black").Judge(ruling.Next);
        Assert.True(decider.GameOver);
        Assert.Equal(ruling.Next.Shooter, decider.Winner);
    }
}
