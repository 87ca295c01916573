using System.Text.Json;

namespace Billiards.App.Game;

/// <summary>
/// What <c>play --stats</c> writes (format <c>billiards-play-stats/1</c>): the frame rate of every
/// whole second and its frame-time percentiles, and for each scripted input event the delay to
/// the first frame that shows it, in frames and ms.
/// </summary>
/// <remarks>
/// Times are taken at the start of each frame. The loop swaps and waits for the frame to finish
/// (one frame in flight) before the next one starts, so a frame is on screen at the next frame's
/// start: that is when it "shows". A scripted event is raised at the start of the first frame at
/// or after its time, so the frame that shows it is that frame; its delay in frames counts the
/// frames started after the event up to and including that one.
/// </remarks>
public sealed class FrameStats
{
    /// <summary>The format tag.</summary>
    public const string Format = "billiards-play-stats/1";

    private readonly List<double> _starts = [];
    private readonly List<double> _cpu = [];
    private double _endCpu = double.NaN;
    private readonly List<(ScriptEvent Event, double Due, int Frame)> _inputs = [];
    private double? _zero;
    private double? _end;

    /// <summary>Frames recorded.</summary>
    public int Frames => _starts.Count;

    /// <summary>
    /// Records the start of a frame at clock time <paramref name="now"/> (s); the first sets time
    /// zero. <paramref name="cpu"/> is the process's processor time then (s,
    /// <see cref="Platform.CpuClock"/>), or NaN when not measured.
    /// </summary>
    public void FrameStarted(double now, double cpu = double.NaN)
    {
        _zero ??= now;
        _starts.Add(now - _zero.Value);
        _cpu.Add(cpu);
    }

    /// <summary>Records the end of the last frame (its swap finished) at clock time <paramref name="now"/> (s), with the processor time then (s) if measured.</summary>
    public void Ended(double now, double cpu = double.NaN)
    {
        if (_zero is { } zero)
        {
            _end = now - zero;
            _endCpu = cpu;
        }
    }

    // The processor time frame k took (s), from its start to the next one's: NaN when not measured.
    private double CpuOf(int k) => (k + 1 < _cpu.Count ? _cpu[k + 1] : k + 1 == _cpu.Count ? _endCpu : double.NaN) - _cpu[k];

    // When frame k was on screen: the next frame's start, or the end for the last frame.
    private double? Shown(int k) => k + 1 < _starts.Count ? _starts[k + 1] : k + 1 == _starts.Count ? _end : null;

    /// <summary>
    /// Records that a scripted event was raised in the frame started last; <paramref name="due"/>
    /// is when it was due, in the stats' time (s from the first frame): its script time, plus the
    /// time the script stood still in waits before it (<see cref="ScriptedInput.Waited"/>).
    /// </summary>
    public void InputRaised(ScriptEvent e, double? due = null) => _inputs.Add((e, due ?? e.Time, _starts.Count - 1));

    /// <summary>One whole second's figures.</summary>
    /// <param name="Second">Which second (from 0).</param>
    /// <param name="Frames">Frames started in it: its frame rate (frames/s).</param>
    /// <param name="P50">Median frame time (ms) of those frames.</param>
    /// <param name="P95">95th percentile (ms).</param>
    /// <param name="P99">99th percentile (ms).</param>
    /// <param name="Max">Longest frame (ms).</param>
    /// <param name="CpuMs">
    /// The processor time of those frames, every thread's, divided by their number (ms a frame),
    /// or NaN when not measured: what a frame costs, which a busy machine does not inflate as it
    /// does the frame times (on two cores, frames of 33 ms of processor time cannot come at 60 a
    /// second; drawing threads overlap, so a frame's wall time can be less than its processor time).
    /// </param>
    public sealed record SecondSample(int Second, int Frames, double P50, double P95, double P99, double Max, double CpuMs = double.NaN);

    /// <summary>One input event's delay.</summary>
    /// <param name="Time">Its time in the script (s).</param>
    /// <param name="Event">What it was.</param>
    /// <param name="Frame">Index of the frame that shows it.</param>
    /// <param name="DelayFrames">Frames from the event to the one that shows it, inclusive.</param>
    /// <param name="DelayMs">From the event's time to that frame on screen (ms).</param>
    public sealed record InputDelay(double Time, string Event, int Frame, int DelayFrames, double DelayMs);

    /// <summary>The whole seconds recorded, up to the last frame's end.</summary>
    public List<SecondSample> Seconds()
    {
        var result = new List<SecondSample>();
        if (_starts.Count == 0 || Shown(_starts.Count - 1) is not { } last)
        {
            return result;
        }
        int whole = (int)Math.Floor(last);
        for (int s = 0; s < whole; s++)
        {
            var times = new List<double>();
            double cpu = 0;
            for (int k = 0; k < _starts.Count; k++)
            {
                if (_starts[k] >= s && _starts[k] < s + 1 && Shown(k) is { } shown)
                {
                    times.Add((shown - _starts[k]) * 1000);
                    cpu += CpuOf(k);
                }
            }
            times.Sort();
            result.Add(new SecondSample(s, times.Count, Percentile(times, 0.5), Percentile(times, 0.95), Percentile(times, 0.99), times.Count > 0 ? times[^1] : 0,
                times.Count > 0 ? 1000 * cpu / times.Count : double.NaN));
        }
        return result;
    }

