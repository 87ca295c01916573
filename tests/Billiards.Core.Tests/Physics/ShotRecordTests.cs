using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;
using static Billiards.Core.Tests.Standard.StandardTestKit;

namespace Billiards.Core.Tests.Physics;

/// <summary>A strike opens a shot in the log; pocket drops carry their speed; the record reads one shot.</summary>
public class ShotRecordTests
{
    public static TheoryData<string, string?> Breaks => new()
    {
        { "eight-ball-break.json", "exact" },
        { "eight-ball-break.json", "event" },
        { "eight-ball-break.json", "euler" },
        { "nine-ball-break.json", "exact" },
        { "thesis-eight-ball-break.json", null },
        { "thesis-nine-ball-break.json", null },
    };

    [Theory]
    [MemberData(nameof(Breaks))]
    public void ABreakStartsWithItsCueStrikeAndEveryDropHasASpeed(string file, string? integrator)
    {
        var scene = SceneLoader.Load(AssetFolder.Scene(file), new SceneOverrides(null, integrator, null));
        var outcome = SimulationRunner.Run(scene, new RunOptions());
        var events = outcome.Simulation.Events.AsSpan();

        Assert.Equal(EventKind.CueStrike, events[0].Kind);
        Assert.Equal(0, events[0].Time);
        Assert.Equal(PoolBalls.Cue, events[0].A);
        Assert.Equal(scene.Shot!.Speed, events[0].Speed);
        int drops = 0;
        for (int i = 1; i < events.Length; i++)
        {
            Assert.NotEqual(EventKind.CueStrike, events[i].Kind);
            if (events[i].Kind == EventKind.BallPocket)
            {
                drops++;
                // A ball drops moving, and no faster than the break sent the cue ball (cue speed
                // times the largest cue-to-ball speed ratio, 2 m_c / (m_c + m_b) < 2).
                Assert.InRange(events[i].Speed, 1e-6, 2 * scene.Shot.Speed);
                Assert.NotEqual(PocketId.None, outcome.Simulation.Pocket(events[i]));
            }
        }
        // Euler's coarse break pockets nothing in this rack; the event-exact breaks all pocket a ball.
        Assert.True(drops > 0 || integrator == "euler", "the break pockets at least one ball");
    }

    [Fact]
    public void TheResultJsonBeginsWithTheCueStrikeAndGivesEveryDropASpeed()
    {
        var scene = SceneLoader.Load(AssetFolder.Scene("eight-ball-break.json"));
        var json = JsonDocument.Parse(ResultWriter.ToUtf8(SimulationRunner.Run(scene, new RunOptions())));
        var events = json.RootElement.GetProperty("events");
        var first = events[0];
        Assert.Equal("cue-strike", first.GetProperty("type").GetString());
        Assert.Equal("cue", first.GetProperty("balls")[0].GetString());
        Assert.Equal(scene.Shot!.Speed, first.GetProperty("speed").GetDouble());
        foreach (var e in events.EnumerateArray().Where(e => e.GetProperty("type").GetString() == "ball-pocket"))
        {
            Assert.True(e.GetProperty("speed").GetDouble() > 0);
            Assert.True(PoolPockets.Set.TryParse(e.GetProperty("pocket").GetString(), out _));
        }
    }

    [Fact]
    public void TheRecordNamesTheFirstBallTheCueBallTouches()
    {
        // Ball 5 stands nearer the cue ball's start but off the line; ball 3 is on it.
        var sim = Create("event", 1.0 / 250, """{ "preset": "pocketless" }""", """{ "speed": 2.0, "aim_deg": 0 }""", "",
            Ball("cue", -0.8, 0), Ball("3", 0, 0), Ball("5", -0.5, 0.2));
        sim.AdvanceTo(600);
        var record = ShotRecord.LastShot(sim, new Billiards.Core.Cue.ShotSpec(2.0, 0));
        Assert.Equal(new BallId(3), record.FirstContact);
        Assert.Equal(EventKind.CueStrike, record.Events[0].Kind);
        Assert.Equal(1, record.FirstContactIndex);
        Assert.False(record.IsPocketedAfter(new BallId(3)));
        Assert.Equal(0, record.StartTime);
        Assert.Equal(sim.Time, record.EndTime);
    }

    [Fact]
    public void AShotThatMissesEveryBallHasNoFirstContact()
    {
        var sim = Create("event", 1.0 / 250, """{ "preset": "pocketless" }""", """{ "speed": 1.0, "aim_deg": 90 }""", "",
            Ball("cue", -0.8, 0), Ball("3", 0, 0));
        sim.AdvanceTo(600);
        var record = ShotRecord.LastShot(sim, null);
        Assert.Null(record.FirstContact);
        Assert.Equal(-1, record.FirstContactIndex);
        Assert.Contains(record.Events.ToArray(), e => e.Kind == EventKind.BallCushion);
    }

    [Fact]
    public void ASecondShotsRecordStartsAtItsOwnStrike()
    {
        var sim = Create("event", 1.0 / 250, """{ "preset": "pocketless" }""", """{ "speed": 1.0, "aim_deg": 90 }""", "",
            Ball("cue", -0.8, 0), Ball("3", 0, 0));
        sim.AdvanceTo(600);
        double secondStart = sim.Time;
        int before = sim.Events.Count;
        sim.Strike(new Billiards.Core.Cue.ShotSpec(1.5, 0));
        sim.AdvanceTo(1200);
        var record = ShotRecord.LastShot(sim, null);
        Assert.Equal(sim.Events.Count - before, record.EventCount);
        Assert.Equal(secondStart, record.StartTime);
        Assert.Equal(EventKind.CueStrike, record.Events[0].Kind);
        Assert.Equal(1.5, record.Events[0].Speed);
    }

    [Fact]
    public void PocketNamesRoundTrip()
    {
        foreach (var p in PoolPockets.All)
        {
            Assert.True(PoolPockets.Set.TryParse(p.ToName(), out var back));
            Assert.Equal(p, back);
            Assert.Equal(PoolPockets.Set.NameOf(p.Index), p.ToName());
        }
        Assert.False(PoolPockets.Set.TryParse("middle", out _));
    }
}
