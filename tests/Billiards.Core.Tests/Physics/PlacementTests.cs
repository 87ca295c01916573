using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Thesis;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Physics;

/// <summary>Placing, removing, spotting and reracking balls through the simulation, under both models.</summary>
public class PlacementTests
{
    public static TheoryData<string> Models => [.. ModelRegistry.Names];

    // Positions come back through the thesis model's single-precision centimetres.
    private static double Tolerance(Simulation sim) => sim is ThesisSimulation ? 1e-6 : 0;

    private static double Tolerance(string model) => Tolerance(Create(model));

    private static string F(double x) => x.ToString("R", CultureInfo.InvariantCulture);

    private static Simulation Create(string model, params (string Id, double X, double Y)[] balls)
    {
        string list = string.Join(", ", balls.Select(b => $$"""{ "id": "{{b.Id}}", "position": [{{F(b.X)}}, {{F(b.Y)}}] }"""));
        string json = $$"""
            { "format": "billiards-scene/1", "table": { "preset": "pool-9ft" },
              "physics": { "model": "{{model}}" }, "balls": [ {{list}} ] }
            """;
        return SimulationFactory.Create(SceneLoader.Parse(json, "placement.json"));
    }

    private static BallState State(Simulation sim, string id) =>
        sim.Balls[sim.IndexOf(BallSet.Pool.TryParse(id, out var b) ? b : throw new ArgumentException(id))];