    /// <summary>The delays of the scripted events whose frame has been shown.</summary>
    public List<InputDelay> Inputs()
    {
        var result = new List<InputDelay>();
        foreach (var (e, due, frame) in _inputs)
        {
            if (frame < 0 || Shown(frame) is not { } shown)
            {
                continue; // the frame that shows it never reached the screen
            }
            int firstAfter = _starts.FindIndex(t => t >= due);
            int delayFrames = frame - (firstAfter < 0 ? frame : firstAfter) + 1;
            result.Add(new InputDelay(e.Time, e.Describe(), frame, delayFrames, (shown - due) * 1000));
        }
        return result;
    }

    /// <summary>Nearest-rank percentile of sorted values; 0 for none.</summary>
    public static double Percentile(IReadOnlyList<double> sorted, double p)
    {
        if (sorted.Count == 0)
        {
            return 0;
        }
        int rank = (int)Math.Ceiling(p * sorted.Count);
        return sorted[Math.Clamp(rank - 1, 0, sorted.Count - 1)];
    }

    /// <summary>The stats as JSON.</summary>
    /// <param name="scene">The scene played.</param>
    /// <param name="script">The script, or null.</param>
    /// <param name="width">Framebuffer width (pixels).</param>
    /// <param name="height">Framebuffer height (pixels).</param>
    /// <param name="renderer">The GL renderer's name, or null.</param>
    public byte[] ToJson(string scene, string? script, int width, int height, string? renderer)
    {
        var seconds = Seconds();
        var inputs = Inputs();
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("format", Format);
            w.WriteString("scene", scene);
            if (script is null)
            {
                w.WriteNull("script");
            }
            else
            {
                w.WriteString("script", script);
            }
            w.WriteNumber("width", width);
            w.WriteNumber("height", height);
            w.WriteString("renderer", renderer ?? "unknown");
            w.WriteNumber("frames", _starts.Count);
            w.WriteNumber("seconds_recorded", seconds.Count);
            w.WriteStartArray("per_second");
            foreach (var s in seconds)
            {
                w.WriteStartObject();
                w.WriteNumber("second", s.Second);
                w.WriteNumber("fps", s.Frames);
                w.WriteStartObject("frame_ms");
                w.WriteNumber("p50", Math.Round(s.P50, 3));
                w.WriteNumber("p95", Math.Round(s.P95, 3));
                w.WriteNumber("p99", Math.Round(s.P99, 3));
                w.WriteNumber("max", Math.Round(s.Max, 3));
                w.WriteEndObject();
                if (double.IsFinite(s.CpuMs))
                {
                    w.WriteNumber("cpu_ms_per_frame", Math.Round(s.CpuMs, 3));
                }
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartObject("summary");
            w.WriteNumber("min_fps", seconds.Count > 0 ? seconds.Min(s => s.Frames) : 0);
            w.WriteNumber("first_ten_fps", Math.Round(MeanFps(seconds.Take(10)), 3));
            w.WriteNumber("last_ten_fps", Math.Round(MeanFps(seconds.TakeLast(10)), 3));
            var cpus = seconds.Where(s => double.IsFinite(s.CpuMs)).ToList();
            if (cpus.Count > 0)
            {
                // All frames' processor time over their number, and the costliest second's.
                w.WriteNumber("cpu_ms_per_frame", Math.Round(cpus.Sum(s => s.CpuMs * s.Frames) / Math.Max(1, cpus.Sum(s => s.Frames)), 3));
                w.WriteNumber("cpu_ms_per_frame_max", Math.Round(cpus.Max(s => s.CpuMs), 3));
            }
            var delays = inputs.Select(i => (double)i.DelayFrames).Order().ToList();
            var ms = inputs.Select(i => i.DelayMs).Order().ToList();
            w.WriteNumber("inputs", inputs.Count);
            w.WriteNumber("input_delay_median_frames", Percentile(delays, 0.5));
            w.WriteNumber("input_delay_max_frames", delays.Count > 0 ? delays[^1] : 0);
            w.WriteNumber("input_delay_median_ms", Math.Round(Percentile(ms, 0.5), 3));
            w.WriteNumber("input_delay_max_ms", Math.Round(ms.Count > 0 ? ms[^1] : 0, 3));
            w.WriteEndObject();
            w.WriteStartArray("inputs");
            foreach (var i in inputs)
            {
                w.WriteStartObject();
                w.WriteNumber("t", i.Time);
                w.WriteString("event", i.Event);
                w.WriteNumber("frame", i.Frame);
                w.WriteNumber("delay_frames", i.DelayFrames);
                w.WriteNumber("delay_ms", Math.Round(i.DelayMs, 3));
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteEndObject();
        }
        return stream.ToArray();
    }

    private static double MeanFps(IEnumerable<SecondSample> seconds)
    {
        var list = seconds.ToList();
        return list.Count == 0 ? 0 : list.Average(s => s.Frames);
    }
}
