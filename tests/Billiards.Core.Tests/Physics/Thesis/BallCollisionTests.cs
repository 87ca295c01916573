using System.Numerics;
using Billiards.Core.Physics;
using static Billiards.Core.Tests.Physics.Thesis.ThesisKit;

namespace Billiards.Core.Tests.Physics.Thesis;

/// <summary>Formel 11-19 (seed 4.3.3): ball-ball overlap, separation, velocity swap, follow and draw.</summary>
public class BallCollisionTests
{
    // Centres 5 cm apart along (4, 0, 3): d_n = (0.8, 0, 0.6), n = normalize((0,1,0) x d) = (3, 0, -4) / 5.
    [Fact]
    public void OverlappingBallsAreSeparatedAlongTheLineOfCentres()
    {
        var first = At(1, 0, 0);
        var second = At(2, 4, 3);
        var engine = Engine("thesis", first, second);
        Assert.True(engine.CalculateBallCollision(first, second));
        // Formel 11: p1 = p2 - d_n * 5.72 = (4 - 4.576, ., 3 - 3.432).
        AssertVector(new Vector3(-0.576f, Y, -0.432f), first.Position, 1e-5f);
        AssertVector(new Vector3(4, Y, 3), second.Position, 0);
    }

    [Fact]
    public void TheLineOfCentresPartsAreSwappedAndBothKeep95Percent()
    {
        var first = At(1, 0, 0, vx: 100);
        var second = At(2, 4, 3);
        var engine = Engine("thesis", first, second);
        engine.CalculateBallCollision(first, second);
        // v_d1 = 100 * 0.8 = 80, v_n1 = 100 * 0.6 = 60, v_d2 = v_n2 = 0 (Formel 12-15).
        // v1' = (0 d_n + 60 n) 0.95 = 57 (0.6, 0, -0.8) = (34.2, 0, -45.6)  (Formel 16)
        // v2' = (80 d_n + 0 n) 0.95 = 76 (0.8, 0, 0.6) = (60.8, 0, 45.6)   (Formel 17)
        AssertVector(new Vector3(34.2f, 0, -45.6f), first.Velocity);
        AssertVector(new Vector3(60.8f, 0, 45.6f), second.Velocity);
    }

    [Fact]
    public void AHeadOnCollisionOfTwoMovingBallsSwapsTheirSpeedsAndLogsTheApproach()
    {
        var first = At(3, 0, 0, vx: 100);
        var second = At(4, 5, 0, vx: -50);
        var engine = Engine("thesis", first, second);
        engine.CalculateBallCollision(first, second);
        // d_n = x: v1' = -50 * 0.95 = -47.5, v2' = 100 * 0.95 = 95.
        AssertVector(new Vector3(-47.5f, 0, 0), first.Velocity);
        AssertVector(new Vector3(95, 0, 0), second.Velocity);
        var e = Assert.Single(engine.Events!.AsSpan().ToArray());
        Assert.Equal(EventKind.BallBall, e.Kind);
        Assert.Equal(3, e.A.Value);
        Assert.Equal(4, e.B.Value);
        Assert.Equal(1.5, e.Speed, 1e-6); // approach 100 - (-50) = 150 cm/s = 1.5 m/s
    }

    [Fact]
    public void BallsExactlyTouchingDoNotCollide()
    {
        var first = At(1, 0, 0, vx: 100);
        var second = At(2, 5.72f, 0);
        var engine = Engine("thesis", first, second);
        Assert.False(engine.CalculateBallCollision(first, second));
        Assert.Equal(new Vector3(100, 0, 0), first.Velocity);
    }

    [Theory]
    // e_y, cue speed, expected cue velocity after, expected e_y after.
    // f = |v_old| / 4 capped at 100 (Formel 18); v_e = v' + v_old/|v_old| e_y f (Formel 19), v' = 0 head-on.
    [InlineData(1f, 100f, 25f, 0.2f)]      // follow: f = 25, +25; e_y 1 * 0.2
    [InlineData(-2f, 100f, -50f, 0.4f)]    // draw: f = 25, -50; e_y -2 * 0.2 = -0.4, inverted to 0.4
    [InlineData(1f, 800f, 100f, 0.2f)]     // f = 200 capped at 100
    [InlineData(0f, 100f, 0f, 0f)]         // no effet: the cue ball stops
    public void TheCueBallGetsFollowOrDrawAndItsEffetDecays(float ey, float speed, float expectedVx, float expectedEy)
    {
        var cue = At(0, 0, 0, vx: speed);
        var ball = At(1, 5, 0);
        var engine = Engine("thesis", cue, ball);
        engine.Queue.EY = ey;
        engine.CalculateBallCollision(cue, ball);
        AssertVector(new Vector3(expectedVx, 0, 0), cue.Velocity);
        AssertVector(new Vector3(0.95f * speed, 0, 0), ball.Velocity);
        Assert.Equal(expectedEy, engine.Queue.EY, 1e-6f);
    }

    [Fact]
    public void DrawTurnsToFollowAtTheSecondContact()
    {
        // After a draw contact e_y = +0.4 (see above); a second head-on contact at 100 cm/s adds
        // 0.4 * 25 = +10 cm/s forward, and e_y becomes 0.08.
        var cue = At(0, 0, 0, vx: 100);
        var ball = At(1, 5, 0);
        var engine = Engine("thesis", cue, ball);
        engine.Queue.EY = -2;
        engine.CalculateBallCollision(cue, ball);
        cue.Velocity = new Vector3(100, 0, 0);
        ball.Position = new Vector3(cue.Position.X + 5, Y, 0);
        ball.Velocity = Vector3.Zero;
        engine.CalculateBallCollision(cue, ball);
        AssertVector(new Vector3(10, 0, 0), cue.Velocity);
        Assert.Equal(0.08f, engine.Queue.EY, 1e-6f);
    }

    [Fact]
    public void TheCueBallGetsItsEffetAlsoAsTheSecondBallOfThePair()
    {
        var ball = At(1, 0, 0);
        var cue = At(0, 5, 0, vx: -100);
        var engine = Engine("thesis", ball, cue);
        engine.Queue.EY = 1;
        engine.CalculateBallCollision(ball, cue);
        // d_n = x, v_d2 = -100: ball 1 gets -95; the cue gets 0 plus (-1, 0, 0) * 1 * 25.
        AssertVector(new Vector3(-95, 0, 0), ball.Velocity);
        AssertVector(new Vector3(-25, 0, 0), cue.Velocity);
        // The first ball of the pair is the one moved back: 5 - 5.72.
        AssertVector(new Vector3(-0.72f, Y, 0), ball.Position, 1e-5f);
    }

    [Fact]
    public void ObjectBallsIgnoreTheCueEffet()
    {
        var first = At(1, 0, 0, vx: 100);
        var second = At(2, 5, 0);
        var engine = Engine("thesis", first, second);
        engine.Queue.EY = 2;
        engine.CalculateBallCollision(first, second);
        AssertVector(Vector3.Zero, first.Velocity);
        Assert.Equal(2, engine.Queue.EY);
    }
}