    private static void AssertAt(Simulation sim, string id, double x, double y)
    {
        var s = State(sim, id);
        Assert.False(s.IsPocketed);
        Assert.Equal(MotionState.Stationary, s.State);
        Assert.Equal(x, s.Position.X, Tolerance(sim));
        Assert.Equal(y, s.Position.Y, Tolerance(sim));
        Assert.Equal(sim.BallRadius, s.Position.Z, Tolerance(sim));
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void APlacedCueBallIsStruckFromWhereItWasPlaced(string model)
    {
        var sim = Create(model, ("cue", -0.6, 0), ("1", 0.3, 0.2));
        sim.PlaceBall(PoolBalls.Cue, new Vec3(-0.2, 0.2, 0));
        AssertAt(sim, "cue", -0.2, 0.2);

        // Straight along +x into the 1, 0.5 m away.
        sim.Strike(new ShotSpec(1, 0));
        sim.AdvanceTo(60);
        Assert.True(sim.IsAtRest);
        var hit = sim.Events.AsSpan().ToArray().Where(e => e.Kind == EventKind.BallBall).ToList();
        Assert.NotEmpty(hit);
        Assert.Equal((PoolBalls.Cue, new BallId(1)), (hit[0].A, hit[0].B));
        // A centred hit along the line of centres sends the 1 along it (and square off the foot
        // cushion, should it reach it): it stays on y = 0.2.
        Assert.Equal(0.2, State(sim, "1").Position.Y, 1e-4);
        Assert.True(Math.Abs(State(sim, "1").Position.X - 0.3) > 0.01, "the 1 moved");
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void APlacementIsRefusedWithTheBallAndTheProblemNamed(string model)
    {
        var sim = Create(model, ("cue", -0.6, 0), ("1", 0.3, 0.2));
        var e = Assert.Throws<PlacementException>(() => sim.PlaceBall(PoolBalls.Cue, new Vec3(0.32, 0.21, 0)));
        Assert.StartsWith("ball \"cue\" overlaps ball \"1\"", e.Message);
        Assert.False(sim.TryPlaceBall(PoolBalls.Cue, new Vec3(-0.3, 0, 0), PlacementRegion.Kitchen, out string? problem));
        Assert.Contains("outside the kitchen", problem);
        Assert.Contains("off the table", sim.PlacementProblem(PoolBalls.Cue, new Vec3(1.4, 0, 0)));
        Assert.Contains("pocket", sim.PlacementProblem(PoolBalls.Cue, new Vec3(1.27 - 0.0286, 0.635 - 0.0286, 0)));
        Assert.Contains("not in this game's ball set", sim.PlacementProblem(new BallId(9), Vec3.Zero));
        // Nothing moved.
        AssertAt(sim, "cue", -0.6, 0);
        Assert.True(sim.TryPlaceBall(PoolBalls.Cue, new Vec3(-0.7, 0.1, 0), PlacementRegion.Kitchen, out problem));
        Assert.Null(problem);
        AssertAt(sim, "cue", -0.7, 0.1);
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void BallsArePlacedOnlyWhileEveryBallRests(string model)
    {
        var sim = Create(model, ("cue", -0.6, 0), ("1", 0.3, 0.2));
        sim.Strike(new ShotSpec(1, 90));
        Assert.Throws<InvalidOperationException>(() => sim.PlaceBall(new BallId(1), new Vec3(0, -0.3, 0)));
        Assert.Throws<InvalidOperationException>(() => sim.RemoveBall(new BallId(1)));
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void ARemovedBallIsOutOfPlayUntilPlacedAgain(string model)
    {
        var sim = Create(model, ("cue", -0.3, 0), ("1", 0, 0));
        sim.RemoveBall(new BallId(1));
        var removed = State(sim, "1");
        Assert.True(removed.IsPocketed);
        Assert.Equal(-1, removed.Pocket);
        // The cue ball rolls through where the 1 stood without touching it.
        sim.Strike(new ShotSpec(0.4, 0));
        sim.AdvanceTo(60);
        Assert.DoesNotContain(sim.Events.AsSpan().ToArray(), e => e.Kind == EventKind.BallBall);
        Assert.True(State(sim, "cue").Position.X > 0.1);
        // Its old place no longer counts against a placement, and it comes back in play.
        sim.PlaceBall(new BallId(1), new Vec3(-0.9, -0.3, 0));
        AssertAt(sim, "1", -0.9, -0.3);
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void ASpottedBallGoesOnTheFootSpotWhenItIsFree(string model)
    {
        var sim = Create(model, ("cue", -0.6, 0), ("9", 0.2, 0.3));
        var at = Billiards.Core.Rules.Ruleset.SpotOnFootSpot(sim, new BallId(9));
        Assert.Equal(new Vec3(1.27 / 2, 0, sim.BallRadius), at);
        AssertAt(sim, "9", 1.27 / 2, 0);
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void ASpottedBallGoesAsCloseBehindTheSpotAsItFits(string model)
    {
        double r = ModelRegistry.Get(model).BallRadius(PhysicsParams.Default);
        double spot = 1.27 / 2;
        // A ball R off the long axis and R behind the spot blocks |x - (spot + R)| < sqrt(4R^2 - R^2).
        var sim = Create(model, ("cue", -0.6, 0), ("5", spot + r, r), ("9", 0.2, 0.3));
        var at = Billiards.Core.Rules.Ruleset.SpotOnFootSpot(sim, new BallId(9));
        // The thesis model keeps the blocking ball in single-precision centimetres.
        Assert.Equal(spot + r + Math.Sqrt(3) * r, at.X, Math.Max(Tolerance(model), 1e-12));
        Assert.Equal(0, at.Y);
        AssertAt(sim, "9", at.X, 0);
        Assert.Equal(2 * r, (State(sim, "9").Position - State(sim, "5").Position).XY.Length, 1e-6);
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void ASpottedBallGoesInFrontOfTheSpotWhenTheAxisBehindItIsFull(string model)
    {
        double r = ModelRegistry.Get(model).BallRadius(PhysicsParams.Default);
        double spot = 1.27 / 2, limit = 1.27 - r;
        // Balls touching in a line from the spot to the foot cushion: no gap of 2R is left behind it.
        var balls = new List<(string, double, double)> { ("cue", -0.6, 0), ("15", 0.2, 0.3) };
        int n = 1;
        for (double x = spot; x <= limit; x += 2 * r)
        {
            balls.Add((n++.ToString(CultureInfo.InvariantCulture), x, 0));
        }
        Assert.True(balls[^1].Item2 + 4 * r > limit, "the line reaches the cushion");
        var sim = Create(model, [.. balls]);
        var at = Billiards.Core.Rules.Ruleset.SpotOnFootSpot(sim, new BallId(15));
        Assert.Equal(spot - 2 * r, at.X, Math.Max(Tolerance(model), 1e-12));
        AssertAt(sim, "15", at.X, 0);
    }

    [Theory]
    [InlineData("eight-ball-break.json")]
    [InlineData("thesis-eight-ball-break.json")]
    public void ARerackPutsTheRackBackWhereTheSceneStartedIt(string file)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file));
        var sim = SimulationFactory.Create(scene);
        sim.Strike(scene.Shot!);
        sim.AdvanceTo(120);
        Assert.True(sim.IsAtRest);
        // The cue ball may have stopped inside the rack's triangle: take it out first.
        sim.RemoveBall(PoolBalls.Cue);
        sim.Rerack(scene.Rack!);
        foreach (var ball in scene.Balls.Where(b => !PoolBalls.IsCue(b.Id)))
        {
            AssertAt(sim, ball.Id.ToString(), ball.Position.X, ball.Position.Y);
        }
        sim.PlaceBall(PoolBalls.Cue, Initializer.HeadSpot(scene.Table, sim.BallRadius), PlacementRegion.Kitchen);
        AssertAt(sim, "cue", scene.Balls[0].Position.X, scene.Balls[0].Position.Y);
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void FourteenBallsAreReRackedWithTheApexEmpty(string model)
    {
        var ids = Enumerable.Range(1, 15).Select(i => ($"{i}", -1.0 + 0.06 * i, -0.5)).Prepend(("cue", -0.9, 0.3)).ToArray();
        var sim = Create(model, ids);
        var fourteen = Enumerable.Range(1, 14).Select(i => new BallId(i)).ToList();
        sim.Rerack(fourteen, RackGame.EightBall, apexEmpty: true);
        var spots = Initializer.RackSpots(RackGame.EightBall, sim.Table, sim.BallRadius);
        for (int k = 0; k < 14; k++)
        {
            AssertAt(sim, fourteen[k].ToString(), spots[k + 1].X, spots[k + 1].Y);
        }
        Assert.Null(sim.PlacementProblem(new BallId(15), spots[0]));
        Assert.Throws<PlacementException>(() => sim.Rerack(Enumerable.Range(1, 15).Select(i => new BallId(i)).ToList(), RackGame.EightBall, apexEmpty: true));
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void ASetIsPlacedWholeOrNotAtAll(string model)
    {
        var sim = Create(model, ("cue", -0.6, 0), ("1", 0.3, 0.2), ("2", 0.5, -0.2));
        var e = Assert.Throws<PlacementException>(() => sim.PlaceBalls([(new BallId(1), new Vec3(0, 0, 0)), (new BallId(2), new Vec3(0.03, 0, 0))]));
        Assert.StartsWith("ball \"2\" overlaps ball \"1\"", e.Message);
        AssertAt(sim, "1", 0.3, 0.2);
        AssertAt(sim, "2", 0.5, -0.2);
        sim.PlaceBalls([(new BallId(1), new Vec3(0, 0, 0)), (new BallId(2), new Vec3(0.06, 0, 0))]);
        AssertAt(sim, "1", 0, 0);
        AssertAt(sim, "2", 0.06, 0);
    }

    [Fact]
    public void APocketedCueBallIsPlacedBackInHandAndTheStandardEnginePredictsItAnew()
    {
        // From the centre straight at the foot-left pocket's capture circle.
        var sim = Create("standard", ("cue", 0, 0), ("1", -0.5, 0));
        var pocket = TableGeometry.Build(sim.Table, sim.BallRadius).Pockets[PoolPockets.FootLeft.Index].Centre;
        double aim = Math.Atan2(pocket.Y, pocket.X) * 180 / Math.PI;
        sim.Strike(new ShotSpec(3, aim));
        sim.AdvanceTo(60);
        Assert.True(State(sim, "cue").IsPocketed);
        Assert.Equal(PoolPockets.FootLeft.Index, State(sim, "cue").Pocket);
        sim.PlaceBall(PoolBalls.Cue, new Vec3(-1.0, 0, 0), PlacementRegion.Kitchen);
        AssertAt(sim, "cue", -1.0, 0);
        sim.Strike(new ShotSpec(1, 0));
        sim.AdvanceTo(60);
        Assert.Contains(sim.Events.AsSpan().ToArray(), e => e.Kind == EventKind.BallBall && e.A == PoolBalls.Cue && e.B == new BallId(1));
    }
}
