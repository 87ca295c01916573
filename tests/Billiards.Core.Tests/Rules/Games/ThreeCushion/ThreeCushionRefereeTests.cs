using Billiards.Core.Balls;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using static Billiards.Core.Tests.Rules.Games.ThreeCushion.CaromShot;

namespace Billiards.Core.Tests.Rules.Games.ThreeCushion;

/// <summary>rules.md, "Three-cushion carom": the point, the fouls, spotting, the break, frozen balls, the race and the score sheet.</summary>
public class ThreeCushionRefereeTests
{
    private static readonly GameRules Game = ThreeCushionRuleset.ThreeCushion;
    private static readonly IReferee Referee = Ruleset.For(Game).Referee(CaromShot.Table, R);

    // Player 0 (white) at the table on shot 5 of the game, 3-2 after 2 innings each.
    private static readonly GameState Later = new GameState(Game) { Shot = 5, Score = new(3, 2), Part = new ThreeCushionPart { Innings = new(2, 2), Run = 1 } };

    private static Ruling Judge(GameState state, CaromShot shot) => Referee.Judge(state, shot.Build());

    [Fact]
    public void ThreeCushionsBeforeTheFirstBallThenTheSecondScoresAPoint()
    {
        var r = Judge(Later, Striking(W).Cushions(W, 3).Hit(W, Y).Hit(W, Red));
        Assert.True(r.Point);
        Assert.True(r.Legal);
        Assert.True(r.Continue);
        Assert.Equal(3, r.Cushions);
        Assert.Equal(new PerPlayer<int>(4, 2), r.Score);
        Assert.Equal(2, r.Run);
        Assert.Equal(0, r.Next.Shooter);
        Assert.Equal(2, ThreeCushionPart.Of(r.Next).Run);
        Assert.Equal(new PerPlayer<int>(2, 2), ThreeCushionPart.Of(r.Next).Innings);
    }

    [Fact]
    public void CushionsBetweenTheBallsCountWithThoseBefore()
    {
        var r = Judge(Later, Striking(W).Cushions(W, 1).Hit(W, Red).Cushions(W, 2).Hit(W, Y));
        Assert.True(r.Point);
        Assert.Equal(3, r.Cushions);
    }

    [Fact]
    public void TheSameCushionTwiceCountsTwice()
    {
        // Cushions() numbers them 0, 1, 2, ...: three contacts on cushion 0 count three.
        var shot = Striking(W).Hit(W, Red);
        for (int k = 0; k < 3; k++)
        {
            shot.Cushions(W, 1);
        }
        Assert.True(Judge(Later, shot.Hit(W, Y)).Point);
    }

    [Fact]
    public void TwoCushionsThenAKissIsNoPoint()
    {
        // The red kisses back into the white after two cushions; the white then makes a third and meets the yellow.
        var r = Judge(Later, Striking(W).Hit(W, Red).Cushions(W, 2).Hit(Red, W).Cushions(W, 1).Hit(W, Y));
        // The kiss is the red again, not a second ball: the second ball is the yellow after three cushions: a point.
        Assert.True(r.Point);
        var kissed = Judge(Later, Striking(W).Hit(W, Red).Cushions(W, 2).Hit(Red, W).Hit(W, Y));
        Assert.False(kissed.Point);
        Assert.Equal(2, kissed.Cushions);
        Assert.False(kissed.Continue);
        Assert.True(kissed.Legal);
        Assert.Equal(1, kissed.Next.Shooter);
    }

    [Fact]
    public void ACushionContactByAnObjectBallDoesNotCount()
    {
        var r = Judge(Later, Striking(W).Cushions(W, 2).Hit(W, Red).Cushions(Red, 3).Hit(W, Y));
        Assert.False(r.Point);
        Assert.Equal(2, r.Cushions);
    }

