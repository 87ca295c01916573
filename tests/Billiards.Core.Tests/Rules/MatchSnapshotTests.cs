using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;

namespace Billiards.Core.Tests.Rules;

/// <summary>
/// A match's snapshot and restore (the take-back and the retried shot): the balls come back bit for
/// bit, the game state and the shots played as they were, and the game goes on from there as it
/// did the first time.
/// </summary>
public class MatchSnapshotTests
{
    private static readonly PerPlayer<string> Players = new("Anna", "Ben");

    private static bool IsTarget(Match game, BallId ball) =>
        game.Ruleset.LegalTargets(game.State, game.Balls.Ids.Where(b => !PoolBalls.IsCue(b))).Contains(ball);

    private static GameShot NextShot(Match game) => Aimer.Next(game, b => IsTarget(game, b), callShots: true);

    // Every coordinate of every ball, as raw bits: equal means equal to the last bit.
    private static long[] Bits(BallLayout balls) =>
        [.. balls.OrderBy(b => b.Id.Value).SelectMany(b => new[] { (long)b.Id.Value, BitConverter.DoubleToInt64Bits(b.Position.X), BitConverter.DoubleToInt64Bits(b.Position.Y), BitConverter.DoubleToInt64Bits(b.Position.Z) })];

    [Theory]
    [InlineData("eight-ball", 3)]
    [InlineData("nine-ball", 1)]
    [InlineData("straight-pool", 2)]
    public void RestoringBeforeEachShotGivesBackItsBallsAndStateAndTheShotPlaysTheSameAgain(GameRules rules, int seed)
    {
        var game = new Match(GameSetup.Of(rules, seed, Players, target: 20));
        game.Play(rules == GameRules.StraightPool ? Aimer.Break(game, Call.Safety) : Aimer.Break(game, null));
        for (int k = 0; k < 6 && !game.IsOver; k++)
        {
            var before = game.Snapshot();
            var balls = Bits(game.Balls);
            var state = game.State;
            int shots = game.Shots.Count;
            var input = NextShot(game);
            var first = game.Play(input);
            // The shot changed something: the restore below has work to do.
            Assert.True(!Bits(game.Balls).SequenceEqual(balls) || game.State != state);

            game.Restore(before);
            Assert.Equal(balls, Bits(game.Balls));
            Assert.Equal(state, game.State);
            Assert.Equal(shots, game.Shots.Count);
            Assert.False(game.IsOver);

            // The retried shot is the same shot: same ruling, same balls at rest.
            var again = game.Play(input);
            Assert.Equal(first.Ruling.Message, again.Ruling.Message);
            Assert.Equal(first.After, again.After);
            Assert.Equal(first.Ruling.Next, again.Ruling.Next);
        }
    }

    [Fact]
    public void ASnapshotRestoresAgainAfterTheGameWentOnSeveralShots()
    {
        var game = new Match(GameSetup.Of(GameRules.EightBall, 3, Players));
        game.Play(Aimer.Break(game, null));
        var snapshot = game.Snapshot();
        var balls = Bits(game.Balls);
        var state = game.State;
        var shots = game.Shots.ToList();
        for (int k = 0; k < 4 && !game.IsOver; k++)
        {
            game.Play(NextShot(game));
        }
        game.Restore(snapshot);
        game.Restore(snapshot);
        Assert.Equal(balls, Bits(game.Balls));
        Assert.Equal(state, game.State);
        Assert.Equal(shots, game.Shots);
        Assert.Equal(snapshot.Shots, game.Shots);
    }

    [Fact]
    public void NoSnapshotWhileAShotRunsAndNoRestoreOfAnotherGame()
    {
        var game = new Match(GameSetup.Of(GameRules.NineBall, 1, Players));
        var other = new Match(GameSetup.Of(GameRules.NineBall, 2, Players));
        var sim = game.Strike(Aimer.Break(game, null));
        Assert.Throws<InvalidOperationException>(game.Snapshot);
        Match.RunToRest(sim);
        game.Judge(sim);
        if (game.PendingOptions.Count > 0)
        {
            Assert.Throws<InvalidOperationException>(game.Snapshot);
            game.Choose(game.PendingOptions[0]);
        }
        Assert.Throws<ArgumentException>(() => other.Restore(game.Snapshot()));
    }

    [Fact]
    public void ARestoreAbandonsAShotStillRunning()
    {
        var game = new Match(GameSetup.Of(GameRules.EightBall, 3, Players));
        var start = game.Snapshot();
        var balls = Bits(game.Balls);
        game.Strike(Aimer.Break(game, null));
        game.Restore(start);
        Assert.False(game.IsShotRunning);
        Assert.Equal(balls, Bits(game.Balls));
        // A new shot can start at once.
        game.Play(Aimer.Break(game, null));
        Assert.Single(game.Shots);
    }
}
