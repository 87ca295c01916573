using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Practice;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Tests.Practice;

/// <summary>The shipped drills (assets/drills): each parses, and its reference shots meet its goal in the game's physics.</summary>
public class DrillTests
{
    private static string Folder => Path.Combine(AssetFolder.Assets, "drills");

    private static List<string> DrillNames() =>
        [.. Directory.EnumerateFiles(Folder, "*.json").Select(f => Path.GetFileNameWithoutExtension(f)).Order(StringComparer.Ordinal)];

    public static TheoryData<string> Names() => [.. DrillNames()];

    // A pocket of the pool tables by its name in files.
    private static PocketId Pocket(string name) =>
        TableSpec.FromPreset("pool-9ft").Pockets.TryParse(name, out var pocket) ? pocket : throw new ArgumentException(name);

    private static Drill Load(string name)
    {
        string path = Path.Combine(Folder, name + ".json");
        return Drill.Parse(File.ReadAllText(path), path);
    }

    [Fact]
    public void AtLeastTwelveDrillsShipWithTheClassicShotsAmongThem()
    {
        var names = DrillNames();
        Assert.True(names.Count >= 17, $"{names.Count} drills");
        foreach (string classic in (string[])["stop-shot", "draw-shot", "follow-shot", "bank-shot", "kick-shot", "cut-60", "position-route",
            "corner-five", "ticky", "umbrella", "reverse-end", "long-short-long"])
        {
            Assert.Contains(classic, names);
        }
        var drills = names.Select(Load).ToList();
        // The three kinds of goal: a pot, a pot with the cue ball in a zone, a sequence.
        Assert.Contains(drills, d => d.Sequence.Count == 1 && d.Zone is null);
        Assert.Contains(drills, d => d.Sequence.Count == 1 && d.Zone is not null);
        Assert.Contains(drills, d => d.Sequence.Count >= 3);
    }

    /// <summary>
    /// Plays a drill's reference shots as the window does: each from a new simulation of the balls
    /// left at rest by the one before, judged by <see cref="DrillAttempt"/>.
    /// </summary>
    internal static (DrillOutcome? Outcome, List<DrillShot> Shots) PlayReference(Drill drill)
    {
        var attempt = new DrillAttempt(drill);
        var position = drill.Scene;
        var shots = new List<DrillShot>();
        foreach (var shot in drill.Reference)
        {
            var sim = SimulationFactory.Create(position);
            sim.Strike(shot);
            sim.AdvanceTo(120);
            Assert.True(sim.IsAtRest);
            var played = DrillShot.Of(sim, position.Balls.Select(b => b.Id), position.CueBall);
            shots.Add(played);
            if (attempt.Judge(played) is { } outcome)
            {
                return (outcome, shots);
            }
            var balls = new List<BallSetup>();
            for (int i = 0; i < sim.Ids.Count; i++)
            {
                if (!sim.Balls[i].IsOutOfPlay)
                {
                    balls.Add(new BallSetup(sim.Ids[i], sim.Balls[i].Position, Vec3.Zero, Vec3.Zero));
                }
            }
            position = position with { Balls = balls, Rack = null };
        }
        return (attempt.Outcome, shots);
    }

    [Theory]
    [MemberData(nameof(Names))]
    public void EveryDrillIsAchievableItsReferenceShotsMeetItsGoal(string name)
    {
        var drill = Load(name);
        Assert.Equal(name, drill.Name);
        var (outcome, shots) = PlayReference(drill);
        if (drill.Carom)
        {
            // One shot scores the point: both balls, three cushions before the second, none off the table.
            Assert.NotNull(outcome);
            Assert.True(outcome.Success, $"{name}: {outcome.Reason}");
            var shot = Assert.Single(shots);
            Assert.True(shot.Contacts.IsPoint);
            Assert.Empty(shot.Potted);
            return;
        }
        Assert.Equal(drill.Sequence.Count, drill.Reference.Count);
        Assert.NotNull(outcome);
        Assert.True(outcome.Success, $"{name}: {outcome.Reason}");
        Assert.Equal(drill.Sequence.Count, outcome.Potted);
        Assert.Equal(drill.Sequence.Count, shots.Count);
        for (int k = 0; k < shots.Count; k++)
        {
            // Each shot potted its ball and no other, in the drill's pocket when it names one.
            var potted = Assert.Single(shots[k].Potted);
            Assert.Equal(drill.Sequence[k], potted.Ball);
            if (drill.PocketFor(k) != PocketId.None)
            {
                Assert.Equal(drill.PocketFor(k), potted.Pocket);
            }
        }
        if (drill.Zone is { } zone)
        {
            Assert.True(zone.Contains(shots[^1].CueAtRest));
            Assert.Equal(zone.DistanceTo(shots[^1].CueAtRest), outcome.ZoneDistance);
        }
    }

