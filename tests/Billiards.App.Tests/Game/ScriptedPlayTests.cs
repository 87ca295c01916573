using System.Text.Json;
using Billiards.App.Cli;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.App.Tests.Rendering;
using Billiards.Core.Scenes;

namespace Billiards.App.Tests.Game;

/// <summary>
/// <c>play --script --stats</c> in a real GLFW window (under Xvfb when there is no display). Frame
/// rates depend on the machine and are not asserted; the stats file's structure and the delay in
/// frames from each input to the frame that shows it are.
/// </summary>
[Collection("GL")]
public class ScriptedPlayTests
{
    [Fact]
    public void AShortBreakScriptPlaysInAWindowAndItsStatsShowEveryInputOnTheNextFrame()
    {
        TestDisplay.Ensure();
        string script = Path.Combine(AssetFolder.Assets, "scripts", "break-short.json");
        string stats = Path.Combine(Path.GetTempPath(), $"stats-{Guid.NewGuid():N}.json");
        try
        {
            int code = PlayCommand.Play(AssetFolder.Scene("eight-ball.json"), PlatformWiring.Open, options: new PlayCommand.PlayOptions(script, stats));
            Assert.Equal(0, code);

            var parsed = InputScript.Load(script);
            using var doc = JsonDocument.Parse(File.ReadAllText(stats));
            var root = doc.RootElement;
            Assert.Equal(FrameStats.Format, root.GetProperty("format").GetString());
            Assert.Equal(1280, root.GetProperty("width").GetInt32());
            Assert.Equal(720, root.GetProperty("height").GetInt32());

            // One sample per whole second of the script, numbered from 0; percentiles ordered.
            var seconds = root.GetProperty("per_second").EnumerateArray().ToList();
            // The script closes the game at its duration; the last frame may run on a little.
            Assert.True(seconds.Count >= (int)parsed.Duration - 1, $"{seconds.Count} seconds");
            int frames = 0;
            for (int i = 0; i < seconds.Count; i++)
            {
                Assert.Equal(i, seconds[i].GetProperty("second").GetInt32());
                // The window drew in every whole second of the script (a second without a frame
                // is a frozen game); how many frames is the machine's and not asserted.
                int fps = seconds[i].GetProperty("fps").GetInt32();
                Assert.True(fps > 0, $"second {i}: no frame");
                frames += fps;
                var ms = seconds[i].GetProperty("frame_ms");
                double p50 = ms.GetProperty("p50").GetDouble(), p95 = ms.GetProperty("p95").GetDouble();
                double p99 = ms.GetProperty("p99").GetDouble(), max = ms.GetProperty("max").GetDouble();
                Assert.True(p50 <= p95 && p95 <= p99 && p99 <= max, $"second {i}: percentiles out of order");
            }
            // Frames that started after the last whole second are in no sample.
            Assert.True(frames <= root.GetProperty("frames").GetInt32());
            Assert.True(frames > 0);

            // Every scripted event reached the screen, on the frame after it happened.
            var inputs = root.GetProperty("inputs").EnumerateArray().ToList();
            Assert.Equal(parsed.Events.Count, inputs.Count);
            int total = root.GetProperty("frames").GetInt32();
            for (int i = 0; i < inputs.Count; i++)
            {
                // Raised in script order, each in a frame that was followed by the one showing it.
                int frame = inputs[i].GetProperty("frame").GetInt32();
                Assert.InRange(frame, i == 0 ? 0 : inputs[i - 1].GetProperty("frame").GetInt32(), total - 2);
                Assert.Equal(parsed.Events[i].Describe(), inputs[i].GetProperty("event").GetString());
                Assert.Equal(1, inputs[i].GetProperty("delay_frames").GetInt32());
                Assert.True(inputs[i].GetProperty("delay_ms").GetDouble() > 0);
            }
            // The script implies at least a frame for each distinct frame its events were raised in, and one to show the last.
            Assert.True(total > inputs.Select(x => x.GetProperty("frame").GetInt32()).Distinct().Count());
            var summary = root.GetProperty("summary");
            Assert.Equal(seconds.Min(x => x.GetProperty("fps").GetInt32()), summary.GetProperty("min_fps").GetInt32());
            Assert.Equal(parsed.Events.Count, summary.GetProperty("inputs").GetInt32());
            Assert.True(summary.GetProperty("input_delay_median_frames").GetDouble() <= 2);
        }
        finally
        {
            File.Delete(stats);
        }
    }
}
