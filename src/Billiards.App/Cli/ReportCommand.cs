using Billiards.Core.Scenes;
using System.CommandLine;
using System.Text;
using Billiards.App.Reports;

namespace Billiards.App.Cli;

/// <summary>
/// <c>report accuracy [--out DIR]</c>: the error-against-run-time report (CSV, SVG plot, Markdown
/// summary) with its cushion and reality pages; <c>report cushions [--out DIR]</c>: the cushion page alone;
/// <c>report reality [--out DIR]</c>: the reality page alone (the engine against measured data);
/// <c>report snookers</c>: the computer player's fouls from snookered positions, without and with jumps;
/// <c>report ai SUMMARY.json ... [--out DIR]</c>: the computer player under execution noise (<see cref="AiReport"/>).
/// </summary>
public static class ReportCommand
{
    /// <summary>The files the report writes into its folder.</summary>
    public static IReadOnlyList<string> FileNames { get; } = ["accuracy.csv", "accuracy.svg", "accuracy.md", .. CushionReport.FileNames, .. RealityReport.FileNames];

    /// <summary>Builds the verb.</summary>
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var output = new Option<string>("--out") { Description = "Folder for accuracy.csv, accuracy.svg and accuracy.md.", DefaultValueFactory = _ => "out/accuracy" };
        var scenes = new Option<string?>("--scenes") { Description = "Folder of the scene suite (default: assets/scenes/accuracy)." };
        var accuracy = new Command("accuracy", VerbHelp.Verb("Measure each integrator and step against the event-based reference solver.", "report-accuracy")) { output, scenes };
        accuracy.SetAction(parse =>
        {
            // Everything is checked before the first measurement: the suite, every scene in every
            // configuration measured, and the output folder.
            string folder = parse.GetValue(scenes) ?? AssetFolder.Scene("accuracy");
            if (string.IsNullOrWhiteSpace(folder))
            {
                throw new CliException("--scenes: the path is empty");
            }
            if (!Directory.Exists(folder))
            {
                throw new CliException($"--scenes {folder}: no such folder");
            }
            var files = Directory.GetFiles(folder, "*.json").Order(StringComparer.Ordinal).ToList();
            if (files.Count == 0)
            {
                throw new CliException($"--scenes {folder}: no scene files");
            }
            string dir = OutputFiles.CheckFolder("--out", parse.GetValue(output)!, [.. FileNames]);
            AccuracyReport.Validate(files);
            string flight = AssetFolder.Scene("flight");
            FlightAccuracy.Validate(flight);

            var rows = AccuracyReport.Measure(files, stderr);
            string summary = AccuracyReport.ToMarkdown(rows, files.Count) + FlightAccuracy.ToMarkdown(FlightAccuracy.Measure(flight));
            byte[][] contents =
            [
                Encoding.UTF8.GetBytes(AccuracyReport.ToCsv(rows)),
                Encoding.UTF8.GetBytes(AccuracyReport.ToSvg(rows)),
                Encoding.UTF8.GetBytes(summary),
                .. CushionReport.Files().Select(f => f.Bytes),
                .. RealityReport.Files().Files.Select(f => f.Bytes),
            ];
            Directory.CreateDirectory(dir);
            OutputFiles.WriteAll([.. FileNames.Select((name, i) => (Path.Combine(dir, name), contents[i]))]);
            stdout.Write(summary);
            return 0;
        });

