using System.Diagnostics;
using System.Globalization;
using System.Text;
using System.Text.Json;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>simulate --batch IN.jsonl --out OUT.jsonl [--threads N]</c>: one scene per input line, one
/// result per output line in the input's order, each line exactly what <c>simulate</c> prints for
/// that scene on its own, written on one line (only <c>stats.wall_ms</c>, a measurement, differs
/// from run to run).
/// </summary>
/// <remarks>
/// A line that is not a usable scene (or whose run fails) gives an error record in its place,
/// <c>{"line": N, "error": "IN.jsonl:N: $.path: problem"}</c>, and the other lines still run; the
/// exit code is then <see cref="SomeFailed"/>. The scenes run in chunks: every thread takes the
/// chunk's next scene as it finishes one, and a chunk is written (in order) before the next is
/// read, so that memory stays bounded by a chunk however long the input. Each scene's run is
/// independent of the others and of the thread that runs it: the results are the same at any
/// thread count.
/// </remarks>
public sealed class BatchSimulation(SceneOverrides overrides, RunOptions options, int threads, TextWriter progress)
{
    /// <summary>Exit code when some lines gave an error record (the others' results are written).</summary>
    public const int SomeFailed = 3;

    /// <summary>The most threads accepted.</summary>
    public const int MaxThreads = 1024;

    private static readonly TimeSpan ProgressInterval = TimeSpan.FromSeconds(2);
    private readonly Lock _progressLock = new();

    /// <summary>Scenes run (lines read).</summary>
    public int Lines { get; private set; }

    /// <summary>Lines that gave an error record.</summary>
    public int Failed { get; private set; }

    /// <summary>
    /// Runs every line of <paramref name="input"/> (its name <paramref name="source"/> is what the
    /// error records name) and writes one line per input line to <paramref name="output"/>.
    /// </summary>
    /// <param name="input">The scenes, one per line.</param>
    /// <param name="source">The input's name, for the error records.</param>
    /// <param name="total">The number of lines, for the progress lines.</param>
    /// <param name="output">Where the results go, one per line.</param>
    public void Run(TextReader input, string source, int total, Stream output)
    {
        ArgumentNullException.ThrowIfNull(input);
        ArgumentNullException.ThrowIfNull(output);
        int chunkSize = Math.Max(256, threads * 64);
        var texts = new List<string>(chunkSize);
        var clock = Stopwatch.StartNew();
        var lastReport = TimeSpan.Zero;
        int done = 0;
        while (true)
        {
            texts.Clear();
            string? line;
            while (texts.Count < chunkSize && (line = input.ReadLine()) is not null)
            {
                texts.Add(line);
            }
            if (texts.Count == 0)
            {
                break;
            }
            int first = Lines + 1;
            var results = new byte[texts.Count][];
            int failed = 0;
            Parallel.For(0, texts.Count, new ParallelOptions { MaxDegreeOfParallelism = threads }, i =>
            {
                results[i] = RunLine(texts[i], source, first + i, out bool ok);
                if (!ok)
                {
                    Interlocked.Increment(ref failed);
                }
                int n = Interlocked.Increment(ref done);
                if (clock.Elapsed - lastReport >= ProgressInterval)
                {
                    lock (_progressLock)
                    {
                        if (clock.Elapsed - lastReport >= ProgressInterval)
                        {
                            lastReport = clock.Elapsed;
                            progress.WriteLine(string.Create(CultureInfo.InvariantCulture, $"simulate --batch: {n}/{total} scenes, {clock.Elapsed.TotalSeconds:F0} s"));
                        }
                    }
                }
            });
            foreach (var bytes in results)
            {
                output.Write(bytes);
            }
            Lines += texts.Count;
            Failed += failed;
        }
        double seconds = clock.Elapsed.TotalSeconds;
        progress.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"simulate --batch: {Lines} scenes, {Failed} failed, {seconds:F2} s, {(seconds > 0 ? Lines / seconds : 0):F0} scenes/s on {threads} thread{(threads == 1 ? "" : "s")}"));
    }

    /// <summary>
    /// The output line of one input line: the scene's result on one line, or its error record.
    /// <paramref name="ok"/> is false for an error record.
    /// </summary>
    public byte[] RunLine(string text, string source, int lineNumber, out bool ok)
    {
        ArgumentNullException.ThrowIfNull(text);
        string name = string.Create(CultureInfo.InvariantCulture, $"{source}:{lineNumber}");
        try
        {
            if (string.IsNullOrWhiteSpace(text))
            {
                throw new SceneException(name, "$", "an empty line; expected a scene (one per line)");
            }
            var scene = SceneLoader.Parse(text, name, overrides);
            ok = true;
            return ResultWriter.ToUtf8(SimulationRunner.Run(scene, options), indented: false);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // The line's message as the single run would print it (the scene's name is its line).
            ok = false;
            return ErrorRecord(lineNumber, CommandLine.OneLine(CommandLine.Classify(e).Message));
        }
    }

    /// <summary>The error record of a line: <c>{"line": N, "error": "..."}</c> and a line break.</summary>
    public static byte[] ErrorRecord(int lineNumber, string message)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            w.WriteStartObject();
            w.WriteNumber("line", lineNumber);
            w.WriteString("error", message);
            w.WriteEndObject();
        }
        stream.WriteByte((byte)'\n');
        return stream.ToArray();
    }

    /// <summary>Counts the lines of a file as <see cref="TextReader.ReadLine"/> splits them.</summary>
    public static int CountLines(string path)
    {
        int count = 0;
        using var reader = new StreamReader(path, Encoding.UTF8);
        while (reader.ReadLine() is not null)
        {
            count++;
        }
        return count;
    }
}
