using Billiards.Core.Balls;

namespace Billiards.Core.Tests.Balls;

/// <summary>Ball sets as data: pool's is the cue ball and 1-15; other sets (carom's two cue balls) are data too.</summary>
public class BallSetTests
{
    [Fact]
    public void PoolIsTheCueBallAndFifteenNumberedBalls()
    {
        var pool = BallSet.Pool;
        Assert.Equal(16, pool.Count);
        Assert.Equal(15, pool.HighestNumber);
        Assert.Equal(PoolBalls.Cue, pool.Ids[0]);
        Assert.Equal(Enumerable.Range(0, 16), pool.Ids.Select(b => b.Value));
        Assert.True(pool.Contains(new BallId(15)));
        Assert.False(pool.Contains(new BallId(16)));
        Assert.Equal("\"cue\" or \"1\" .. \"15\"", pool.Describe());
    }

    [Theory]
    [InlineData("cue", 0)]
    [InlineData("1", 1)]
    [InlineData("15", 15)]
    public void IdsOfTheSetParse(string text, int value)
    {
        Assert.True(BallSet.Pool.TryParse(text, out var id));
        Assert.Equal(value, id.Value);
        Assert.Equal(text, id.ToString());
    }

    [Theory]
    [InlineData("16")]
    [InlineData("0")]
    [InlineData("01")]
    [InlineData("-1")]
    [InlineData("")]
    [InlineData(null)]
    [InlineData("9999999999")]
    public void OtherTextIsNoBallOfTheSet(string? text)
    {
        Assert.False(BallSet.Pool.TryParse(text, out _));
        Assert.False(BallSet.Pool.TryParse(text, out _));
    }

    [Fact]
    public void PoolsBallsKnowTheirGroupsLooksRadiusAndMass()
    {
        var pool = BallSet.Pool;
        Assert.Equal(Enumerable.Range(1, 7), pool.Group("solids").Select(b => b.Value));
        Assert.Equal(Enumerable.Range(9, 7), pool.Group("stripes").Select(b => b.Value));
        Assert.Empty(pool.Group("reds"));
        Assert.Equal([PoolBalls.Cue], pool.CueBalls);
        Assert.All(pool.Balls, b => Assert.Equal(b.Value > 8, b.Look.Striped));
        Assert.All(pool.Balls, b => Assert.Equal(!pool.IsCueBall(b.Id), b.Look.Numbered));
        // The 1 and the 9 share yellow; the 8 is black; the cue ball is near white.
        Assert.Equal((pool.Kind(new BallId(1)).Look.Red, pool.Kind(new BallId(1)).Look.Blue), (pool.Kind(new BallId(9)).Look.Red, pool.Kind(new BallId(9)).Look.Blue));
        Assert.True(pool.Kind(new BallId(8)).Look.Red < 0.1f);
        Assert.True(pool.Kind(PoolBalls.Cue).Look.Green > 0.9f);
        Assert.Equal(Billiards.Core.Physics.PhysicsParams.DefaultRadius, pool.Radius);
        Assert.Equal(Billiards.Core.Physics.PhysicsParams.DefaultMass, pool.Mass);
    }

    [Fact]
    public void ASetWithTwoCueBallsKnowsBoth()
    {
        var look = new BallLook(1, 1, 1, false, false);
        var white = new BallId(0);
        var yellow = new BallId(1);
        var red = new BallId(2);
        var carom = new BallSet("carom", [new(white, "white", 0, look), new(yellow, "yellow", 0, look with { Blue = 0 }), new(red, "red", 0, look with { Green = 0, Blue = 0 })],
            [white, yellow], new Dictionary<string, IReadOnlyList<BallId>>(), 0.03075, 0.21);
        Assert.True(carom.IsCueBall(white));
        Assert.True(carom.IsCueBall(yellow));
        Assert.False(carom.IsCueBall(red));
        Assert.True(carom.TryParse("yellow", out var parsed));
        Assert.Equal(yellow, parsed);
        Assert.False(carom.TryParse("1", out _));
        Assert.Equal("\"white\", \"yellow\", \"red\"", carom.Describe());
        Assert.Equal("red", carom.NameOf(red));
        Assert.Throws<ArgumentException>(() => carom.Kind(new BallId(3)));
    }

    [Fact]
    public void A_set_with_two_cue_balls_plays_the_second_as_the_shots_cue_ball_and_files_name_it()
    {
        var look = new BallLook(1, 1, 1, false, false);
        var (white, yellow, red) = (new BallId(0), new BallId(1), new BallId(2));
        var carom = new BallSet("carom", [new(white, "white", 0, look), new(yellow, "yellow", 0, look), new(red, "red", 0, look)],
            [white, yellow], new Dictionary<string, IReadOnlyList<BallId>>(), Billiards.Core.Physics.PhysicsParams.DefaultRadius, Billiards.Core.Physics.PhysicsParams.DefaultMass);
        var scene = Billiards.Core.Scenes.SceneLoader.Parse("""
            { "format": "billiards-scene/1", "table": { "preset": "pocketless" },
              "balls": [ { "id": "cue", "position": [-0.5, 0.3] }, { "id": "1", "position": [-0.5, 0] }, { "id": "2", "position": [0, 0] } ] }
            """, "carom.json") with { BallSet = carom };
        var sim = Billiards.Core.Scenes.SimulationFactory.Create(scene);
        // Yellow (id 1) at the red: the white (id 0) stays where it is.
        sim.Strike(new Billiards.Core.Cue.ShotSpec(1.5, 0), yellow);
        sim.AdvanceTo(30);
        var record = Billiards.Core.Physics.ShotRecord.LastShot(sim, null);
        Assert.Equal(yellow, record.CueBall);
        Assert.Equal(red, record.FirstContact);
        Assert.Equal(new Billiards.Core.Mathematics.Vec3(-0.5, 0.3, sim.BallRadius), sim.Balls[0].Position);
        Assert.Equal(Billiards.Core.Physics.EventKind.CueStrike, sim.Events[0].Kind);
        Assert.Equal("yellow", sim.BallSet.NameOf(sim.Events[0].A));
    }
}