    /// <summary>
    /// The three-cushion patterns: each reference shot takes its pattern's route, the struck ball's
    /// balls (B, the sequence's first ball first) and cushions by the table's names for them, up to
    /// the second ball.
    /// </summary>
    [Theory]
    [InlineData("corner-five", "left-foot foot right-foot B B")]
    [InlineData("long-short-long", "B left-head head right-head B")]
    [InlineData("umbrella", "right-foot B left-foot foot B")]
    [InlineData("ticky", "B left-foot right-foot foot B")]
    [InlineData("reverse-end", "B foot left-head head B")]
    public void TheThreeCushionDrillsAreTheirPatterns(string name, string route)
    {
        var drill = Load(name);
        Assert.True(drill.Carom);
        var sim = SimulationFactory.Create(drill.Scene);
        sim.Strike(drill.Reference[0], drill.Scene.CueBall);
        sim.AdvanceTo(120);
        var white = drill.Scene.CueBall;
        var steps = new List<string>();
        var met = new List<BallId>();
        foreach (var e in sim.Events.AsSpan())
        {
            if (met.Count == 2)
            {
                break;
            }
            if (e.Kind == EventKind.BallCushion && e.A == white)
            {
                steps.Add(sim.FeatureName(e.Kind, e.Feature));
            }
            else if (e.Kind == EventKind.BallBall && (e.A == white || e.B == white))
            {
                var other = e.A == white ? e.B : e.A;
                if (!met.Contains(other))
                {
                    met.Add(other);
                    steps.Add("B");
                }
            }
        }
        Assert.Equal(route, string.Join(' ', steps));
        Assert.Equal(drill.Sequence, met);
    }

    [Fact]
    public void TheTechniqueDrillsNeedTheirTechniqueDrawBelowCentreFollowAboveAndTheKickCannotGoStraight()
    {
        Assert.All(Load("draw-shot").Reference, s => Assert.True(s.TipHeight < 0, "a draw is struck below centre"));
        Assert.All(Load("stop-shot").Reference, s => Assert.True(s.TipHeight < 0, "a stop shot is struck below centre"));
        Assert.All(Load("follow-shot").Reference, s => Assert.True(s.TipHeight > 0, "a follow is struck above centre"));

        // The kick: the 2 lies on the straight line from the cue ball to the 1.
        var kick = Load("kick-shot").Scene;
        Vec3 At(string id) => kick.Balls.First(b => b.Id.ToString() == id).Position;
        var cue = At("cue");
        var one = At("1");
        var two = At("2");
        var line = (one - cue).Normalized();
        double along = Vec3.Dot(two - cue, line);
        double off = ((two - cue) - (line * along)).LengthXY;
        Assert.InRange(along, 0, (one - cue).LengthXY);
        Assert.True(off < 2 * kick.BallRadius, $"the 2 is {off:0.000} m off the line");
        // And the reference kicks: the cue ball meets a cushion before any ball.
        List<SimEvent> kicked = Collisions(Load("kick-shot"));
        var cueBall = kick.CueBall;
        Assert.Equal(EventKind.BallCushion, kicked.First(e => e.A == cueBall || e.B == cueBall).Kind);

        // The bank: once struck, the 1 meets a cushion before it drops.
        List<SimEvent> banked = Collisions(Load("bank-shot"));
        var one1 = new BallId(1);
        int hit = banked.FindIndex(e => e.Kind == EventKind.BallBall && (e.A == one1 || e.B == one1));
        var next = banked.Skip(hit + 1).First(e => e.A == one1 || e.B == one1);
        Assert.NotEqual(-1, hit);
        Assert.Equal(EventKind.BallCushion, next.Kind);

        // The 60 degree cut: between the cue ball's path to the ghost ball and the 1's path to the pocket.
        var cut = Load("cut-60");
        var c = cut.Scene.Balls.First(b => b.Id == cut.Scene.CueBall).Position;
        var b1 = cut.Scene.Balls.First(b => b.Id == new BallId(1)).Position;
        var pocket = TableGeometry.Build(cut.Scene.Table, cut.Scene.BallRadius).Pockets.ToArray().First(p => p.Pocket == Pocket("foot-left").Index).Centre with { Z = b1.Z };
        var u = (pocket - b1).Normalized();
        var ghost = b1 - (u * (2 * cut.Scene.BallRadius));
        double angle = Math.Acos(Vec3.Dot((ghost - c).Normalized(), u)) * 180 / Math.PI;
        Assert.True(angle is > 59.5 and < 60.5, $"a cut of {angle:0.00} deg");
    }

    // The collisions and pockets of a drill's first reference shot, in time order.
    private static List<SimEvent> Collisions(Drill drill)
    {
        var sim = SimulationFactory.Create(drill.Scene);
        sim.Strike(drill.Reference[0]);
        sim.AdvanceTo(120);
        return [.. sim.Events.AsSpan().ToArray().Where(e => e.Kind is EventKind.BallBall or EventKind.BallCushion or EventKind.BallPocket)];
    }

