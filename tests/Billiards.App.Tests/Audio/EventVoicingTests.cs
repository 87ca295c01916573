using Billiards.App.Audio;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;

namespace Billiards.App.Tests.Audio;

public sealed class EventVoicingTests
{
    private static string Names(EventKind kind, int feature) => feature switch
    {
        1 => "left jaw of the corner pocket",
        _ => "head rail",
    };

    private static SimEvent Strike(double speed) => new(0, EventKind.CueStrike, PoolBalls.Cue, PoolBalls.Cue, -1, speed);

    [Theory]
    [InlineData(0.0, 0.0, SoundKind.CueStrike)]
    [InlineData(0.45, 0.0, SoundKind.CueStrike)]
    [InlineData(0.3, 0.3, SoundKind.CueStrike)] // 0.42 R from the centre
    [InlineData(0.0, -0.55, SoundKind.Miscue)]
    [InlineData(0.4, 0.4, SoundKind.Miscue)]    // 0.57 R
    public void ATipBeyondHalfTheRadiusMiscues(double side, double height, SoundKind expected)
    {
        var voicing = new EventVoicing(Names);
        var cue = voicing.Voice(Strike(3), Vec3.Zero, new ShotSpec(3, 0, side, height));
        Assert.Equal(expected, cue!.Value.Kind);
        Assert.Equal(3, cue.Value.Speed);
    }

    [Fact]
    public void EventsBecomeTheirSoundsAndJawsAreKnocksNotThuds()
    {
        var voicing = new EventVoicing(Names);
        var one = new BallId(1);
        Assert.Equal(SoundKind.BallClick, voicing.Voice(new SimEvent(0.1, EventKind.BallBall, PoolBalls.Cue, one, -1, 2), Vec3.Zero, null)!.Value.Kind);
        Assert.Equal(SoundKind.CushionThud, voicing.Voice(new SimEvent(0.2, EventKind.BallCushion, one, one, 0, 1), Vec3.Zero, null)!.Value.Kind);
        Assert.Equal(SoundKind.JawKnock, voicing.Voice(new SimEvent(0.3, EventKind.BallCushion, one, one, 1, 1), Vec3.Zero, null)!.Value.Kind);
        var landing = voicing.Voice(new SimEvent(0.4, EventKind.BallTable, one, one, -1, 1.7), Vec3.Zero, null)!.Value;
        Assert.Equal(SoundKind.TableLanding, landing.Kind);
        Assert.Equal(1.7, landing.Speed);
        // Leaving the bed makes no sound of its own; its landing will.
        Assert.Null(voicing.Voice(new SimEvent(0.5, EventKind.BallAirborne, one, one, -1, 1.7), Vec3.Zero, null));
    }

    [Fact]
    public void ADropJustAfterAJawHitRattlesAndALaterOneDoesNot()
    {
        var voicing = new EventVoicing(Names);
        var one = new BallId(1);
        var two = new BallId(2);
        voicing.Voice(new SimEvent(1.0, EventKind.BallCushion, one, one, 1, 1), Vec3.Zero, null);
        voicing.Voice(new SimEvent(1.0, EventKind.BallCushion, two, two, 1, 1), Vec3.Zero, null);
        Assert.True(voicing.Voice(new SimEvent(1.1, EventKind.BallPocket, one, one, 0, 1), Vec3.Zero, null)!.Value.Rattle);
        Assert.False(voicing.Voice(new SimEvent(1.0 + EventVoicing.RattleWindow + 0.1, EventKind.BallPocket, two, two, 0, 1), Vec3.Zero, null)!.Value.Rattle);
        // A ball that never touched a jaw drops cleanly.
        Assert.False(voicing.Voice(new SimEvent(1.2, EventKind.BallPocket, new BallId(3), new BallId(3), 0, 1), Vec3.Zero, null)!.Value.Rattle);
    }

    [Fact]
    public void TheSameShotGetsTheSameSeedsAndANewStrikeStartsAfresh()
    {
        var voicing = new EventVoicing(Names);
        var click = new SimEvent(0.1, EventKind.BallBall, PoolBalls.Cue, new BallId(1), -1, 2);
        uint first = voicing.Voice(Strike(3), Vec3.Zero, null)!.Value.Seed;
        uint second = voicing.Voice(click, Vec3.Zero, null)!.Value.Seed;
        Assert.NotEqual(first, second);
        Assert.Equal(first, voicing.Voice(Strike(3), Vec3.Zero, null)!.Value.Seed);
        Assert.Equal(second, voicing.Voice(click, Vec3.Zero, null)!.Value.Seed);
    }
}
