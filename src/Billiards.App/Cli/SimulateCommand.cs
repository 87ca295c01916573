using System.CommandLine;
using System.Globalization;
using System.Text;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>simulate SCENE [--model M] [--integrator I] [--dt S] [--until T] [--sample DT] [--out FILE]</c>:
/// headless; prints the result JSON or writes it to FILE. Never touches OpenGL or audio.
/// <c>simulate --batch IN.jsonl --out OUT.jsonl [--threads N]</c> runs one scene per line
/// (<see cref="BatchSimulation"/>) with the same options.
/// </summary>
public static class SimulateCommand
{
    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var scene = new Argument<string?>("scene") { Description = "The scene file (billiards-scene/1 JSON).", Arity = ArgumentArity.ZeroOrOne };
        var model = new Option<string?>("--model") { Description = "Override the physics model: standard or thesis." };
        var integrator = new Option<string?>("--integrator") { Description = "Override the integrator: exact, euler or event (standard); fixed (thesis)." };
        var dt = new Option<double?>("--dt") { Description = "Override the fixed step (s)." };
        var until = new Option<double?>("--until") { Description = "Stop at this simulated time (s, at most 3600) instead of at rest." };
        var sample = new Option<double?>("--sample") { Description = "Record positions every DT seconds." };
        var output = new Option<string?>("--out") { Description = "Write the result to FILE instead of standard output (with --batch: the results, one per line; required)." };
        var maxWall = new Option<double?>("--max-wall") { Description = $"Bound on the run's wall-clock time (s, default {RunOptions.DefaultMaxWallSeconds}); stats.stop tells which bound ended a run." };
        var batch = new Option<string?>("--batch") { Description = "Simulate every scene of IN.jsonl (one scene per line) into --out, one result per line in the same order." };
        var threads = new Option<int?>("--threads") { Description = "With --batch: the threads that run scenes (default: every core)." };

        var command = new Command("simulate", VerbHelp.Verb("Simulate a scene headless and print its result JSON.", "simulate"))
        {
            scene, model, integrator, dt, until, sample, output, maxWall, batch, threads,
        };
        command.SetAction(parse =>
        {
            var options = Options(parse.GetValue(until), parse.GetValue(sample), parse.GetValue(maxWall));
            var overrides = new SceneOverrides(parse.GetValue(model), parse.GetValue(integrator), parse.GetValue(dt));
            string? scenePath = parse.GetValue(scene);
            if (parse.GetValue(batch) is { } batchPath)
            {
                if (scenePath is not null)
                {
                    throw new CliException($"simulate --batch {batchPath}: give either a scene or --batch, not both (got {scenePath})");
                }
                return RunBatch(batchPath, parse.GetValue(output), parse.GetValue(threads), overrides, options, stderr);
            }
            if (parse.GetValue(threads) is not null)
            {
                throw new CliException("--threads: only with --batch");
            }
            if (scenePath is null)
            {
                throw new CliException("simulate: expected a scene file (or --batch IN.jsonl --out OUT.jsonl)");
            }
            string? outPath = parse.GetValue(output) is { } o ? OutputFiles.Check("--out", o) : null;
            var loaded = SceneLoader.Load(scenePath, overrides);
            byte[] json = ResultWriter.ToUtf8(SimulationRunner.Run(loaded, options));
            if (outPath is not null)
            {
                OutputFiles.Write(outPath, json);
            }
            else
            {
                stdout.Write(Encoding.UTF8.GetString(json));
            }
            return 0;
        });
        return command;
    }

    // The run options, checked as a single run and a batch share them.
    private static RunOptions Options(double? until, double? sample, double? maxWall)
    {
        if (until is { } u && (!double.IsFinite(u) || u < 0 || u > RunOptions.MaxUntil))
        {
            throw new CliException(string.Create(CultureInfo.InvariantCulture,
                $"--until {u}: expected a time from 0 to {RunOptions.MaxUntil} s (the longest run simulated)"));
        }
        if (sample is { } s && (!double.IsFinite(s) || s <= 0))
        {
            throw new CliException($"--sample {s}: expected a positive interval (s)");
        }
        double wall = maxWall ?? RunOptions.DefaultMaxWallSeconds;
        if (!double.IsFinite(wall) || wall <= 0 || wall > RunOptions.MaxUntil)
        {
            throw new CliException(string.Create(CultureInfo.InvariantCulture, $"--max-wall {wall}: expected more than 0 and at most {RunOptions.MaxUntil} s"));
        }
        var options = new RunOptions(until, sample, MaxWallSeconds: wall);
        if (sample is { } interval && (until ?? options.MaxTime) / interval > 1_000_000)
        {
            throw new CliException($"--sample {interval}: more than a million samples; choose a larger interval");
        }
        return options;
    }

    private static int RunBatch(string input, string? output, int? threadCount, SceneOverrides overrides, RunOptions options, TextWriter stderr)
    {
        if (output is null)
        {
            throw new CliException($"simulate --batch {input}: --out OUT.jsonl is required (the results, one per line)");
        }
        int threads = threadCount ?? Environment.ProcessorCount;
        if (threads < 1 || threads > BatchSimulation.MaxThreads)
        {
            throw new CliException($"--threads {threads}: expected 1 to {BatchSimulation.MaxThreads}");
        }
        string outPath = OutputFiles.Check("--out", output);
        if (string.Equals(outPath, Path.GetFullPath(input), StringComparison.Ordinal))
        {
            throw new CliException($"--out {output}: is the input; choose another file");
        }
        int total;
        StreamReader reader;
        try
        {
            total = BatchSimulation.CountLines(input);
            reader = new StreamReader(input, Encoding.UTF8);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new CliException($"--batch {input}: cannot read the file ({e.Message})");
        }
        using (reader)
        {
            if (total == 0)
            {
                throw new CliException($"--batch {input}: the file is empty; expected one scene per line");
            }
            var run = new BatchSimulation(overrides, options, threads, stderr);
            OutputFiles.WriteStreaming(outPath, stream => run.Run(reader, input, total, stream));
            return run.Failed > 0 ? BatchSimulation.SomeFailed : 0;
        }
    }
}
