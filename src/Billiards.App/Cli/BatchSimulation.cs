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
/// exit code is then <see cref="SomeFailed"/>. Each scene's run is independent of the others and
/// of the thread that runs it: the results are the same at any thread count.
/// </remarks>
public sealed class BatchSimulation(SceneOverrides overrides, RunOptions options, int threads, TextWriter progress)
{
    /// <summary>Exit code when some lines gave an error record (the others' results are written).</summary>
    public const int SomeFailed = 3;

    /// <summary>The most threads accepted.</summary>
    public const int MaxThreads = 1024;

    private static readonly TimeSpan ProgressInterval = TimeSpan.FromSeconds(2);

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
        // Scenes take from a tenth of a millisecond to seconds: each worker takes the next line as
        // soon as it is free (no barrier where fast workers wait for a slow scene), and the results
        // are written in the input's order by this thread. A worker may run at most Window lines
        // ahead of the writer, which bounds the memory held by results waiting for their turn.
        int window = Math.Max(256, threads * 64);
        using var slots = new SemaphoreSlim(window);
        using var stop = new CancellationTokenSource();
        // Monitor, not Lock: the writer waits on it for the next result.
        var gate = new object();
        var reading = new Lock();
        var pending = new Dictionary<int, (byte[] Bytes, bool Ok)>();
        int read = 0, running = threads;
        Exception? failure = null;
        var clock = Stopwatch.StartNew();
        var cpuAtStart = Process.GetCurrentProcess().TotalProcessorTime;

        void Work()
        {
            try
            {
                while (true)
                {
                    slots.Wait(stop.Token);
                    string? line;
                    int index;
                    lock (reading)
                    {
                        line = input.ReadLine();
                        index = read;
                        if (line is not null)
                        {
                            read++;
                        }
                    }
                    if (line is null)
                    {
                        return;
                    }
                    var bytes = RunLine(line, source, index + 1, out bool ok);
                    lock (gate)
                    {
                        pending[index] = (bytes, ok);
                        Monitor.PulseAll(gate);
                    }
                }
            }
            catch (OperationCanceledException)
            {
                // The writer failed; its exception is the one reported.
            }
            catch (Exception e)
            {
                lock (gate)
                {
                    failure ??= e;
                }
                stop.Cancel();
            }
            finally
            {
                lock (gate)
                {
                    running--;
                    Monitor.PulseAll(gate);
                }
            }
        }

        var workers = new Thread[threads];
        for (int t = 0; t < threads; t++)
        {
            workers[t] = new Thread(Work) { IsBackground = true, Name = $"batch-{t}" };
            workers[t].Start();
        }
        var lastReport = TimeSpan.Zero;
        try
        {
            for (int next = 0; ; next++)
            {
                (byte[] Bytes, bool Ok) result;
                lock (gate)
                {
                    while (!pending.ContainsKey(next) && failure is null && !(running == 0 && next >= read))
                    {
                        Monitor.Wait(gate);
                    }
                    if (failure is not null)
                    {
                        throw failure;
                    }
                    if (!pending.Remove(next, out result))
                    {
                        break;
                    }
                }
                output.Write(result.Bytes);
                slots.Release();
                Lines++;
                Failed += result.Ok ? 0 : 1;
                if (clock.Elapsed - lastReport >= ProgressInterval)
                {
                    lastReport = clock.Elapsed;
                    progress.WriteLine(string.Create(CultureInfo.InvariantCulture, $"simulate --batch: {Lines}/{total} scenes, {Failed} failed, {clock.Elapsed.TotalSeconds:F0} s"));
                }
            }
        }
        finally
        {
            stop.Cancel();
            foreach (var worker in workers)
            {
                worker.Join();
            }
        }
        double seconds = clock.Elapsed.TotalSeconds;
        // The processor time beside the wall clock: on a machine shared with other work the
        // scenes per processor second show what the threads got done when they did run.
        double cpu = (Process.GetCurrentProcess().TotalProcessorTime - cpuAtStart).TotalSeconds;
        progress.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"simulate --batch: {Lines} scenes, {Failed} failed, {seconds:F2} s, {(seconds > 0 ? Lines / seconds : 0):F0} scenes/s on {threads} thread{(threads == 1 ? "" : "s")} ({cpu:F2} s of processor time)"));
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