    [Fact]
    public void TheSecondBallMetBeforeTheThirdCushionIsNoPoint()
    {
        var r = Judge(Later, Striking(W).Cushions(W, 1).Hit(W, Red).Cushions(W, 1).Hit(W, Y).Cushions(W, 3));
        Assert.False(r.Point);
        Assert.Equal(2, r.Cushions);
        Assert.Equal(new PerPlayer<int>(3, 2), r.Score);
    }

    [Fact]
    public void OneBallOnlyCountsAllTheCushions()
    {
        var r = Judge(Later, Striking(W).Cushions(W, 2).Hit(W, Red).Cushions(W, 4));
        Assert.False(r.Point);
        Assert.Equal(6, r.Cushions);
    }

    [Fact]
    public void NoPointEndsTheInningAndBeginsTheOpponents()
    {
        var r = Judge(Later, Striking(W).Cushions(W, 1));
        Assert.False(r.Point);
        Assert.True(r.Legal);
        Assert.Empty(r.Fouls);
        Assert.Equal(1, r.Next.Shooter);
        Assert.Equal(new PerPlayer<int>(2, 3), ThreeCushionPart.Of(r.Next).Innings);
        Assert.Equal(0, ThreeCushionPart.Of(r.Next).Run);
        Assert.Equal(1, r.Run);
    }

    [Fact]
    public void StrikingTheOpponentsCueBallIsAFoul()
    {
        var r = Judge(Later, Striking(Y).Cushions(Y, 3).Hit(Y, W).Hit(Y, Red));
        Assert.False(r.Legal);
        Assert.Equal([Foul.WrongCueBall], r.Fouls);
        Assert.False(r.Point);
        Assert.Equal(1, r.Next.Shooter);
    }

    [Fact]
    public void EachPlayerStrikesTheirOwnCueBall()
    {
        var yellowUp = Later with { Shooter = 1 };
        Assert.True(Judge(yellowUp, Striking(Y).Cushions(Y, 3).Hit(Y, W).Hit(Y, Red)).Point);
        var swapped = Later with { Part = ThreeCushionPart.Of(Later) with { CueBalls = new(Y, W) } };
        Assert.True(Judge(swapped, Striking(Y).Cushions(Y, 3).Hit(Y, W).Hit(Y, Red)).Point);
    }

    [Fact]
    public void TheBreakNotOnTheRedFirstIsAFoul()
    {
        var start = new GameState(Game);
        var r = Judge(start, Striking(W).Hit(W, Y).Cushions(W, 3).Hit(W, Red));
        Assert.Equal([Foul.RedNotFirstOnBreak], r.Fouls);
        Assert.False(r.Point);
        Assert.Equal(1, r.Next.Shooter);
        Assert.Equal(new PerPlayer<int>(1, 0), r.Innings);
        Assert.Equal(new PerPlayer<int>(1, 1), ThreeCushionPart.Of(r.Next).Innings);
        Assert.True(Judge(start, Striking(W).Hit(W, Red).Cushions(W, 3).Hit(W, Y)).Point);
    }

    [Fact]
    public void ABallOffTheTableIsAFoulAndIsSpotted()
    {
        var r = Judge(Later, Striking(W).Hit(W, Red).OffTable(Red).Cushions(W, 3).Hit(W, Y));
        Assert.Equal([Foul.BallOffTable], r.Fouls);
        Assert.False(r.Point);
        Assert.Equal([Red], r.Spot);
        Assert.Equal(1, r.Next.Shooter);
    }

    [Fact]
    public void AFrozenBallOffersTheBreakSpots()
    {
        // The yellow (the next shooter's) rests against the red.
        var r = Judge(Later, Striking(W).Cushions(W, 1).Rests(Y, 0.5, 0).Rests(Red, 0.5 + 2 * R, 0));
        Assert.Equal([RefereeOption.Accept, RefereeOption.SpotBreak], r.Options);
        var outcome = r.Choose(RefereeOption.SpotBreak);
        Assert.Equal([Y, W, Red], outcome.Spot);
        Assert.Empty(Judge(Later, Striking(W).Cushions(W, 1)).Options);
    }

