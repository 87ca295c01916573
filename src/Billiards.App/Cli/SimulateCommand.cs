using System.CommandLine;
using System.Globalization;
using System.Text;
using Billiards.Core.Scenes;

namespace Billiards.App.Cli;

/// <summary>
/// <c>simulate SCENE [--model M] [--integrator I] [--dt S] [--until T] [--sample DT] [--out FILE]</c>:
/// headless; prints the result JSON or writes it to FILE. Never touches OpenGL or audio.
/// </summary>
public static class SimulateCommand
{
    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout)
    {
        var scene = new Argument<string>("scene") { Description = "The scene file (billiards-scene/1 JSON)." };
        var model = new Option<string?>("--model") { Description = "Override the physics model: standard or thesis." };
        var integrator = new Option<string?>("--integrator") { Description = "Override the integrator: exact, euler or event (standard); fixed (thesis)." };
        var dt = new Option<double?>("--dt") { Description = "Override the fixed step (s)." };
        var until = new Option<double?>("--until") { Description = "Stop at this simulated time (s, at most 3600) instead of at rest." };
        var sample = new Option<double?>("--sample") { Description = "Record positions every DT seconds." };
        var output = new Option<string?>("--out") { Description = "Write the result to FILE instead of standard output." };
        var maxWall = new Option<double?>("--max-wall") { Description = $"Bound on the run's wall-clock time (s, default {RunOptions.DefaultMaxWallSeconds}); stats.stop tells which bound ended a run." };

        var command = new Command("simulate", "Simulate a scene headless and print its result JSON.")
        {
            scene, model, integrator, dt, until, sample, output, maxWall,
        };
        command.SetAction(parse =>
        {
            double? untilValue = parse.GetValue(until);
            double? sampleValue = parse.GetValue(sample);
            if (untilValue is { } u && (!double.IsFinite(u) || u < 0 || u > RunOptions.MaxUntil))
            {
                throw new CliException(string.Create(CultureInfo.InvariantCulture,
                    $"--until {u}: expected a time from 0 to {RunOptions.MaxUntil} s (the longest run simulated)"));
            }
            if (sampleValue is { } s && (!double.IsFinite(s) || s <= 0))
            {
                throw new CliException($"--sample {s}: expected a positive interval (s)");
            }
            double wall = parse.GetValue(maxWall) ?? RunOptions.DefaultMaxWallSeconds;
            if (!double.IsFinite(wall) || wall <= 0 || wall > RunOptions.MaxUntil)
            {
                throw new CliException(string.Create(CultureInfo.InvariantCulture, $"--max-wall {wall}: expected more than 0 and at most {RunOptions.MaxUntil} s"));
            }
            string? outPath = parse.GetValue(output) is { } o ? OutputFiles.Check("--out", o) : null;
            var loaded = SceneLoader.Load(parse.GetValue(scene)!, new SceneOverrides(parse.GetValue(model), parse.GetValue(integrator), parse.GetValue(dt)));
            var options = new RunOptions(untilValue, sampleValue, MaxWallSeconds: wall);
            if (sampleValue is { } interval && (untilValue ?? options.MaxTime) / interval > 1_000_000)
            {
                throw new CliException($"--sample {interval}: more than a million samples; choose a larger interval");
            }
            var outcome = SimulationRunner.Run(loaded, options);
            byte[] json = ResultWriter.ToUtf8(outcome);
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
}
