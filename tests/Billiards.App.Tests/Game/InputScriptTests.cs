using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Platform;

namespace Billiards.App.Tests.Game;

public class InputScriptTests
{
    [Fact]
    public void AScriptParsesEveryAction()
    {
        var script = InputScript.Parse("""
            { "format": "billiards-input-script/1", "duration": 5, "events": [
              { "t": 0.5, "key_down": "s" }, { "t": 0.5, "key_up": "F1" },
              { "t": 1, "mouse_move": [10, 20] }, { "t": 1.5, "mouse_move_by": [0, -4.5] },
              { "t": 2, "mouse_down": "left" }, { "t": 2, "mouse_up": "right" }, { "t": 3, "wheel": 2 }, { "t": 3, "wheel": -1 } ] }
            """, "s.json");
        Assert.Equal(5, script.Duration);
        Assert.Equal(
            ["key_down S", "key_up F1", "mouse_move 10,20", "mouse_move_by 0,-4.5", "mouse_down left", "mouse_up right", "wheel 2", "wheel -1"],
            script.Events.Select(e => e.Describe()));
        Assert.Equal(Key.S, script.Events[0].Key);
        Assert.Equal(MouseButton.Right, script.Events[5].Button);
    }

    [Fact]
    public void TheDurationDefaultsToASecondAfterTheLastEvent()
    {
        var script = InputScript.Parse("""{ "format": "billiards-input-script/1", "events": [ { "t": 2.5, "key_down": "P" } ] }""", "s.json");
        Assert.Equal(3.5, script.Duration);
    }