    [Fact]
    public void TheRaceEndsAtTheTargetAfterTheEqualizingInning()
    {
        // The breaker (player 0) reaches 40 in his 20th inning; player 1 has had 19.
        var nearly = new GameState(Game) { Shot = 70, Score = new(39, 30), Part = new ThreeCushionPart { Innings = new(20, 19) } };
        var r = Judge(nearly, Striking(W).Cushions(W, 3).Hit(W, Y).Hit(W, Red));
        Assert.True(r.Point);
        Assert.False(r.GameOver);
        Assert.False(r.Continue);
        Assert.Equal(1, r.Next.Shooter);
        Assert.Equal(new PerPlayer<int>(20, 20), ThreeCushionPart.Of(r.Next).Innings);
        // The equalizing inning: a miss ends the game for the breaker.
        var last = r.Next;
        var miss = Judge(last, Striking(Y).Cushions(Y, 1));
        Assert.True(miss.GameOver);
        Assert.Equal(0, miss.Winner);
        // Points in it go on; reaching 40 too is a draw.
        var equal = Judge(last with { Score = new(40, 39) }, Striking(Y).Cushions(Y, 3).Hit(Y, W).Hit(Y, Red));
        Assert.True(equal.GameOver);
        Assert.Null(equal.Winner);
        Assert.Equal(new PerPlayer<int>(40, 40), equal.Score);
    }

    [Fact]
    public void WithoutEqualizingTheTargetWinsAtOnce()
    {
        var nearly = new GameState(Game) { Shot = 70, Score = new(39, 30), Part = new ThreeCushionPart { Innings = new(20, 19), Equalizing = false } };
        var r = Judge(nearly, Striking(W).Cushions(W, 3).Hit(W, Y).Hit(W, Red));
        Assert.True(r.GameOver);
        Assert.Equal(0, r.Winner);
    }

    [Fact]
    public void TheNonBreakerReachingTheTargetFirstWins()
    {
        var nearly = new GameState(Game) { Shooter = 1, Shot = 70, Score = new(30, 39), Part = new ThreeCushionPart { Innings = new(20, 20) } };
        var r = Judge(nearly, Striking(Y).Cushions(Y, 3).Hit(Y, W).Hit(Y, Red));
        Assert.True(r.GameOver);
        Assert.Equal(1, r.Winner);
    }

    [Fact]
    public void TheDefaultTargetIsForty() => Assert.Equal(40, new GameState(Game).Target);

    [Fact]
    public void TheAverageIsPointsPerInningToThreeDecimals()
    {
        Assert.Equal("0.667", ThreeCushionRuleset.Average(2, 3));
        Assert.Equal("1.143", ThreeCushionRuleset.Average(8, 7));
        Assert.Equal("0.000", ThreeCushionRuleset.Average(0, 0));
        Assert.Equal(0.333, ThreeCushionRuleset.AverageValue(1, 3));
        var r = Judge(Later with { Score = new(1, 2), Part = ThreeCushionPart.Of(Later) with { Innings = new(3, 2) } }, Striking(W).Cushions(W, 3).Hit(W, Y).Hit(W, Red));
        string json = System.Text.Encoding.UTF8.GetString(GameBlockWriter.RulingToUtf8(r));
        Assert.Contains("\"average\": [\n    0.667,\n    1\n  ]", json.Replace("\r\n", "\n", StringComparison.Ordinal), StringComparison.Ordinal);
    }

    [Fact]
    public void TheHighestRunIsTheLongestVisitOfPoints()
    {
        var ruleset = Ruleset.For(Game);
        var point = Judge(Later, Striking(W).Cushions(W, 3).Hit(W, Y).Hit(W, Red));
        var miss = Judge(Later, Striking(W).Cushions(W, 1));
        var visits = ruleset.Visits([(0, point), (0, point), (0, miss), (1, miss), (0, point), (0, miss)]).ToList();
        Assert.Equal([2, 0, 1], visits.Select(v => v.Break));
    }
}
