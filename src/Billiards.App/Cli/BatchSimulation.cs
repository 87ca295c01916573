using System.Buffers;
using System.Diagnostics;
using System.Runtime.ExceptionServices;
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
        // soon as it is free (no barrier where fast workers wait for a slow scene) and writes its
        // result into the ring slot of its line, a buffer the slot keeps from one use to the next.
        // The worker that fills the slot of the next line to write writes it and every filled
        // slot after it: no writer thread to wake for each result, no lock held while a scene
        // runs, and a worker waits only when it is a whole ring ahead of the oldest line still
        // running, which bounds the memory held by results waiting for their turn.
        int window = Math.Max(256, threads * 64);
        var slots = new Slot[window];
        for (int i = 0; i < window; i++)
        {
            slots[i] = new Slot();
        }
        using var free = new SemaphoreSlim(window);
        using var stop = new CancellationTokenSource();
        var reading = new Lock();
        var writing = new Lock();
        int read = 0, written = 0;
        bool endOfInput = false;
        Exception? failure = null;
        var clock = Stopwatch.StartNew();
        var lastReport = TimeSpan.Zero;
        var cpuAtStart = Process.GetCurrentProcess().TotalProcessorTime;
        long allocatedAtStart = GC.GetTotalAllocatedBytes(precise: true);
        int collectionsAtStart = GC.CollectionCount(0);
        var pausedAtStart = GC.GetTotalPauseDuration();

        bool Ready(int index) => Volatile.Read(ref slots[index % window].Line) == index;

        // Writes the filled slots from the next line on. Whoever holds the lock writes for every
        // worker; one that finds it held leaves its slot to the holder, who looks again after
        // letting go. The fences after letting go and after filling a slot make sure one of the
        // two sees the other: the holder the filled slot, or the filler the lock free.
        void Drain()
        {
            while (Ready(Volatile.Read(ref written)))
            {
                if (!writing.TryEnter())
                {
                    return;
                }
                try
                {
                    while (Ready(written))
                    {
                        var slot = slots[written % window];
                        output.Write(slot.Bytes.WrittenSpan);
                        Lines++;
                        Failed += slot.Ok ? 0 : 1;
                        slot.Release();
                        Volatile.Write(ref written, written + 1);
                        free.Release();
                        if (clock.Elapsed - lastReport >= ProgressInterval)
                        {
                            lastReport = clock.Elapsed;
                            progress.WriteLine(string.Create(CultureInfo.InvariantCulture, $"simulate --batch: {Lines}/{total} scenes, {Failed} failed, {clock.Elapsed.TotalSeconds:F0} s"));
                        }
                    }
                }
                finally
                {
                    writing.Exit();
                }
                Interlocked.MemoryBarrier();
            }
        }

        void Work()
        {
            var json = new Utf8JsonWriter(Stream.Null);
            try
            {
                while (true)
                {
                    free.Wait(stop.Token);
                    string? line = null;
                    int index = 0;
                    lock (reading)
                    {
                        if (!endOfInput)
                        {
                            line = input.ReadLine();
                            index = read;
                            if (line is null)
                            {
                                endOfInput = true;
                            }
                            else
                            {
                                read++;
                            }
                        }
                    }
                    if (line is null)
                    {
                        free.Release();
                        return;
                    }
                    var slot = slots[index % window];
                    slot.Ok = RunLine(line, source, index + 1, json, slot.Bytes);
                    // A full fence, the other half of Drain's: either this worker sees the lock
                    // free, or its holder sees the slot filled.
                    Interlocked.Exchange(ref slot.Line, index);
                    Drain();
                }
            }
            catch (OperationCanceledException)
            {
                // Another worker failed; its exception is the one reported.
            }
            catch (Exception e)
            {
                Interlocked.CompareExchange(ref failure, e, null);
                stop.Cancel();
            }
            finally
            {
                json.Dispose();
            }
        }

        var workers = new Thread[threads];
        for (int t = 0; t < threads; t++)
        {
            workers[t] = new Thread(Work) { IsBackground = true, Name = $"batch-{t}" };
            workers[t].Start();
        }
        foreach (var worker in workers)
        {
            worker.Join();
        }
        if (failure is not null)
        {
            ExceptionDispatchInfo.Throw(failure);
        }
        // Every line read was run, and the last to fill its slot wrote it or left it to a holder
        // who looked again: nothing is left, but a last look costs nothing.
        Drain();
        if (written != read)
        {
            throw new InvalidOperationException($"simulate --batch: {read - written} results were not written");
        }
        double seconds = clock.Elapsed.TotalSeconds;
        // The processor time beside the wall clock: on a machine shared with other work the
        // scenes per processor second show what the threads got done when they did run. The
        // allocation and the collections it caused, for the same reason: they do not depend on
        // the machine's load.
        double cpu = (Process.GetCurrentProcess().TotalProcessorTime - cpuAtStart).TotalSeconds;
        long allocated = GC.GetTotalAllocatedBytes(precise: true) - allocatedAtStart;
        progress.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"simulate --batch: {Lines} scenes, {Failed} failed, {seconds:F2} s, {(seconds > 0 ? Lines / seconds : 0):F0} scenes/s on {threads} thread{(threads == 1 ? "" : "s")} ({cpu:F2} s of processor time; {allocated / Math.Max(1, Lines) / 1024.0:F1} KB allocated a scene, {GC.CollectionCount(0) - collectionsAtStart} collections, {(GC.GetTotalPauseDuration() - pausedAtStart).TotalMilliseconds:F0} ms paused)"));
    }

    // One line's place in the ring: the line it holds (-1 before its first), its output and
    // whether that is a result. Buffers stay with their slot, so a batch allocates them once.
    private sealed class Slot
    {
        // Above this a slot lets its buffer go after writing it: one huge result (a long --sample
        // run) does not keep its memory for the rest of the batch.
        private const int KeptCapacity = 1 << 20;

        public int Line = -1;
        public bool Ok;
        public ArrayBufferWriter<byte> Bytes = new(4096);

        public void Release()
        {
            if (Bytes.Capacity > KeptCapacity)
            {
                Bytes = new ArrayBufferWriter<byte>(4096);
            }
        }
    }

    /// <summary>
    /// Writes the output line of one input line to <paramref name="output"/> (cleared first): the
    /// scene's result on one line, or its error record; false for an error record.
    /// <paramref name="json"/> is the caller's writer, reused from line to line (its white space
    /// decides the output's: the default, none).
    /// </summary>
    public bool RunLine(string text, string source, int lineNumber, Utf8JsonWriter json, ArrayBufferWriter<byte> output)
    {
        ArgumentNullException.ThrowIfNull(text);
        ArgumentNullException.ThrowIfNull(json);
        ArgumentNullException.ThrowIfNull(output);
        string name = string.Create(CultureInfo.InvariantCulture, $"{source}:{lineNumber}");
        try
        {
            if (string.IsNullOrWhiteSpace(text))
            {
                throw new SceneException(name, "$", "an empty line; expected a scene (one per line)");
            }
            var scene = SceneLoader.Parse(text, name, overrides);
            var outcome = SimulationRunner.Run(scene, options);
            Start(json, output);
            ResultWriter.Write(json, outcome);
            End(json, output);
            return true;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // The line's message as the single run would print it (the scene's name is its line).
            Start(json, output);
            ErrorRecord(json, lineNumber, CommandLine.OneLine(CommandLine.Classify(e).Message));
            End(json, output);
            return false;
        }
    }

    private static void Start(Utf8JsonWriter json, ArrayBufferWriter<byte> output)
    {
        output.ResetWrittenCount();
        json.Reset(output);
    }

    private static void End(Utf8JsonWriter json, ArrayBufferWriter<byte> output)
    {
        json.Flush();
        output.Write("\n"u8);
    }

    /// <summary>The error record of a line: <c>{"line": N, "error": "..."}</c>, without the line break.</summary>
    public static void ErrorRecord(Utf8JsonWriter json, int lineNumber, string message)
    {
        ArgumentNullException.ThrowIfNull(json);
        json.WriteStartObject();
        json.WriteNumber("line", lineNumber);
        json.WriteString("error", message);
        json.WriteEndObject();
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