    [Theory]
    [InlineData("""{ "events": [] }""", "s.json: $.format: expected")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "key_down": "S" } ] }""", "s.json: $.events[0].t: missing")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "t": 1, "key_down": "Nope" } ] }""", "s.json: $.events[0].key_down: unknown key")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "t": 2, "key_down": "S" }, { "t": 1, "key_up": "S" } ] }""", "s.json: $.events[1].t: 1 s is before")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "t": 1, "key_down": "S", "wheel": 1 } ] }""", "s.json: $.events[0].wheel: one action")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "t": 1, "mouse_move": [1] } ] }""", "s.json: $.events[0].mouse_move: expected [x, y]")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "t": 1, "mouse_down": "thumb" } ] }""", "s.json: $.events[0].mouse_down: expected")]
    [InlineData("""{ "format": "billiards-input-script/1", "duration": 1, "events": [ { "t": 2, "wheel": 1 } ] }""", "s.json: $.duration: 1 s ends before")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "t": 1, "wheel": -101 } ] }""", "s.json: $.events[0].wheel: expected a number of notches from -100 to 100")]
    [InlineData("""[1]""", "s.json: $: expected an object")]
    [InlineData("""{ "format": "billiards-input-script/1", "events": [ { "t": 1, "wait": "keys" } ] }""", "s.json: $.events[0].wait: expected \"rest\"")]
    [InlineData("""{ "format": "billiards-input-script/1", "speed": 0, "events": [] }""", "s.json: $.speed: expected a number above 0, at most 64")]
    [InlineData("""{ "format": "billiards-input-script/1", "speed": 65, "events": [] }""", "s.json: $.speed: expected a number above 0, at most 64")]
    public void ABadScriptNamesTheFileThePathAndTheProblem(string json, string expected)
    {
        var e = Assert.Throws<CliException>(() => InputScript.Parse(json, "s.json"));
        Assert.StartsWith(expected, e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void AWaitHoldsTheScriptsClockUntilTheGameRestsAndTheEventsAfterItKeepTheirSpacing()
    {
        var script = InputScript.Parse("""
            { "format": "billiards-input-script/1", "speed": 8, "duration": 1.5, "events": [
              { "t": 0.1, "key_down": "Space" }, { "t": 0.2, "wait": "rest" }, { "t": 0.5, "key_down": "X" } ] }
            """, "s.json");
        Assert.Equal(8, script.Speed);
        Assert.Equal("wait rest", script.Events[1].Describe());
        var window = new FakeWindow();
        var manual = new ManualClock { Now = 100 };
        var clock = new ScriptClock(manual);
        using var scripted = new ScriptedInput(window, script, clock);
        bool rest = false;
        scripted.IsAtRest = () => rest;
        var seen = new List<(Key Key, double Time)>();
        window.KeyDown += _ => { };
        scripted.KeyDown += k => seen.Add((k, clock.Now));
        scripted.Pump(100);
        scripted.Pump(100.3);               // Space raised; the wait holds
        Assert.Equal([Key.Space], seen.Select(s => s.Key));
        scripted.Pump(105);                 // still rolling: nothing, and the script does not end
        Assert.Single(seen);
        Assert.False(scripted.Finished);
        rest = true;
        scripted.Pump(110);                 // at rest: the script's clock goes on from the wait's 0.2 s
        Assert.Single(seen);
        Assert.Equal(110 - 100 - 0.2, scripted.Waited, 9);
        scripted.Pump(110.29);
        Assert.Single(seen);
        scripted.Pump(110.31);              // 0.3 s after the wait, as in the script
        Assert.Equal(Key.X, seen[^1].Key);
        Assert.Equal(110.3, seen[^1].Time, 9); // stamped with its own time, waits included
        Assert.False(scripted.Finished);
        scripted.Pump(111.31);
        Assert.True(scripted.Finished);
    }

    [Fact]
    public void ScriptedEventsAreRaisedAtTheFirstFrameAtOrAfterTheirTimeStampedWithTheirOwnTime()
    {
        var script = InputScript.Parse("""
            { "format": "billiards-input-script/1", "duration": 1, "events": [
              { "t": 0.010, "key_down": "S" }, { "t": 0.020, "mouse_move_by": [0, 5] }, { "t": 0.050, "mouse_move_by": [0, 5] } ] }
            """, "s.json");
        var window = new FakeWindow();
        var clock = new ScriptClock(new ManualClock { Now = 100 });
        using var scripted = new ScriptedInput(window, script, clock);
        var seen = new List<(string, double)>();
        scripted.KeyDown += k => seen.Add(($"down {k}", clock.Now));
        scripted.MouseMove += p => seen.Add(($"move {p.Y}", clock.Now));
        scripted.Pump(100);          // zero
        Assert.Empty(seen);
        scripted.Pump(100.030);      // the first two are due
        Assert.Equal([("down S", 100.010), ("move 5", 100.020)], seen);
        scripted.Pump(100.040);
        Assert.Equal(2, seen.Count);
        scripted.Pump(100.060);
        Assert.Equal(("move 10", 100.050), seen[^1]);
        Assert.False(scripted.Finished);
        scripted.Pump(101.0);
        Assert.True(scripted.Finished);
        Assert.Equal(100, clock.Now); // the override is gone between events
    }

    [Fact]
    public void StatsCountFramesPerSecondAndTheDelayOfEachInputToTheFrameThatShowsIt()
    {
        var stats = new FrameStats();
        // Frames every 10 ms for 2.5 s; an input at 0.505 s is raised in the frame started at 0.51.
        for (int k = 0; k <= 250; k++)
        {
            stats.FrameStarted(10 + (k * 0.01));
            if (k == 51)
            {
                stats.InputRaised(new ScriptEvent(0.505, ScriptAction.KeyDown, Key.F1));
            }
        }
        Assert.Empty(stats.Seconds()); // the last frame has not ended yet
        stats.Ended(10 + 2.51);
        var seconds = stats.Seconds();
        Assert.Equal(2, seconds.Count);
        Assert.InRange(seconds[0].Frames, 99, 101);
        Assert.Equal(10, seconds[0].P50, 6);
        var input = Assert.Single(stats.Inputs());
        Assert.Equal(51, input.Frame);
        Assert.Equal(1, input.DelayFrames);
        Assert.Equal(15, input.DelayMs, 6); // shown at 0.52 s
        Assert.Equal(2, FrameStats.Percentile([1, 2, 3, 4], 0.5));
        Assert.Equal(4, FrameStats.Percentile([1, 2, 3, 4], 0.99));
    }

    [Fact]
    public void StatsGiveEachSecondTheProcessorTimeOfItsFramesOverTheirNumber()
    {
        var stats = new FrameStats();
        // Frames every 10 ms; the process takes 4 ms of processor time a frame in the first
        // second and 12 ms in the second.
        double cpu = 50;
        for (int k = 0; k < 200; k++)
        {
            stats.FrameStarted(10 + (k * 0.01), cpu);
            cpu += k < 100 ? 0.004 : 0.012;
        }
        stats.Ended(12.0, cpu);
        var seconds = stats.Seconds();
        Assert.Equal(2, seconds.Count);
        Assert.Equal(4, seconds[0].CpuMs, 6);
        Assert.Equal(12, seconds[1].CpuMs, 6);
        string json = System.Text.Encoding.UTF8.GetString(stats.ToJson("s.json", null, 1280, 720, "test"));
        Assert.Contains("\"cpu_ms_per_frame\": 8", json, StringComparison.Ordinal);
        Assert.Contains("\"cpu_ms_per_frame_max\": 12", json, StringComparison.Ordinal);
        // Without processor times the figure is left out, not written as zero.
        var plain = new FrameStats();
        plain.FrameStarted(1);
        plain.Ended(2.5);
        Assert.True(double.IsNaN(plain.Seconds()[0].CpuMs));
        Assert.DoesNotContain("cpu_ms", System.Text.Encoding.UTF8.GetString(plain.ToJson("s.json", null, 1, 1, null)), StringComparison.Ordinal);
    }
}

public class PlayDisplayTests
{
    [Fact]
    public void PlayWithoutADisplayIsAnEnvironmentProblemNamedInOneLine()
    {
        if (OperatingSystem.IsWindows() || OperatingSystem.IsMacOS())
        {
            PlayCommand.RequireDisplay(_ => null); // nothing to check there
            return;
        }
        var e = Assert.Throws<EnvironmentException>(() => PlayCommand.RequireDisplay(_ => null));
        Assert.Contains("no display", e.Message, StringComparison.Ordinal);
        Assert.Equal((CommandLine.OneLine("billiards: " + e.Message), CommandLine.Failure), CommandLine.Classify(e));
        PlayCommand.RequireDisplay(name => name == "DISPLAY" ? ":0" : null);
        PlayCommand.RequireDisplay(name => name == "WAYLAND_DISPLAY" ? "wayland-0" : null);
    }
}
