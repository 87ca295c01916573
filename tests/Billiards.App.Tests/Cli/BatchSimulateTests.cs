using System.Buffers;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;
using Billiards.App.Cli;
using Billiards.Tools;

namespace Billiards.App.Tests.Cli;

/// <summary><c>simulate --batch</c>: the same results as single runs, in order, with error records for bad lines.</summary>
public sealed partial class BatchSimulateTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("billiards-batch-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string Path_(string name) => Path.Combine(_dir, name);

    // A result without white space and with stats.wall_ms (a measurement) blanked: what must be equal.
    internal static string Comparable(string json)
    {
        using var doc = JsonDocument.Parse(json);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            doc.RootElement.WriteTo(w);
        }
        return WallMs().Replace(Encoding.UTF8.GetString(stream.ToArray()), "\"wall_ms\":_");
    }

    [GeneratedRegex("\"wall_ms\":[-0-9.eE+]+")]
    private static partial Regex WallMs();

    private string SingleRun(string sceneLine, int k)
    {
        string scene = Path_($"scene-{k}.json");
        File.WriteAllText(scene, sceneLine);
        var (code, stdout, stderr) = CliRun.Run("simulate", scene);
        Assert.True(code == 0, stderr);
        return stdout;
    }

    [Fact]
    public void EveryLineEqualsTheSingleRunOfItsScene()
    {
        const int count = 40;
        string input = Path_("in.jsonl"), output = Path_("out.jsonl");
        File.WriteAllText(input, RandomScenes.Lines(2027, count));
        var (code, _, stderr) = CliRun.Run("simulate", "--batch", input, "--out", output, "--threads", "2");

        Assert.True(code == 0, stderr);
        Assert.Contains($"simulate --batch: {count} scenes, 0 failed", stderr, StringComparison.Ordinal);
        string[] scenes = File.ReadAllLines(input), results = File.ReadAllLines(output);
        Assert.Equal(count, results.Length);
        for (int k = 0; k < count; k++)
        {
            // One line each, the single run's result once white space is gone.
            Assert.Equal(Comparable(SingleRun(scenes[k], k)), Comparable(results[k]));
            // And the line is already that text: one line, no white space.
            Assert.Equal(Comparable(results[k]), WallMs().Replace(results[k], "\"wall_ms\":_"));
        }
        // The scenes are not all alike: the order of the lines is tested, not a constant.
        Assert.True(results.Select(Comparable).Distinct().Count() > count / 2);
    }

    [Fact]
    public void TheThreadCountDoesNotChangeAResult()
    {
        string input = Path_("in.jsonl");
        File.WriteAllText(input, RandomScenes.Lines(11, 30));
        string[] outputs = ["1", "3"];
        foreach (string threads in outputs)
        {
            var (code, _, stderr) = CliRun.Run("simulate", "--batch", input, "--out", Path_($"out-{threads}.jsonl"), "--threads", threads);
            Assert.True(code == 0, stderr);
            Assert.Contains($"on {threads} thread", stderr, StringComparison.Ordinal);
        }
        Assert.Equal(File.ReadAllLines(Path_("out-1.jsonl")).Select(Comparable), File.ReadAllLines(Path_("out-3.jsonl")).Select(Comparable));
    }

    [Fact]
    public void ABadLineGivesItsErrorRecordAndTheOthersStillRun()
    {
        string[] good = RandomScenes.Lines(5, 2).TrimEnd('\n').Split('\n');
        string badField = good[0].Replace("\"speed\":", "\"sped\":", StringComparison.Ordinal);
        string input = Path_("in.jsonl"), output = Path_("out.jsonl");
        File.WriteAllLines(input, [good[0], "{ not json", good[1], "", badField]);
        var (code, stdout, stderr) = CliRun.Run("simulate", "--batch", input, "--out", output, "--threads", "2");

        Assert.Equal(BatchSimulation.SomeFailed, code);
        Assert.Equal("", stdout);
        Assert.Contains("simulate --batch: 5 scenes, 3 failed", stderr, StringComparison.Ordinal);
        string[] lines = File.ReadAllLines(output);
        Assert.Equal(5, lines.Length);
        Assert.Equal(Comparable(SingleRun(good[0], 0)), Comparable(lines[0]));
        Assert.Equal(Comparable(SingleRun(good[1], 1)), Comparable(lines[2]));
        foreach (var (index, expected) in new[] { (1, $"{input}:2: $: not valid JSON"), (3, $"{input}:4: $: an empty line"), (4, $"{input}:5: $.shot") })
        {
            using var record = JsonDocument.Parse(lines[index]);
            Assert.Equal(index + 1, record.RootElement.GetProperty("line").GetInt32());
            string error = record.RootElement.GetProperty("error").GetString()!;
            Assert.StartsWith(expected, error, StringComparison.Ordinal);
            Assert.DoesNotContain('\n', error);
            Assert.Equal(2, record.RootElement.EnumerateObject().Count());
        }
        // The same message as a single run of the bad scene prints.
        string scene = Path_("bad.json");
        File.WriteAllText(scene, badField);
        var single = CliRun.Run("simulate", scene);
        Assert.Equal(2, single.Code);
        using (var record = JsonDocument.Parse(lines[4]))
        {
            Assert.Equal(single.Err.Trim().Replace(scene, $"{input}:5", StringComparison.Ordinal), record.RootElement.GetProperty("error").GetString());
        }
    }

    [Theory]
    [InlineData("--threads 0", "--threads 0: expected 1 to 1024")]
    [InlineData("--threads 2000", "--threads 2000")]
    [InlineData("no-out", "--out OUT.jsonl is required")]
    [InlineData("missing-input", "cannot read the file")]
    [InlineData("empty-input", "the file is empty")]
    [InlineData("scene-too", "give either a scene or --batch")]
    public void ABadArgumentIsOneLineExitTwoAndNothingWritten(string bad, string expected)
    {
        string input = Path_("in.jsonl"), output = Path_("out.jsonl");
        File.WriteAllText(input, bad == "empty-input" ? "" : RandomScenes.Lines(1, 2));
        var args = new List<string> { "simulate", "--batch", bad == "missing-input" ? Path_("none.jsonl") : input };
        if (bad != "no-out")
        {
            args.AddRange(["--out", output]);
        }
        if (bad.StartsWith("--threads", StringComparison.Ordinal))
        {
            args.AddRange(bad.Split(' '));
        }
        if (bad == "scene-too")
        {
            args.Add(input);
        }
        var (code, stdout, stderr) = CliRun.Run([.. args]);

        Assert.Equal(CommandLine.BadInput, code);
        Assert.Equal("", stdout);
        Assert.Single(stderr.TrimEnd('\n').Split('\n'));
        Assert.Contains(expected, stderr, StringComparison.Ordinal);
        Assert.False(File.Exists(output));
        Assert.Single(Directory.GetFiles(_dir));
    }

    private sealed class FailingStream : MemoryStream
    {
        public override void Write(ReadOnlySpan<byte> buffer) => throw new IOException("disk full");
    }

    private sealed class FailingReader(string first) : TextReader
    {
        private int _calls;

        public override string? ReadLine() => Interlocked.Increment(ref _calls) == 1 ? first : throw new IOException("read error");
    }

    [Fact]
    public void AFailureToWriteOrReadStopsEveryWorkerAndPassesTheErrorOn()
    {
        string scenes = RandomScenes.Lines(3, 600);
        var run = new BatchSimulation(new(), new(), 2, TextWriter.Null);
        var written = Assert.Throws<IOException>(() => run.Run(new StringReader(scenes), "in.jsonl", 600, new FailingStream()));
        Assert.Equal("disk full", written.Message);
        var read = Assert.Throws<IOException>(() => new BatchSimulation(new(), new(), 2, TextWriter.Null).Run(new FailingReader(scenes.Split('\n')[0]), "in.jsonl", 2, new MemoryStream()));
        Assert.Equal("read error", read.Message);
    }
    // Exact bytes a thread allocates, so that the test measures only its own work.
    private static long Allocated(Action action)
    {
        long before = GC.GetAllocatedBytesForCurrentThread();
        action();
        return GC.GetAllocatedBytesForCurrentThread() - before;
    }

    [Fact]
    public void ALineAllocatesLittleAndItsOutputNothing()
    {
        string[] scenes = RandomScenes.Lines(2027, 200).TrimEnd('\n').Split('\n');
        var run = new BatchSimulation(new(), new(), 1, TextWriter.Null);
        using var json = new Utf8JsonWriter(Stream.Null);
        var buffer = new ArrayBufferWriter<byte>();
        // A first pass warms the code and the buffer (which keeps the largest result's size).
        foreach (var line in scenes)
        {
            Assert.True(run.RunLine(line, "in.jsonl", 1, json, buffer));
        }
        long total = 0;
        foreach (var line in scenes)
        {
            total += Allocated(() => run.RunLine(line, "in.jsonl", 1, json, buffer));
        }
        // The scene's loading and run allocate (its objects, the simulation and its event log);
        // the budget is what they took when it was set and a little room: 41.7 KB a scene, 48.4 KB
        // once tables' pockets and ball sets became data.
        Assert.InRange(total / scenes.Length, 1, 50 * 1024);

        // Writing the result allocates nothing once the writer and the buffer are warm.
        var scene = Billiards.Core.Scenes.SceneLoader.Parse(scenes[0], "in.jsonl:1");
        var outcome = Billiards.Core.Scenes.SimulationRunner.Run(scene, new());
        void Write()
        {
            buffer.ResetWrittenCount();
            json.Reset(buffer);
            Billiards.Core.Scenes.ResultWriter.Write(json, outcome);
            json.Flush();
        }
        Write();
        Assert.Equal(0, Allocated(Write));
        // And it is what a single run writes (on one line).
        Assert.Equal(Billiards.Core.Scenes.ResultWriter.ToUtf8(outcome, indented: false)[..^1], buffer.WrittenSpan.ToArray());
    }
}