    private static Drill TwoShotDrill(DrillZone? zone = null) => new(
        "test", "Test", "Pot the 1 then the 2.",
        SceneLoader.Parse("""{ "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] }, { "id": "1", "position": [0.5, 0] }, { "id": "2", "position": [0.5, 0.3] } ] }""", "t.json"),
        [new BallId(1), new BallId(2)], zone, []) { Pockets = [Pocket("foot-left"), PocketId.None] };

    [Fact]
    public void AnAttemptFailsOnAScratchAWrongBallAWrongPocketOrAnExtraBallAndSucceedsOnlyInOrder()
    {
        var one = new BallId(1);
        var two = new BallId(2);
        DrillOutcome? Judge(params DrillShot[] shots)
        {
            var a = new DrillAttempt(TwoShotDrill());
            DrillOutcome? o = null;
            foreach (var s in shots)
            {
                o = a.Judge(s);
            }
            return o;
        }
        var here = new Vec3(0, 0, 0);
        Assert.False(Judge(new DrillShot([(one, Pocket("foot-left"))], false, here))!.Success);
        Assert.False(Judge(new DrillShot([(two, Pocket("foot-left"))], true, here))!.Success);
        Assert.False(Judge(new DrillShot([(one, Pocket("foot-right"))], true, here))!.Success);
        Assert.False(Judge(new DrillShot([(one, Pocket("foot-left")), (two, Pocket("foot-left"))], true, here))!.Success);
        // The first ball right: the attempt goes on; then the second in any pocket.
        var attempt = new DrillAttempt(TwoShotDrill());
        Assert.Null(attempt.Judge(new DrillShot([(one, Pocket("foot-left"))], true, here)));
        Assert.Equal(two, attempt.Next);
        var done = attempt.Judge(new DrillShot([(two, Pocket("head-right"))], true, here))!;
        Assert.True(done.Success);
        Assert.Equal(2, done.Potted);
        Assert.Null(attempt.Next);
        Assert.Throws<InvalidOperationException>(() => attempt.Judge(new DrillShot([], true, here)));
    }

    [Fact]
    public void AZoneIsMetInsideItsRadiusAndTheDistanceFromItsCentreIsReported()
    {
        var zone = new DrillZone(new Vec3(0.2, 0.1, 0), 0.05);
        var one = new BallId(1);
        var two = new BallId(2);
        var inside = new DrillAttempt(TwoShotDrill(zone));
        inside.Judge(new DrillShot([(one, Pocket("foot-left"))], true, new Vec3(1, 1, 0)));
        var o = inside.Judge(new DrillShot([(two, Pocket("side-left"))], true, new Vec3(0.23, 0.14, 0.028)))!;
        Assert.True(o.Success);
        Assert.Equal(0.05, o.ZoneDistance!.Value, 12);
        var outside = new DrillAttempt(TwoShotDrill(zone));
        outside.Judge(new DrillShot([(one, Pocket("foot-left"))], true, Vec3.Zero));
        var miss = outside.Judge(new DrillShot([(two, Pocket("side-left"))], true, new Vec3(0.2, 0.2, 0)))!;
        Assert.False(miss.Success);
        Assert.Equal(0.1, miss.ZoneDistance!.Value, 12);
    }

    [Theory]
    [InlineData("""{ "format": "billiards-drill/1", "title": "T", "goal": "G", "scene": { "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] } ] }, "sequence": ["1"] }""", "$.sequence[0]")]
    [InlineData("""{ "format": "billiards-drill/1", "title": "T", "goal": "G", "scene": { "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] }, { "id": "1", "position": [0.5, 0] } ] }, "sequence": ["1"], "pockets": ["middle"] }""", "$.pockets[0]")]
    [InlineData("""{ "format": "billiards-drill/1", "title": "T", "goal": "G", "scene": { "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] }, { "id": "1", "position": [0.5, 0] } ] }, "sequence": ["1"], "reference": [] }""", "$.reference")]
    [InlineData("""{ "format": "billiards-drill/1", "title": "T", "goal": "G", "scene": { "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] }, { "id": "1", "position": [0.5, 0] } ] }, "sequence": ["1"], "zone": { "centre": [9, 0], "radius": 0.1 } }""", "$.zone")]
    [InlineData("""{ "format": "billiards-drill/1", "title": "T", "goal": "G", "scene": { "format": "billiards-scene/1", "balls": [ { "id": "cue", "position": [0, 0] }, { "id": "1", "position": [0.5, 0] } ] }, "sequence": ["1"], "extra": 1 }""", "$.extra")]
    public void ABadDrillIsOneErrorNamingTheField(string json, string at)
    {
        var e = Assert.Throws<SceneException>(() => Drill.Parse(json, "bad.json"));
        Assert.Equal(at, e.JsonPath);
        Assert.StartsWith("bad.json", e.Message, StringComparison.Ordinal);
    }
}
