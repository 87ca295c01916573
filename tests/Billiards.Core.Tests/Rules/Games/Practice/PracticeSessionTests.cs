using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Rules.Games.Practice;

/// <summary>
/// Practice is the turn controller's timeline without a referee: shots go through the session,
/// every shot is legal and the player stays, a dropped cue ball comes back in hand, and the
/// take-back puts back every ball bit for bit, shot by shot, as in a game.
/// </summary>
public class PracticeSessionTests
{
    private static readonly TableSpec Table = TableSpec.FromPreset("pool-9ft");
    private static readonly BallId Cue = BallSet.Pool.CueBalls[0];

    private static Scene Position(params (int Id, double X, double Y)[] balls)
    {
        double r = PhysicsConfig.Default.Model.BallRadius(PhysicsConfig.Default.Params);
        return new Scene("practice", null, Table, PhysicsConfig.Default, null,
            [.. balls.Select(b => new BallSetup(new BallId(b.Id), new Vec3(b.X, b.Y, r), Vec3.Zero, Vec3.Zero))], null, null);
    }

    private static Scene Open() => Position((0, -0.6, 0.05), (1, 0.3, 0.0), (2, 0.5, 0.4), (3, -0.2, -0.4));

    // Every coordinate of every ball, as raw bits: equal means equal to the last bit.
    private static long[] Bits(BallLayout balls) =>
        [.. balls.OrderBy(b => b.Id.Value).SelectMany(b => new[] { (long)b.Id.Value, BitConverter.DoubleToInt64Bits(b.Position.X), BitConverter.DoubleToInt64Bits(b.Position.Y), BitConverter.DoubleToInt64Bits(b.Position.Z) })];

    private static GameShot Shot(double speed, double aimDeg) => new(new ShotSpec(speed, aimDeg, 0, 0), null, null, false);

    [Fact]
    public void EveryShotIsLegalThePlayerStaysAndTakeBacksRestoreEachTableBitForBit()
    {
        var session = Session.Practice(Open());
        var before = new List<long[]>();
        (double Speed, double Aim)[] shots = [(1.2, 3), (1.0, 140), (1.1, -70), (1.3, 20)];
        foreach (var (speed, aim) in shots)
        {
            before.Add(Bits(session.Game.Balls));
            var played = session.Play(Shot(speed, aim), SeatKind.Person);
            Assert.True(played.Ruling.Legal);
            Assert.True(played.Ruling.Continue);
            Assert.Empty(played.Ruling.Fouls);
            Assert.False(session.IsOver);
            Assert.Equal(0, session.State.Shooter);
            Assert.NotEqual(before[^1], Bits(session.Game.Balls));
        }
        Assert.Equal(shots.Length, session.Game.Shots.Count);
        for (int k = shots.Length - 1; k >= 0; k--)
        {
            Assert.True(session.TakeBack());
            Assert.Equal(before[k], Bits(session.Game.Balls));
            Assert.Equal(k, session.Game.Shots.Count);
        }
        Assert.False(session.TakeBack());
    }

    [Fact]
    public void ADroppedCueBallComesBackInHandAnywhereAndTheObjectBallsStayDown()
    {
        // The cue ball 0.4 m from the top right corner on its diagonal, struck into the corner; the 1 out of the way.
        double x = (Table.Length / 2) - 0.4, y = (Table.Width / 2) - 0.4;
        var session = Session.Practice(Position((0, x, y), (1, -0.5, 0.2)));
        var played = session.Play(Shot(1.5, 45), SeatKind.Person);
        Assert.True(played.Ruling.Legal);
        Assert.Equal(BallInHand.Table, session.BallInHand);
        Assert.False(session.Game.Balls.Contains(Cue));
        // Placed anywhere on the table, struck from there.
        var place = new Vec3(-0.9, -0.3, 0);
        var next = session.Play(new GameShot(new ShotSpec(1.0, 0, 0, 0), null, place, false), SeatKind.Person);
        Assert.Equal(BallInHand.None, session.BallInHand);
        Assert.Equal(-0.9, next.Before.Placement!.Value.X);
        Assert.True(session.Game.Balls.Contains(Cue));
    }

    [Fact]
    public void BallsMovedByHandAreWhereTheNextTakeBackReturns()
    {
        var session = Session.Practice(Open());
        session.Play(Shot(2.0, 10), SeatKind.Person);
        var moved = Position((0, -0.9, 0.0), (1, 0.6, -0.1), (2, 0.5, 0.4));
        session.Reposition(moved);
        var atMove = Bits(session.Game.Balls);
        Assert.Equal(3, session.Game.Balls.Count);
        session.Play(Shot(2.0, 0), SeatKind.Person);
        Assert.True(session.TakeBack());
        Assert.Equal(atMove, Bits(session.Game.Balls));
    }

    [Fact]
    public void OnlyPracticeMovesBallsByHandAndItIsNoGameOfTheRegistry()
    {
        var game = new Session(GameSetup.Of(GameRules.EightBall, 1, new PerPlayer<string>("Anna", "Ben")), Seat.Of(new PerPlayer<string>("Anna", "Ben"), SeatKind.Person));
        Assert.Throws<InvalidOperationException>(() => game.Reposition(Open()));
        Assert.DoesNotContain(Ruleset.All, r => r is PracticeRuleset);
        Assert.False(RuleNames.TryParseGame("practice", out _));
        Assert.Same(PracticeRuleset.Instance, Ruleset.For(PracticeRuleset.Practice));
    }
}