        var cushionOutput = new Option<string>("--out") { Description = "Folder for cushions.md and its plots.", DefaultValueFactory = _ => "out/accuracy" };
        var cushions = new Command("cushions", VerbHelp.Verb("Draw the cushion models' rebounds side by side (the accuracy report's cushion page).", "report-cushions")) { cushionOutput };
        cushions.SetAction(parse =>
        {
            string dir = OutputFiles.CheckFolder("--out", parse.GetValue(cushionOutput)!, [.. CushionReport.FileNames]);
            var files = CushionReport.Files();
            Directory.CreateDirectory(dir);
            OutputFiles.WriteAll([.. files.Select(f => (Path.Combine(dir, f.Name), f.Bytes))]);
            stdout.WriteLine(string.Join(" ", files.Select(f => Path.Combine(dir, f.Name))));
            return 0;
        });
        var realityOutput = new Option<string>("--out") { Description = "Folder for reality.md, reality.csv and their plots.", DefaultValueFactory = _ => "out/accuracy" };
        var reality = new Command("reality", VerbHelp.Verb("Compare the engine with measured real shots: plots, pass bands and verdicts.", "report-reality")) { realityOutput };
        reality.SetAction(parse =>
        {
            string dir = OutputFiles.CheckFolder("--out", parse.GetValue(realityOutput)!, [.. RealityReport.FileNames]);
            var (files, cases) = RealityReport.Files();
            Directory.CreateDirectory(dir);
            OutputFiles.WriteAll([.. files.Select(f => (Path.Combine(dir, f.Name), f.Bytes))]);
            stdout.WriteLine(string.Join(" ", files.Select(f => Path.Combine(dir, f.Name))));
            stdout.WriteLine(string.Create(System.Globalization.CultureInfo.InvariantCulture,
                $"{cases.Count(c => c.Verdict == "pass")} pass, {cases.Count(c => c.Verdict == "fail")} fail, {cases.Count(c => c.Verdict == "beyond")} beyond the model"));
            return 0;
        });
        var count = new Option<int>("--positions") { Description = "Snookered positions to play.", DefaultValueFactory = _ => 40 };
        var level = new Option<int>("--level") { Description = "The computer player's level (1-5).", DefaultValueFactory = _ => 4 };
        var tries = new Option<int>("--tries") { Description = "Strikes of each decision with the level's error.", DefaultValueFactory = _ => 5 };
        var seed = new Option<ulong>("--seed") { Description = "Seed of the positions and of the player's error.", DefaultValueFactory = _ => 1 };
        var snookers = new Command("snookers", VerbHelp.Verb("Play snookered 8-ball positions without and with jump shots and count the fouls.", "report-snookers")) { count, level, tries, seed };
        snookers.SetAction(parse =>
        {
            int n = parse.GetValue(count), l = parse.GetValue(level), k = parse.GetValue(tries);
            if (n is < 1 or > 1000)
            {
                throw new CliException($"--positions {n}: expected 1 to 1000");
            }
            if (l is < Billiards.Core.Ai.SkillLevel.Min or > Billiards.Core.Ai.SkillLevel.Max)
            {
                throw new CliException($"--level {l}: expected {Billiards.Core.Ai.SkillLevel.Min} to {Billiards.Core.Ai.SkillLevel.Max}");
            }
            if (k is < 1 or > 100)
            {
                throw new CliException($"--tries {k}: expected 1 to 100");
            }
            stdout.Write(SnookerReport.Run(n, l, k, parse.GetValue(seed), stderr));
            return 0;
        });
        var aiRuns = new Argument<string[]>("summaries") { Description = "The merged summaries of selfplay --noise fastfiz:K --planners noise,blind, one a noise level.", Arity = ArgumentArity.OneOrMore };
        var aiOutput = new Option<string>("--out") { Description = "Folder for ai.md and ai-break-and-run.png.", DefaultValueFactory = _ => "out/ai" };
        var aiBreaks = new Option<string[]>("--breaks") { Description = "The shard summaries of selfplay --planners noise,noise over the odd games of a run (the racks the blind planner broke there), counted in the break-and-run rate.", AllowMultipleArgumentsPerToken = true };
        var ai = new Command("ai", VerbHelp.Verb("Tabulate the computer player under execution noise against the noise-blind planner, with 95 % intervals and a plot.", "report-ai")) { aiRuns, aiOutput, aiBreaks };
        ai.SetAction(parse =>
        {
            string dir = OutputFiles.CheckFolder("--out", parse.GetValue(aiOutput)!, [.. AiReport.FileNames]);
            var files = AiReport.Files(AiReport.Read(parse.GetValue(aiRuns)!, parse.GetValue(aiBreaks) ?? []));
            Directory.CreateDirectory(dir);
            OutputFiles.WriteAll([.. files.Select(f => (Path.Combine(dir, f.Name), f.Bytes))]);
            stdout.Write(Encoding.UTF8.GetString(files[0].Bytes));
            return 0;
        });
        return new Command("report", VerbHelp.Verb("Write a report about the physics or the computer player.", "report")) { accuracy, cushions, reality, snookers, ai };
    }
}
