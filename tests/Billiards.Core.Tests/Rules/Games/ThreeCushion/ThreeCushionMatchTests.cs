using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Rules.Games.ThreeCushion;

/// <summary>Three-cushion's equipment and a game through Core's match with real physics: the break's places, spotting, records that replay.</summary>
public class ThreeCushionMatchTests
{
    private static readonly GameRules Game = ThreeCushionRuleset.ThreeCushion;

    [Fact]
    public void TheCaromMatchTableIsTheUmbsPocketlessTwoEightyFour()
    {
        var table = TableSpec.FromPreset("carom-match");
        Assert.Equal(2.84, table.Length);
        Assert.Equal(1.42, table.Width);
        Assert.False(table.HasPockets);
        Assert.Equal(0.037, table.CushionHeight);
        Assert.Equal(0.355, CaromTable.DiamondSpacing(table), 12);
        // The nose meets a 61.5 mm ball 11.7 deg above its equator.
        Assert.Equal(11.7, CaromTable.ContactAngle(table.CushionHeight, 0.03075) * 180 / Math.PI, 1);
    }

    [Fact]
    public void CaromBallsAreWhiteYellowAndRedOf615MillimetresAnd210GramsOnTheHeatedCloth()
    {
        var set = Ruleset.For(Game).BallSet;
        Assert.Equal(["white", "yellow", "red"], set.Balls.Select(b => b.Name));
        Assert.Equal([BallSet.White, BallSet.Yellow], set.CueBalls);
        Assert.Equal(0.03075, set.Radius);
        Assert.Equal(0.210, set.Mass);
        var p = set.DefaultParams;
        Assert.Equal((0.03075, 0.210, Cloth.Heated.MuS, Cloth.Heated.MuR), (p.R, p.M, p.MuS, p.MuR));
        // Spin about z dies at pool's rate on the bigger, heavier ball (to 1e-9 rad/s^2).
        Assert.Equal(PhysicsParams.Pool.SpinDeceleration, p.SpinDeceleration, 9);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    public void TheBreakPutsTheRedOnTheFootSpotAndTheBreakersBallBesideTheOpponents(int breaker)
    {
        var setup = GameSetup.Of(Game, 1);
        setup = setup with { Start = setup.Start with { Shooter = breaker, Part = ThreeCushionPart.Of(setup.Start) with { Breaker = breaker } } };
        var match = new Match(setup);
        double r = setup.BallRadius;
        var own = breaker == 0 ? BallSet.White : BallSet.Yellow;
        var other = breaker == 0 ? BallSet.Yellow : BallSet.White;
        Assert.Equal(new Vec3(0.71, 0, r), match.Balls[BallSet.Red]);
        Assert.Equal(new Vec3(-0.71, 0, r), match.Balls[other]);
        Assert.Equal(new Vec3(-0.71, 0.1826, r), match.Balls[own]);
        Assert.Equal(own, Ruleset.For(Game).CueBall(match.State));
    }

    [Fact]
    public void ASceneRackOfThreeCushionPlacesTheShootersBallForTheBreak()
    {
        const string json = """
            {"format": "billiards-scene/1", "table": {"preset": "carom-match"}, "rack": {"game": "three-cushion"},
             "game": {"rules": "three-cushion", "shooter": 1}}
            """;
        var scene = SceneLoader.Parse(json, "break.json");
        Assert.Equal(BallSet.Carom, scene.BallSet);
        Assert.Equal(0.1826, scene.Balls.Single(b => b.Id == BallSet.Yellow).Position.Y, 12);
        Assert.Equal(0, scene.Balls.Single(b => b.Id == BallSet.White).Position.Y);
        Assert.Equal(BallSet.Yellow, scene.CueBall);
    }

    [Fact]
    public void ABallOffTheTableGoesToItsSpotOrTheOthersWhenItIsTaken()
    {
        var match = new Match(GameSetup.Of(Game, 1));
        var ruleset = Ruleset.For(Game);
        var sim = match.Layout();
        double r = match.Setup.BallRadius;
        // The yellow stands on the head spot (the white's) and the red on the foot spot (the other): the white goes to the centre spot.
        ruleset.SpotBalls(sim, [BallSet.White]);
        Assert.Equal(new Vec3(0, 0, r), Position(sim, BallSet.White));
        // With the foot spot free the red goes back to it.
        sim.PlaceBall(BallSet.Red, new Vec3(0.3, 0.3, r));
        ruleset.SpotBalls(sim, [BallSet.Red]);
        Assert.Equal(new Vec3(0.71, 0, r), Position(sim, BallSet.Red));
    }

    private static Vec3 Position(Simulation sim, BallId id) => sim.Balls[sim.IndexOf(id)].Position;

    /// <summary>
    /// Seeded random strokes of the right cue ball through a game: every ruling applies, the score
    /// and the innings only grow, no two balls overlap between shots, and the record replays.
    /// </summary>
    [Theory]
    [InlineData(7)]
    [InlineData(31)]
    public void RandomStrokesThroughAGameApplyEveryRulingAndReplay(int seed)
    {
        var random = new Random(seed);
        var setup = GameSetup.Of(Game, 3, target: 2);
        var match = new Match(setup);
        double r = setup.BallRadius;
        for (int i = 0; i < 40 && !match.IsOver; i++)
        {
            var before = match.State;
            var shot = match.Play(new GameShot(new ShotSpec(1 + (random.NextDouble() * 5), random.NextDouble() * 360, (random.NextDouble() - 0.5) * 0.6, (random.NextDouble() - 0.5) * 0.6),
                Choice: RefereeOption.Accept));
            if (match.IsOver)
            {
                break;
            }
            Assert.True(match.State.Score.First >= before.Score.First && match.State.Score.Second >= before.Score.Second, shot.Ruling.Message);
            Assert.True(ThreeCushionPart.Of(match.State).Innings.First >= ThreeCushionPart.Of(before).Innings.First && ThreeCushionPart.Of(match.State).Innings.Second >= ThreeCushionPart.Of(before).Innings.Second, shot.Ruling.Message);
            var balls = match.Balls.Positions.ToList();
            Assert.Equal(3, balls.Count);
            for (int a = 0; a < balls.Count; a++)
            {
                for (int b = a + 1; b < balls.Count; b++)
                {
                    Assert.True((balls[a] - balls[b]).LengthXY >= 2 * r - 1e-6, $"shot {i}: two balls overlap");
                }
            }
        }
        var record = GameRecordFile.Parse(System.Text.Encoding.UTF8.GetString(GameRecordFile.ToUtf8(match)), "random.json");
        Assert.Equal(-1, GameRecordFile.Replay(record, out _));
    }
}
